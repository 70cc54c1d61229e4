"""Hit volumes: the exported scene through Python gives the Rust core's events bit for bit;
ids go stale when the next frame begins; teams, swings, rules; bad input raises, naming the
argument."""

import math

import numpy as np
import pytest

import tileslide
from conftest import named, same_bits
from tileslide import HitType, HitWorld, Volume


def volume(row):
    kind, p0, p1, p2, p3, p4, hit = row
    hit = int(hit)
    if kind == 0:
        return Volume.circle(p0, p1, p2, hit)
    if kind == 1:
        return Volume.rect(p0, p1, p2, p3, hit)
    return Volume.capsule(p0, p1, p2, p3, p4, hit)


@pytest.mark.parametrize("broadphase", ["sweep_and_prune", "uniform_grid"])
def test_the_scene_gives_the_cores_events_bit_for_bit(systems, broadphase):
    objects = systems.floats("hits_objects", 29)
    expected = systems.floats("hits_events", 10)
    world = HitWorld(broadphase)
    got = []
    for frame in range(systems.settings["hit_frames"]):
        world.begin_frame()
        for row in objects[objects[:, 0] == frame]:
            _, owner, x, y, w, h, mx, my, team, fx, fy, inv, swing, ax, ay = row[:15]
            attack = [] if row[15] < 0 else [volume(row[15:22])]
            world.register(
                int(owner), x, y, w, h,
                attack=attack,
                vulnerable=[volume(row[22:29])],
                motion=(mx, my),
                flip_x=bool(fx),
                flip_y=bool(fy),
                aim=None if math.isnan(ax) else (ax, ay),
                team=int(team),
                invulnerable=bool(inv),
                swing=None if swing < 0 else int(swing),
            )
        assert len(world) == systems.settings["hit_objects"]
        for e in world.detect():
            assert e.attacker.frame == e.victim.frame == world.frame
            assert world.owner(e.attacker) == e.attacker_owner
            got.append([frame, e.attacker.index, e.victim.index, e.attacker_owner,
                        e.victim_owner, e.hit_type, e.accepted, e.t, e.x, e.y])
    got = np.array(got, dtype=np.float32)
    assert same_bits(got, expected)
    # The scene has accepted and refused hits, and hits along a move.
    assert expected[:, 6].any() and not expected[:, 6].all() and (expected[:, 7] > 0).any()


def test_a_fist_hits_a_body_of_another_team_once_per_swing():
    world = HitWorld()
    ids = []
    for frame in range(3):
        world.begin_frame()
        hero = world.register(1, 0.0, 0.0, 1.0, 2.0,
                              attack=[Volume.circle(1.5, 1.0, 0.5)], team=0, swing=77)
        slime = world.register(2, 1.6, 0.0, 1.0, 1.0,
                               vulnerable=[Volume.rect(0.5, 0.5, 0.5, 0.5, HitType.ANY)],
                               team=1)
        ids.append(hero)
        events = world.detect()
        if frame == 0:
            (e,) = events
            assert (e.attacker, e.victim) == (hero, slime)
            assert (e.attacker_owner, e.victim_owner, e.hit_type) == (1, 2, HitType.HIT)
            assert e.accepted and e.t == 0.0 and "HitEvent(" in repr(e)
        else:
            assert events == [], "the swing already landed"
    assert world.events() == [] and world.frame == 3
    # Ids of an earlier frame are stale; this frame's are not.
    assert ids[0] not in world and ids[2] in world
    with pytest.raises(KeyError, match="stale object id"):
        world.owner(ids[0])
    with pytest.raises(KeyError, match="stale object id"):
        world.bounding_circle(ids[1])
    x, y, r = world.bounding_circle(ids[2])
    assert r >= 0.5 and (x, y) == (1.5, 1.0)


def test_teams_invulnerability_and_a_rule_decide_who_takes_a_hit():
    world = HitWorld()
    world.begin_frame()
    a = world.register(1, 0.0, 0.0, 1.0, 1.0, attack=[Volume.circle(0.5, 0.5, 1.0)])
    friend = world.register(2, 0.5, 0.0, 1.0, 1.0, vulnerable=[Volume.circle(0.5, 0.5, 0.5)])
    ghost = world.register(3, 0.0, 0.5, 1.0, 1.0, team=1, invulnerable=True,
                           vulnerable=[Volume.circle(0.5, 0.5, 0.5)])
    accepted = {(e.victim_owner, e.accepted) for e in world.detect()}
    assert accepted == {(2, False), (3, False)}
    asked = []

    def rule(attacker, victim, hit_type):
        asked.append((attacker, victim, hit_type))
        return victim == friend

    events = world.detect(rule)
    assert {(e.victim_owner, e.accepted) for e in events} == {(2, True), (3, False)}
    assert sorted(asked, key=lambda q: q[1].index) == [(a, friend, 1), (a, ghost, 1)]

    def broken(attacker, victim, hit_type):
        raise RuntimeError("the rule broke")

    with pytest.raises(RuntimeError, match="the rule broke"):
        world.detect(broken)


def test_a_fast_projectile_is_swept_and_cannot_pass_through():
    world = HitWorld()
    world.begin_frame()
    world.register(1, 10.0, 0.0, 0.2, 0.2, attack=[Volume.circle(0.1, 0.1, 0.1)],
                   motion=(10.0, 0.0))
    world.register(2, 5.0, 0.0, 1.0, 1.0, team=1, vulnerable=[Volume.rect(0.5, 0.5, 0.5, 0.5)])
    (e,) = world.detect()
    assert 0.0 < e.t < 1.0 and 4.5 < e.x < 5.5


def test_hit_types_are_the_cores_bits():
    assert (HitType.NONE, HitType.HIT, HitType.DEATH, HitType.COLLECT) == (0, 1, 2, 4)
    assert (HitType.POSSESS, HitType.DEPRESS, HitType.LAUNCH) == (8, 16, 32)
    assert HitType.ANY == 0xFFFFFFFF
    assert Volume.circle(0.0, 0.0, 1.0).hit == HitType.HIT
    assert Volume.rect(0.0, 0.0, 1.0, 1.0, HitType.DEATH | HitType.LAUNCH).hit == 34
    assert "Volume(" in repr(Volume.capsule(0.0, 0.0, 1.0, 0.0, 0.1))


@pytest.mark.parametrize(
    "make, error, match",
    [
        (lambda: Volume.circle(math.nan, 0.0, 1.0), ValueError, "x is NaN"),
        (lambda: Volume.circle(0.0, 0.0, math.inf), ValueError, "radius is inf"),
        (lambda: Volume.circle(0.0, 0.0, -1.0), ValueError, "negative radius"),
        (lambda: Volume.rect(0.0, 0.0, -1.0, 1.0), ValueError, "negative half extents"),
        (lambda: Volume.rect(0.0, 0.0, 1.0, math.nan), ValueError, "half_height is NaN"),
        (lambda: Volume.rect(1e30, 0.0, 1.0, 1.0), ValueError, "out of range"),
        (lambda: Volume.capsule(0.0, 0.0, 1.0, math.nan, 0.1), ValueError, "y1 is NaN"),
        (lambda: Volume.circle(0.0, 0.0, 1.0, -1), ValueError, "hit is -1"),
        (lambda: Volume.circle(0.0, 0.0, 1.0, 2**32), ValueError, "hit is"),
        (lambda: Volume.circle(0.0, 0.0, 1.0, "HIT"), TypeError, named("hit")),
        (lambda: HitWorld("octree"), ValueError, "broadphase"),
    ],
)
def test_bad_volumes_are_refused_naming_the_argument(make, error, match):
    with pytest.raises(error, match=match):
        make()


def test_bad_objects_are_refused_naming_the_argument():
    world = HitWorld()
    world.begin_frame()
    v = [Volume.circle(0.0, 0.0, 1.0)]
    for kwargs, error, match in [
        ({"owner": -1}, ValueError, "owner is -1"),
        ({"owner": 1.5}, TypeError, named("owner")),
        ({"x": math.nan}, ValueError, "x is NaN"),
        ({"height": math.inf}, ValueError, "height is inf"),
        ({"width": -1.0}, ValueError, "size"),
        ({"x": 1e30}, ValueError, "out of range"),
        ({"motion": (0.0, math.nan)}, ValueError, r"motion\[1\] is NaN"),
        ({"aim": (0.0, 0.0)}, ValueError, "aim"),
        ({"aim": (math.inf, 0.0)}, ValueError, r"aim\[0\] is inf"),
        ({"team": -2}, ValueError, "team is -2"),
        ({"swing": -1}, ValueError, "swing is -1"),
        ({"attack": [1]}, TypeError, named("attack")),
        ({"vulnerable": "abc"}, TypeError, named("vulnerable")),
    ]:
        args = {"owner": 1, "x": 0.0, "y": 0.0, "width": 1.0, "height": 1.0, "attack": v}
        args.update(kwargs)
        with pytest.raises(error, match=match):
            world.register(**args)
    assert len(world) == 0, "nothing was registered"


def test_an_id_of_this_frame_that_no_object_has_raises_key_error():
    world, other = HitWorld(), HitWorld()
    world.begin_frame()
    other.begin_frame()
    world.register(1, 0.0, 0.0, 1.0, 1.0)
    far = [other.register(k, 0.0, 0.0, 1.0, 1.0) for k in range(3)][-1]
    assert far.frame == world.frame and far not in world
    with pytest.raises(KeyError, match="no object 2"):
        world.owner(far)
    assert "ObjectId(index=2, frame=1)" == repr(far)
