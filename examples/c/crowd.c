/* A crowd from C: a circle on every eighth free cell of a map, each pushed its own way, 240
 * steps; the bodies slide round each other and along the walls, never overlapping.
 *
 *   make -C examples/c crowd && (cd examples/c && ./crowd ../maps/cave.txt)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "tileslide.h"

#define FAIL(what)                                                   \
    do {                                                             \
        fprintf(stderr, "%s: %s\n", what, ts_last_error_message()); \
        return 1;                                                    \
    } while (0)

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : "../maps/cave.txt";
    ts_map *map = NULL;
    if (ts_map_load_file(path, NULL, &map) != TS_OK) FAIL("load");
    uint32_t width = 0, height = 0;
    float cell_w = 1, cell_h = 1;
    ts_map_size(map, &width, &height, &cell_w, &cell_h);

    ts_bodies *bodies = NULL;
    if (ts_bodies_create(&bodies) != TS_OK) FAIL("create");
    size_t cap = (size_t)width * height / 8 + 1, n = 0;
    ts_body_id *ids = malloc(cap * sizeof *ids);
    float *moves = malloc(2 * cap * sizeof *moves);
    float *xy = malloc(2 * cap * sizeof *xy);
    const float radius = 0.3f * cell_w;
    /* A free cell: a ray across its middle from its left edge meets no face inside it. */
    for (uint32_t k = 0; k < width * height && n < cap; k += 8) {
        float cx = (k % width + 0.5f) * cell_w, cy = (k / width + 0.5f) * cell_h;
        ts_ray_hit hit;
        if (ts_map_cast_ray(map, cx - 0.5f * cell_w, cy, cx + 0.5f * cell_w, cy,
                            TS_RAY_BOTH_SIDES, &hit))
            continue;
        if (ts_map_cast_ray(map, cx, cy - 0.5f * cell_h, cx, cy + 0.5f * cell_h,
                            TS_RAY_BOTH_SIDES, &hit))
            continue;
        ts_body_def def = ts_default_body_def();
        def.x = cx;
        def.y = cy;
        def.radius = radius;
        if (ts_bodies_add(bodies, &def, &ids[n]) != TS_OK) continue; /* inside a wall */
        float a = (float)n * 2.39996f;                                /* the golden angle */
        moves[2 * n] = cosf(a) * 0.1f * cell_w;
        moves[2 * n + 1] = sinf(a) * 0.1f * cell_h;
        n++;
    }
    size_t contacts = 0;
    for (int step = 0; step < 240; step++) {
        ts_step_report report;
        if (ts_bodies_propose_many(bodies, ids, moves, n) != TS_OK) FAIL("propose");
        if (ts_bodies_step(bodies, map, &report) != TS_OK) FAIL("step");
        contacts += report.contacts;
    }
    if (ts_bodies_positions(bodies, ids, n, xy) != TS_OK) FAIL("positions");
    float closest = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            float d = hypotf(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1]);
            if (d < closest) closest = d;
        }
    printf("%s: %zu bodies, 240 steps, %zu contacts; the closest two %.4f apart (radii sum %.4f)\n",
           path, n, contacts, closest, 2 * radius);
    int overlap = closest < 2 * radius - 1e-3f * cell_w;
    free(ids);
    free(moves);
    free(xy);
    ts_bodies_free(bodies);
    ts_map_free(map);
    return overlap;
}
