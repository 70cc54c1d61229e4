/* tileslide from C: load a map, cast a ray, then a batch of rays.
 *
 *   make -C examples/c run            (or: ./rays MAP, from examples/c after `make`)
 *
 * Every fallible call returns a ts_status; ts_last_error_message() says what went wrong. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "tileslide.h"

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : "../maps/cave.tmx";
    ts_map *map = NULL;
    if (ts_map_load_file(path, NULL, &map) != TS_OK) {
        fprintf(stderr, "error: %s\n", ts_last_error_message());
        return 1;
    }
    uint32_t width = 0, height = 0;
    float cell_w = 0, cell_h = 0;
    ts_map_size(map, &width, &height, &cell_w, &cell_h);
    printf("%s: %u x %u cells of %g x %g (tileslide %s)\n", path, width, height, cell_w, cell_h,
           ts_version());

    /* One ray, left to right along the middle of the map. */
    float y = height * cell_h * 0.5f;
    ts_ray_hit hit;
    if (ts_map_cast_ray(map, cell_w * 1.5f, y, width * cell_w, y, 0, &hit)) {
        printf("ray: hit at (%g, %g), normal (%g, %g), tile %u in cell (%u, %u)\n", hit.x, hit.y,
               hit.nx, hit.ny, hit.tile, hit.col, hit.row);
    } else {
        printf("ray: no hit\n");
    }

    /* A batch: 360 rays out of the map's centre, one a degree. */
    enum { N = 360 };
    float rays[4 * N];
    ts_ray_hit hits[N];
    float cx = width * cell_w * 0.5f, cy = height * cell_h * 0.5f;
    float reach = (width * cell_w + height * cell_h);
    for (int k = 0; k < N; k++) {
        float a = (float)k * 3.14159265f / 180.0f;
        rays[4 * k + 0] = cx;
        rays[4 * k + 1] = cy;
        rays[4 * k + 2] = cx + cosf(a) * reach;
        rays[4 * k + 3] = cy + sinf(a) * reach;
    }
    if (ts_map_cast_rays(map, rays, N, 0, hits) != TS_OK) {
        fprintf(stderr, "error: %s\n", ts_last_error_message());
        ts_map_free(map);
        return 1;
    }
    int hit_count = 0;
    float nearest = INFINITY;
    for (int k = 0; k < N; k++) {
        if (!isnan(hits[k].t)) {
            hit_count++;
            float d = hits[k].t * reach;
            if (d < nearest) nearest = d;
        }
    }
    printf("batch: %d of %d rays hit, the nearest wall %g away\n", hit_count, N, nearest);
    ts_map_free(map);
    return 0;
}
