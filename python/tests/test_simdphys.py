"""The simdphys Python module (docs/python.md): scene files, stepping, zero-copy numpy views whose
writes the next step sees and checks, snapshots, batch queries and the paths."""
import math
import os
import pathlib

import numpy as np
import pytest

import simdphys

SCENES = pathlib.Path(os.environ["SIMDPHYS_SOURCE_DIR"]) / "scenes"


def test_paths_are_listed_and_set():
    paths = simdphys.available_paths()
    assert paths[-1] == "reference"
    before = simdphys.active_path()
    simdphys.set_path("reference")
    assert simdphys.active_path() == "reference"
    simdphys.set_path(before)
    with pytest.raises(simdphys.Error, match="avx9000"):
        simdphys.set_path("avx9000")


def test_a_scene_file_loads_and_steps():
    scene = simdphys.load_scene(SCENES / "w5_pyramid_b10.json")
    assert scene["name"] == "W5 pyramid, B = 10"
    assert scene["frames"] == 600
    world = scene["world"]
    assert world.body_count == 385
    y0 = world.bodies()["y"].copy()
    world.step(10)
    y = world.bodies()["y"]
    # The pyramid settles by its contacts' compliance (1.1 mm in 10 frames at the default 5
    # substeps), within W5's bound on a box's displacement at the end (2.5 mm, Jolt's figure).
    assert np.max(np.abs(y - y0)) < 2.5e-3
    assert np.all(np.isfinite(y))


def test_a_bad_scene_file_raises_naming_the_place():
    bad = SCENES.parent / "tests" / "scene_files" / "negative_half_extent.json"
    with pytest.raises(simdphys.Error, match=r"/rigid/bodies/17/halfExtents/1: must be positive"):
        simdphys.load_scene(bad)


def test_particle_views_share_memory_and_a_write_is_seen_by_the_next_step():
    world = simdphys.World(time_step=1 / 60)
    world.add_plane(normal=[0, 1, 0])
    world.add_particles(np.array([[0, 5, 0], [1, 5, 0]], dtype=np.float32))
    p = world.particles(0)
    assert p["y"].dtype == np.float32 and p["y"].shape == (2,)
    assert not p["y"].flags["OWNDATA"]  # a view of the world's stream, no copy
    p["vx"][1] = 3.0  # written through numpy...
    world.step()
    q = world.particles(0)
    # ...and moved by the step: x' = x + v dt + a dt^2 / 2 along x (no force along x).
    assert q["x"][1] == pytest.approx(1 + 3.0 / 60, rel=1e-6)
    assert q["x"][0] == 0.0
    # The old view sees the same memory as the new one.
    assert p["x"][1] == q["x"][1]


def test_a_bad_write_is_refused_by_the_next_step_and_nothing_moves():
    world = simdphys.World()
    world.add_particles(np.zeros((3, 3), dtype=np.float32))
    p = world.particles(0)
    p["y"][2] = math.nan
    before = world.snapshot()
    with pytest.raises(simdphys.Error, match=r"particle system 0: particle 2: y is nan"):
        world.step()
    p["y"][2] = 0  # the world kept its state apart from the written value
    world.step()
    assert before != world.snapshot()


def test_body_views_write_through_and_a_bad_quaternion_is_refused():
    world = simdphys.World()
    world.add_body(position=[0, 10, 0])
    b = world.bodies()
    b["vx"][0] = 2.0
    world.step()
    assert world.bodies()["x"][0] == pytest.approx(2.0 / 60, rel=1e-5)
    b["qw"][0] = 2.0  # not a unit quaternion
    with pytest.raises(simdphys.Error, match=r"bodies: body 0: \|orientation\|"):
        world.step()


def test_a_hull_body_rests_on_the_ground_and_bad_points_are_refused():
    world = simdphys.World()
    world.add_plane([0, 1, 0])
    corners = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
    world.add_body(shape="hull", points=corners, position=[0, 2, 0])
    with pytest.raises(simdphys.Error, match="the points are flat"):
        world.add_body(shape="hull", points=corners[corners[:, 1] > 0], position=[0, 4, 0])
    with pytest.raises(simdphys.Error, match="only for a hull"):
        world.add_body(shape="box", points=corners)
    assert world.body_count == 1
    world.step(120)
    # A unit cube made of its corners rests on its face, its centre within the 5 mm slop of 0.5.
    assert world.bodies()["y"][0] == pytest.approx(0.5, abs=0.005)


def test_adding_after_a_view_is_refused():
    world = simdphys.World()
    world.add_body(position=[0, 1, 0])
    world.bodies()
    with pytest.raises(simdphys.Error, match="dangling"):
        world.add_body(position=[0, 3, 0])


def test_snapshots_restore_a_world_that_steps_the_same():
    scene = simdphys.load_scene(SCENES / "playground.json")
    world = scene["world"]
    world.step(5)
    copy = simdphys.World.restore(world.snapshot())
    world.step(5)
    copy.step(5)
    assert world.snapshot() == copy.snapshot()
    with pytest.raises(simdphys.Error, match="corrupt"):
        damaged = bytearray(world.snapshot())
        damaged[100] ^= 1
        simdphys.World.restore(bytes(damaged))


def test_mesh_raycasts_and_box_queries_from_numpy():
    # Two triangles making the square [0, 1] x [0, 1] at z = 0.
    mesh = simdphys.Mesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float32),
                         np.array([[0, 1, 2], [0, 2, 3]], dtype=np.uint32))
    origins = np.array([[0.75, 0.25, 2], [0.25, 0.75, 2], [3, 3, 2]], dtype=np.float32)
    directions = np.tile(np.array([0, 0, -1], dtype=np.float32), (3, 1))
    t, tri = mesh.raycast(origins, directions)
    assert t[0] == 2 and tri[0] == 0
    assert t[1] == 2 and tri[1] == 1
    assert math.isinf(t[2]) and tri[2] == 2**32 - 1
    assert sorted(mesh.overlap_sphere([0.5, 0.5, 0.1], 0.2)) == [0, 1]
    tree = simdphys.BoxTree(np.array([[0, 0, 0], [5, 5, 5]], dtype=np.float32),
                            np.array([[1, 1, 1], [6, 6, 6]], dtype=np.float32))
    pairs = tree.query(np.array([[0.5, 0.5, 0.5], [2, 2, 2]], dtype=np.float32),
                       np.array([[5.5, 5.5, 5.5], [3, 3, 3]], dtype=np.float32))
    assert sorted(map(tuple, pairs.tolist())) == [(0, 0), (0, 1)]
    with pytest.raises(simdphys.Error, match=r"shape \(n, 3\)"):
        mesh.raycast(np.zeros((2, 2), dtype=np.float32), np.zeros((2, 2), dtype=np.float32))


def test_the_batch_runner_gives_each_job_the_result_it_gives_alone():
    batch = SCENES.parent / "tests" / "batch" / "small.json"
    together = simdphys.run_batch(batch, threads=2)
    alone = simdphys.run_batch(batch, threads=1)
    assert len(together) == 7
    assert [r["job"] for r in together] == list(range(7))
    assert not any(r["failed"] for r in together)
    assert [r["state_hash"] for r in together] == [r["state_hash"] for r in alone]
    # The sweep's two substep counts give two different pyramids, both standing.
    assert together[0]["state_hash"] != together[1]["state_hash"]
    assert together[0]["standing"] and together[0]["bodies"] == 385
