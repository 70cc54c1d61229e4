/* The C API's tests, in C: built with AddressSanitizer and UndefinedBehaviorSanitizer by
 * `make -C examples/c test`, run from examples/c. Each check prints what failed; the exit
 * status counts the failures. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tileslide.h"

static int failures = 0;

#define CHECK(cond)                                                           \
    do {                                                                      \
        if (!(cond)) {                                                        \
            fprintf(stderr, "%s:%d: failed: %s\n", __FILE__, __LINE__, #cond); \
            failures++;                                                       \
        }                                                                     \
    } while (0)

static int contains(const char *text, const char *words) { return strstr(text, words) != NULL; }

/* rays.csv's first ray against cave.txt: left into a wall's right face at (8, 12.5). */
static void a_ray_hits_the_wall_the_cli_names(void) {
    ts_map *map = NULL;
    CHECK(ts_map_load_file("../maps/cave.txt", NULL, &map) == TS_OK);
    if (!map) return;
    ts_ray_hit hit;
    CHECK(ts_map_cast_ray(map, 12.0f, 12.5f, 4.0f, 12.5f, 0, &hit));
    CHECK(hit.x == 8.0f && hit.y == 12.5f);
    CHECK(hit.nx == 1.0f && hit.ny == 0.0f);
    CHECK(hit.col == 7 && hit.row == 12 && hit.tile != TS_NONE);
    CHECK(hit.t == 0.5f);
    /* From inside the wall out, only with both sides. */
    CHECK(!ts_map_cast_ray(map, 7.5f, 12.5f, 12.0f, 12.5f, 0, &hit));
    CHECK(ts_map_cast_ray(map, 7.5f, 12.5f, 12.0f, 12.5f, TS_RAY_BOTH_SIDES, &hit));
    ts_map_free(map);
}

/* Every format the CLI reads (but Replica Island's, whose files are not in the repository). */
static void every_format_loads(void) {
    const char *files[] = {"../maps/cave.txt", "../maps/cave.tmx", "../maps/cave.tmj",
                           "../maps/dungeon.tmj", "../maps/ldtk/dungeon.ldtk",
                           "../maps/ldtk/platformer.ldtk"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        ts_map *map = NULL;
        ts_status status = ts_map_load_file(files[i], NULL, &map);
        if (status != TS_OK) fprintf(stderr, "%s: %s\n", files[i], ts_last_error_message());
        CHECK(status == TS_OK && map != NULL);
        uint32_t w = 0, h = 0;
        CHECK(ts_map_size(map, &w, &h, NULL, NULL) == TS_OK && w > 0 && h > 0);
        ts_map_free(map);
    }
}

static void a_batch_agrees_with_single_rays_and_misses_are_nan(void) {
    ts_map *map = NULL;
    CHECK(ts_map_from_ascii("#####\n#...#\n#...#\n#####", 2.0f, &map) == TS_OK);
    if (!map) return;
    enum { N = 5000 };
    static float rays[4 * N];
    static ts_ray_hit hits[N];
    for (int k = 0; k < N; k++) {
        float a = (float)k * 0.0123f;
        rays[4 * k + 0] = 5.0f;
        rays[4 * k + 1] = 4.0f;
        /* Every tenth ray is too short to reach a wall. */
        float reach = k % 10 == 0 ? 0.5f : 20.0f;
        rays[4 * k + 2] = 5.0f + cosf(a) * reach;
        rays[4 * k + 3] = 4.0f + sinf(a) * reach;
    }
    CHECK(ts_map_cast_rays(map, rays, N, 0, hits) == TS_OK);
    int agree = 0;
    for (int k = 0; k < N; k++) {
        ts_ray_hit one;
        bool found = ts_map_cast_ray(map, rays[4 * k], rays[4 * k + 1], rays[4 * k + 2],
                                     rays[4 * k + 3], 0, &one);
        if (k % 10 == 0) {
            agree += !found && isnan(hits[k].t) && hits[k].tile == TS_NONE;
        } else {
            agree += found && memcmp(&one, &hits[k], sizeof one) == 0;
        }
    }
    CHECK(agree == N);
    ts_map_free(map);
}

static void bad_input_gets_a_status_and_a_message(void) {
    ts_map *map = NULL;
    CHECK(ts_map_load_file("../maps/nowhere.tmx", NULL, &map) == TS_ERROR_NOT_FOUND);
    CHECK(map == NULL);
    CHECK(contains(ts_last_error_message(), "nowhere.tmx"));
    CHECK(ts_map_load_file(NULL, NULL, &map) == TS_ERROR_NULL_POINTER);
    CHECK(contains(ts_last_error_message(), "path is a null pointer"));
    CHECK(ts_map_load_file("../maps/tiles.png", NULL, &map) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "unknown map format"));
    CHECK(ts_map_from_ascii("###\n#?#\n###", 1.0f, &map) == TS_ERROR_LOAD);
    CHECK(contains(ts_last_error_message(), ":2:2"));
    CHECK(ts_map_from_ascii("###", NAN, &map) == TS_ERROR_INVALID_ARGUMENT);

    CHECK(ts_map_from_ascii("####\n#..#\n####", 1.0f, &map) == TS_OK);
    ts_ray_hit hit;
    CHECK(!ts_map_cast_ray(map, NAN, 1.5f, 3.0f, 1.5f, 0, &hit));
    CHECK(contains(ts_last_error_message(), "not finite"));
    CHECK(!ts_map_cast_ray(NULL, 1.5f, 1.5f, 3.0f, 1.5f, 0, &hit));
    CHECK(!ts_map_cast_ray(map, 1.5f, 1.5f, 3.0f, 1.5f, 0x80, &hit));
    CHECK(contains(ts_last_error_message(), "flags 0x80"));
    float rays[8] = {1.5f, 1.5f, 3.0f, 1.5f, 1.5f, 1.5f, INFINITY, 1.5f};
    ts_ray_hit hits[2];
    CHECK(ts_map_cast_rays(map, rays, 2, 0, hits) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "ray 1"));
    CHECK(ts_map_cast_rays(map, NULL, 2, 0, hits) == TS_ERROR_NULL_POINTER);
    CHECK(ts_map_cast_rays(map, NULL, 0, 0, NULL) == TS_OK);
    ts_map_free(map);
    ts_map_free(NULL);
}

/* Two bodies pushed into each other in a room: they meet and stop touching, not overlapping;
 * a removed body's id is stale. */
static void bodies_meet_without_overlap_and_removed_ids_go_stale(void) {
    ts_map *map = NULL;
    CHECK(ts_map_from_ascii("##########\n#........#\n#........#\n##########", 1.0f, &map) == TS_OK);
    ts_bodies *bodies = NULL;
    CHECK(ts_bodies_create(&bodies) == TS_OK);
    if (!map || !bodies) return;
    ts_body_def def = ts_default_body_def();
    def.radius = 0.4f;
    def.y = 1.5f;
    ts_body_id a, b;
    def.x = 2.0f;
    CHECK(ts_bodies_add(bodies, &def, &a) == TS_OK);
    def.x = 8.0f;
    CHECK(ts_bodies_add(bodies, &def, &b) == TS_OK);
    /* Head-on, they turn opposite ways and slide round each other: never closer than
     * their radii. */
    float xy[4], closest = INFINITY;
    ts_body_id ids[2] = {a, b};
    for (int step = 0; step < 30; step++) {
        CHECK(ts_bodies_propose(bodies, a, 0.3f, 0.0f) == TS_OK);
        CHECK(ts_bodies_propose(bodies, b, -0.3f, 0.0f) == TS_OK);
        CHECK(ts_bodies_step(bodies, map, NULL) == TS_OK);
        CHECK(ts_bodies_positions(bodies, ids, 2, xy) == TS_OK);
        float d = hypotf(xy[2] - xy[0], xy[3] - xy[1]);
        if (d < closest) closest = d;
    }
    CHECK(closest >= 0.8f - 1e-4f && closest < 0.81f);
    CHECK(xy[0] > xy[2]); /* past each other */
    CHECK(ts_bodies_count(bodies) == 2);
    CHECK(ts_bodies_remove(bodies, a) == TS_OK);
    CHECK(ts_bodies_propose(bodies, a, 0.1f, 0.0f) == TS_ERROR_STALE_HANDLE);
    CHECK(contains(ts_last_error_message(), "stale body handle"));
    CHECK(ts_bodies_positions(bodies, ids, 2, xy) == TS_ERROR_STALE_HANDLE);
    CHECK(contains(ts_last_error_message(), "entry 0"));
    def.radius = NAN;
    CHECK(ts_bodies_add(bodies, &def, &a) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(ts_bodies_propose(bodies, b, INFINITY, 0.0f) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(ts_bodies_step(bodies, NULL, NULL) == TS_ERROR_NULL_POINTER);
    ts_bodies_free(bodies);
    ts_map_free(map);
}

/* A box falls onto a one-way platform, stands on it, drops through on request, lands on the
 * floor and runs into the wall; its contacts name the tiles. */
static void a_character_lands_drops_through_and_meets_the_wall(void) {
    ts_map *map = NULL;
    CHECK(ts_map_from_ascii("#########\n#.......#\n#..===..#\n#.......#\n#########", 1.0f,
                            &map) == TS_OK);
    ts_character_def def = ts_default_character_def();
    def.x = 4.5f;
    def.y = 1.5f;
    ts_character *hero = NULL;
    CHECK(ts_character_create(&def, &hero) == TS_OK);
    if (!map || !hero) return;
    ts_character_state s;
    ts_character_contact contacts[TS_CHARACTER_MAX_CONTACTS];
    size_t n = 0;
    const float dt = 1.0f / 60.0f;
    for (int step = 0; step < 60; step++) {
        CHECK(ts_character_get_state(hero, &s) == TS_OK);
        CHECK(ts_character_set_input(hero, 0.0f, s.vy + 30.0f * dt, false) == TS_OK);
        CHECK(ts_character_step(hero, map, dt) == TS_OK);
    }
    CHECK(ts_character_get_state(hero, &s) == TS_OK);
    CHECK(s.grounded && fabsf(s.y - (2.0f - 0.4f - 0.001f)) < 1e-4f && s.vy == 0.0f);
    CHECK(ts_character_contacts(hero, contacts, TS_CHARACTER_MAX_CONTACTS, &n) == TS_OK);
    CHECK(n == 1 && contacts[0].side == TS_CONTACT_GROUND);
    CHECK(contacts[0].col == 4 && contacts[0].row == 2 && contacts[0].tile != TS_NONE);
    CHECK((contacts[0].flags & TS_SEGMENT_ONE_WAY) != 0 && contacts[0].ny == -1.0f);
    /* Down through the platform to the floor, then right into the wall at x = 8. */
    for (int step = 0; step < 60; step++) {
        CHECK(ts_character_get_state(hero, &s) == TS_OK);
        CHECK(ts_character_set_input(hero, 0.0f, s.vy + 30.0f * dt, step < 20) == TS_OK);
        CHECK(ts_character_step(hero, map, dt) == TS_OK);
    }
    CHECK(ts_character_get_state(hero, &s) == TS_OK);
    CHECK(s.grounded && fabsf(s.y - (4.0f - 0.4f - 0.001f)) < 1e-4f);
    for (int step = 0; step < 60; step++) {
        CHECK(ts_character_set_input(hero, 6.0f, 1.0f, false) == TS_OK);
        CHECK(ts_character_step(hero, map, dt) == TS_OK);
    }
    CHECK(ts_character_get_state(hero, &s) == TS_OK);
    CHECK(fabsf(s.x - (8.0f - 0.25f - 0.001f)) < 1e-4f && s.vx == 0.0f);
    /* Two contacts: a buffer of one is too small, and says how many it needs. */
    CHECK(ts_character_contacts(hero, contacts, 1, &n) == TS_ERROR_BUFFER_TOO_SMALL && n == 2);
    CHECK(ts_character_contacts(hero, contacts, 2, &n) == TS_OK && n == 2);
    CHECK(contacts[0].side == TS_CONTACT_GROUND && contacts[1].side == TS_CONTACT_RIGHT);
    CHECK(contacts[1].nx == -1.0f && contacts[1].col == 8 && contacts[1].row == 3);
    /* Bad input. */
    CHECK(ts_character_set_input(hero, NAN, 0.0f, false) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "vx is NaN"));
    CHECK(ts_character_step(hero, map, -1.0f) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "dt"));
    CHECK(ts_character_step(hero, NULL, dt) == TS_ERROR_NULL_POINTER);
    CHECK(ts_character_teleport(hero, INFINITY, 0.0f) == TS_ERROR_INVALID_ARGUMENT);
    def.shape = 7;
    ts_character *bad = NULL;
    CHECK(ts_character_create(&def, &bad) == TS_ERROR_INVALID_ARGUMENT && bad == NULL);
    CHECK(contains(ts_last_error_message(), "def.shape"));
    ts_character_free(hero);
    ts_character_free(NULL);
    ts_map_free(map);
}

/* A hero's sword hits a slime of another team, once per swing; a fast fireball hits what it
 * passes; a removed object's id is stale. */
static void volumes_hit_across_teams_once_per_swing(void) {
    ts_hit_world *world = NULL;
    CHECK(ts_hit_world_create(&world) == TS_OK);
    if (!world) return;
    ts_volume sword = {TS_SHAPE_CIRCLE, 1.2f, 0.0f, 0.4f, 0.0f, 0.0f, TS_HIT_TYPE_HIT};
    ts_volume body = {TS_SHAPE_RECT, 0.0f, 0.0f, 0.0f, 0.4f, 0.5f, TS_HIT_TYPE_ANY};
    ts_hit_object_def def = ts_default_hit_object_def();
    def.team = 1;
    def.swing = 42;
    def.attack = &sword;
    def.attack_count = 1;
    def.vulnerable = &body;
    def.vulnerable_count = 1;
    ts_hit_object_id hero, slime, fireball;
    CHECK(ts_hit_world_add(world, &def, &hero) == TS_OK);
    def = ts_default_hit_object_def();
    def.x = 1.6f;
    def.vulnerable = &body;
    def.vulnerable_count = 1;
    CHECK(ts_hit_world_add(world, &def, &slime) == TS_OK);
    ts_hit_event events[8];
    size_t n = 0;
    CHECK(ts_hit_world_step(world) == TS_OK);
    CHECK(ts_hit_world_events(world, events, 8, &n) == TS_OK && n == 1);
    CHECK(events[0].attacker.index == hero.index && events[0].victim.index == slime.index);
    CHECK(events[0].hit_type == TS_HIT_TYPE_HIT && events[0].accepted && events[0].t == 0.0f);
    /* The same swing again: no second hit. */
    CHECK(ts_hit_world_step(world) == TS_OK);
    CHECK(ts_hit_world_events(world, events, 8, &n) == TS_OK && n == 0);
    /* A fireball from x = 10 to x = -10 in one step: through the slime and the hero. */
    ts_volume fire = {TS_SHAPE_CIRCLE, 0.0f, 0.0f, 0.2f, 0.0f, 0.0f, TS_HIT_TYPE_HIT};
    def = ts_default_hit_object_def();
    def.x = 10.0f;
    def.team = 2;
    def.attack = &fire;
    def.attack_count = 1;
    CHECK(ts_hit_world_add(world, &def, &fireball) == TS_OK);
    CHECK(ts_hit_world_step(world) == TS_OK);
    CHECK(ts_hit_world_move(world, fireball, -10.0f, 0.0f) == TS_OK);
    CHECK(ts_hit_world_step(world) == TS_OK);
    CHECK(ts_hit_world_events(world, events, 1, &n) == TS_ERROR_BUFFER_TOO_SMALL && n == 2);
    CHECK(ts_hit_world_events(world, events, 2, &n) == TS_OK && n == 2);
    CHECK(events[0].attacker.index == fireball.index && events[1].attacker.index == fireball.index);
    /* The slime (at 1.6) is reached before the hero (at 0). */
    int slime_first = events[0].victim.index == slime.index ? 0 : 1;
    CHECK(events[slime_first].t < events[1 - slime_first].t);
    /* Removed: stale, even once the slot is reused. */
    CHECK(ts_hit_world_remove(world, slime) == TS_OK);
    ts_hit_object_id reuse;
    CHECK(ts_hit_world_add(world, &def, &reuse) == TS_OK && reuse.index == slime.index);
    CHECK(ts_hit_world_move(world, slime, 0.0f, 0.0f) == TS_ERROR_STALE_HANDLE);
    CHECK(contains(ts_last_error_message(), "stale hit object id"));
    CHECK(ts_hit_world_count(world) == 3);
    /* Bad input. */
    CHECK(ts_hit_world_move(world, hero, NAN, 0.0f) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "x is NaN"));
    fire.radius = -1.0f;
    CHECK(ts_hit_world_add(world, &def, &reuse) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "def.attack[0]"));
    def.attack = NULL;
    CHECK(ts_hit_world_add(world, &def, &reuse) == TS_ERROR_NULL_POINTER);
    CHECK(ts_hit_world_events(world, NULL, 0, NULL) == TS_ERROR_NULL_POINTER);
    ts_hit_world_free(world);
    ts_hit_world_free(NULL);
}

/* A path round a block, asked for with too little room first; a circle too wide for the
 * corridors has none (not an error); a flow field points the way. */
static void a_path_goes_round_the_block_and_a_wide_circle_has_none(void) {
    ts_map *map = NULL;
    CHECK(ts_map_from_ascii("#######\n#.....#\n#.###.#\n#.....#\n#######", 1.0f, &map) == TS_OK);
    ts_nav *nav = NULL;
    CHECK(ts_nav_create(map, 1.0f, &nav) == TS_OK);
    if (!map || !nav) return;
    float xy[2 * 16];
    size_t n = 0;
    CHECK(ts_nav_find_path(nav, map, 1.5f, 1.5f, 5.5f, 3.5f, 0.3f, xy, 1, &n) ==
          TS_ERROR_BUFFER_TOO_SMALL);
    CHECK(n > 2 && n <= 16);
    size_t m = 0;
    CHECK(ts_nav_find_path(nav, map, 1.5f, 1.5f, 5.5f, 3.5f, 0.3f, xy, 16, &m) == TS_OK);
    CHECK(m == n && xy[0] == 1.5f && xy[1] == 1.5f);
    CHECK(xy[2 * m - 2] == 5.5f && xy[2 * m - 1] == 3.5f);
    /* Every corner lies in the open, clear of the block's middle row. */
    for (size_t k = 0; k < m; k++) CHECK(xy[2 * k + 1] < 2.0f || xy[2 * k + 1] > 3.0f ||
                                         xy[2 * k] < 2.0f || xy[2 * k] > 5.0f);
    CHECK(ts_nav_find_path(nav, map, 1.5f, 1.5f, 5.5f, 3.5f, 0.6f, xy, 16, &m) == TS_OK && m == 0);
    CHECK(ts_nav_find_path(nav, map, NAN, 1.5f, 5.5f, 3.5f, 0.3f, xy, 16, &m) ==
          TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "x0 is NaN"));
    CHECK(ts_nav_find_path(nav, map, 1.5f, 1.5f, 5.5f, 3.5f, 2.0f, xy, 16, &m) ==
          TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "radius"));
    ts_flow_field *field = NULL;
    CHECK(ts_flow_field_create(nav, map, 5.5f, 1.5f, 0.3f, &field) == TS_OK);
    float dx = 0.0f, dy = 0.0f, distance = 0.0f;
    CHECK(ts_flow_field_direction(field, nav, map, 1.5f, 1.5f, &dx, &dy) == TS_OK);
    CHECK(dx == 1.0f && dy == 0.0f);
    CHECK(ts_flow_field_distance(field, nav, map, 1.5f, 1.5f, &distance) == TS_OK);
    CHECK(fabsf(distance - 4.0f) < 1e-3f);
    CHECK(ts_flow_field_distance(field, nav, map, 3.5f, 2.5f, &distance) == TS_OK);
    CHECK(isinf(distance));
    ts_flow_field_free(field);
    ts_nav_free(nav);
    ts_map_free(map);
}

/* Debug lines: the map's walls, normals and hidden seams, bodies owned by their ids, a
 * character and its contacts, hit volumes; kinds and a view limit them; a buffer too small
 * says how many there are. */
static void debug_lines_show_each_part(void) {
    ts_map *map = NULL;
    CHECK(ts_map_from_ascii("######\n#....#\n#.==.#\n######", 1.0f, &map) == TS_OK);
    ts_debug_lines *lines = NULL;
    CHECK(ts_debug_lines_create(&lines) == TS_OK);
    if (!map || !lines) return;
    CHECK(ts_map_debug_lines(map, lines) == TS_OK);
    size_t n = ts_debug_lines_count(lines), m = 0;
    CHECK(n > 20);
    ts_debug_line few[2];
    CHECK(ts_debug_lines_read(lines, few, 2, &m) == TS_ERROR_BUFFER_TOO_SMALL && m == n);
    ts_debug_line *all = malloc(n * sizeof *all);
    CHECK(all && ts_debug_lines_read(lines, all, n, &m) == TS_OK && m == n);
    int counts[17] = {0};
    for (size_t k = 0; all && k < n; k++) {
        CHECK(all[k].shape == TS_DEBUG_SEGMENT && all[k].owner == 0);
        if ((unsigned)all[k].kind < 17) counts[all[k].kind]++;
    }
    free(all);
    /* The platform's two cells: one flat top, its seam hidden; every active segment has its
     * normal. */
    CHECK(counts[TS_DEBUG_ONE_WAY_SEGMENT] >= 1 && counts[TS_DEBUG_HIDDEN_SEGMENT] > 0);
    CHECK(counts[TS_DEBUG_NORMAL] == counts[TS_DEBUG_ACTIVE_SEGMENT] +
                                         counts[TS_DEBUG_ONE_WAY_SEGMENT]);

    /* Only bodies, then: a body is a circle (centre, radius) owned by its id. */
    CHECK(ts_debug_lines_clear(lines) == TS_OK && ts_debug_lines_count(lines) == 0);
    CHECK(ts_debug_lines_set_kinds(lines, 1u << TS_DEBUG_BODY | 1u << TS_DEBUG_CHARACTER |
                                              1u << TS_DEBUG_CONTACT) == TS_OK);
    ts_bodies *bodies = NULL;
    CHECK(ts_bodies_create(&bodies) == TS_OK);
    ts_body_def def = ts_default_body_def();
    def.x = 2.5f;
    def.y = 1.5f;
    def.radius = 0.25f;
    ts_body_id id;
    CHECK(ts_bodies_add(bodies, &def, &id) == TS_OK);
    CHECK(ts_map_debug_lines(map, lines) == TS_OK && ts_debug_lines_count(lines) == 0);
    CHECK(ts_bodies_debug_lines(bodies, lines) == TS_OK);
    ts_debug_line line[4];
    CHECK(ts_debug_lines_read(lines, line, 4, &m) == TS_OK && m == 1);
    CHECK(line[0].kind == TS_DEBUG_BODY && line[0].shape == TS_DEBUG_CIRCLE);
    CHECK(line[0].x0 == 2.5f && line[0].y0 == 1.5f && line[0].x1 == 0.25f);
    CHECK(line[0].owner == ((uint64_t)id.generation << 32 | id.index));
    /* A character standing on the platform: its box and its ground contact. */
    ts_character_def cdef = ts_default_character_def();
    cdef.x = 2.5f;
    cdef.y = 1.5f;
    ts_character *hero = NULL;
    CHECK(ts_character_create(&cdef, &hero) == TS_OK);
    CHECK(ts_character_move_by(hero, map, 0.0f, 1.0f, false) == TS_OK);
    CHECK(ts_debug_lines_clear(lines) == TS_OK);
    CHECK(ts_character_debug_lines(hero, 9, lines) == TS_OK);
    CHECK(ts_debug_lines_read(lines, line, 4, &m) == TS_OK && m == 2);
    CHECK(line[0].kind == TS_DEBUG_CONTACT && line[0].shape == TS_DEBUG_SEGMENT);
    CHECK(line[0].y1 < line[0].y0 && line[0].owner == 9);
    CHECK(line[1].kind == TS_DEBUG_CHARACTER && line[1].shape == TS_DEBUG_BOX);
    CHECK(line[1].x0 == 2.25f && line[1].x1 == 2.75f);
    /* A view outside the map: nothing of it. */
    float view[4] = {100.0f, 100.0f, 110.0f, 110.0f};
    CHECK(ts_debug_lines_set_kinds(lines, TS_DEBUG_ALL_KINDS) == TS_OK);
    CHECK(ts_debug_lines_set_view(lines, view) == TS_OK);
    CHECK(ts_debug_lines_clear(lines) == TS_OK);
    CHECK(ts_map_debug_lines(map, lines) == TS_OK && ts_debug_lines_count(lines) == 0);
    view[0] = NAN;
    CHECK(ts_debug_lines_set_view(lines, view) == TS_ERROR_INVALID_ARGUMENT);
    CHECK(contains(ts_last_error_message(), "view[0] is NaN"));
    CHECK(ts_debug_lines_set_view(lines, NULL) == TS_OK);
    CHECK(ts_map_debug_lines(map, lines) == TS_OK && ts_debug_lines_count(lines) == n);
    CHECK(ts_map_debug_lines(NULL, lines) == TS_ERROR_NULL_POINTER);
    CHECK(ts_debug_lines_read(lines, NULL, 5, &m) == TS_ERROR_NULL_POINTER);
    ts_character_free(hero);
    ts_bodies_free(bodies);
    ts_debug_lines_free(lines);
    ts_debug_lines_free(NULL);
    ts_map_free(map);
}

int main(void) {
    a_ray_hits_the_wall_the_cli_names();
    every_format_loads();
    a_batch_agrees_with_single_rays_and_misses_are_nan();
    bad_input_gets_a_status_and_a_message();
    bodies_meet_without_overlap_and_removed_ids_go_stale();
    a_character_lands_drops_through_and_meets_the_wall();
    volumes_hit_across_teams_once_per_swing();
    a_path_goes_round_the_block_and_a_wide_circle_has_none();
    debug_lines_show_each_part();
    if (failures) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    printf("test_capi: every check passed\n");
    return 0;
}
