/* A platformer character from C: a box runs right across a map under gravity, jumping
 * whenever a wall stops it on the ground, for ten seconds at 60 steps a second; then the
 * debug lines of the map and the character, counted by kind.
 *
 *   make -C examples/c walker && (cd examples/c && ./walker ../maps/cave.txt)
 */
#include <stdio.h>
#include <stdlib.h>

#include "tileslide.h"

#define FAIL(what)                                                   \
    do {                                                             \
        fprintf(stderr, "%s: %s\n", what, ts_last_error_message()); \
        return 1;                                                    \
    } while (0)

static const char *const KIND_NAMES[] = {
    "active segment", "one-way segment", "normal", "hidden segment", "temporary segment",
    "body", "character", "contact", "ray", "ray hit", "attack volume", "vulnerability volume",
    "hit", "refused hit", "path", "flow arrow", "broadphase box"};
#define KINDS (sizeof KIND_NAMES / sizeof KIND_NAMES[0])

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : "../maps/cave.txt";
    ts_map *map = NULL;
    if (ts_map_load_file(path, NULL, &map) != TS_OK) FAIL("load");

    /* Just above the floor near the left wall (y down: up is -y, the default). */
    ts_character_def def = ts_default_character_def();
    def.x = 2.5f;
    def.y = 14.0f;
    ts_character *hero = NULL;
    if (ts_character_create(&def, &hero) != TS_OK) FAIL("create");

    const float dt = 1.0f / 60.0f, gravity = 30.0f, run = 5.0f, jump = 17.0f;
    int jumps = 0;
    ts_character_state s;
    ts_character_contact contacts[TS_CHARACTER_MAX_CONTACTS];
    size_t n = 0;
    for (int step = 0; step < 600; step++) {
        if (ts_character_get_state(hero, &s) != TS_OK) FAIL("state");
        if (ts_character_contacts(hero, contacts, TS_CHARACTER_MAX_CONTACTS, &n) != TS_OK)
            FAIL("contacts");
        /* The game's rules: gravity, the run, a jump at a wall. */
        float vy = s.vy + gravity * dt;
        for (size_t k = 0; k < n; k++) {
            if (contacts[k].side == TS_CONTACT_RIGHT && s.grounded) {
                vy = -jump;
                jumps++;
            }
        }
        if (ts_character_set_input(hero, run, vy, false) != TS_OK) FAIL("input");
        if (ts_character_step(hero, map, dt) != TS_OK) FAIL("step");
    }
    if (ts_character_get_state(hero, &s) != TS_OK) FAIL("state");
    printf("%s: after 600 steps at (%.3f, %.3f), %s, %d jumps\n", path, s.x, s.y,
           s.grounded ? "on the ground" : "in the air", jumps);

    ts_debug_lines *lines = NULL;
    if (ts_debug_lines_create(&lines) != TS_OK) FAIL("debug lines");
    if (ts_map_debug_lines(map, lines) != TS_OK) FAIL("map lines");
    if (ts_character_debug_lines(hero, 1, lines) != TS_OK) FAIL("character lines");
    size_t count = ts_debug_lines_count(lines);
    ts_debug_line *all = malloc(count * sizeof *all);
    if (!all) return 1;
    if (ts_debug_lines_read(lines, all, count, &n) != TS_OK) FAIL("read");
    size_t by_kind[KINDS] = {0};
    for (size_t k = 0; k < n; k++)
        if ((size_t)all[k].kind < KINDS) by_kind[all[k].kind]++;
    printf("debug lines:");
    for (size_t k = 0; k < KINDS; k++)
        if (by_kind[k]) printf(" %zu %s,", by_kind[k], KIND_NAMES[k]);
    printf(" %zu in all\n", n);

    free(all);
    ts_debug_lines_free(lines);
    ts_character_free(hero);
    ts_map_free(map);
    /* It must have got somewhere (on cave.txt, over the pillar, the hill and the step to
     * the right wall, x = 38.749). */
    return s.x > def.x + 1.0f ? 0 : 1;
}
