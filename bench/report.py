#!/usr/bin/python3
"""Benchmark report for simdphys, generated from Google Benchmark JSON.

usage: report.py RESULTS.json [--md docs/benchmarks.md] [--img docs/img] [--quiet]

Prints one table row per benchmark (task/method/path/n) with its ratios to the scalar
reference, to the auto-vectorised loop on the same path and to the fastest peer; with --md
writes the Markdown report (machine, workloads, targets), with --img one PNG per workload.
"""
import argparse
import json
import os
import re
import sys
from collections import namedtuple

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

# Per task: throughput unit, and the reference method it is also compared with ("base").
TASKS = {
    "aabb_query": ("tests/s", "brute"), "aabb_build": ("boxes/s", None),
    "aabb_pairs": ("boxes/s", "grid"), "cull_spheres": ("objects/s", "planes"),
    "cull_boxes": ("objects/s", "planes"), "bandwidth": ("B/s", None),
    "ray_boxes": ("ray-box tests/s", "closest"), "ray_spheres": ("ray-sphere tests/s", "closest"),
    "ray_triangles": ("ray-triangle tests/s", "closest"),
    "rays/coherent": ("rays/s", "bvh"), "rays/incoherent": ("rays/s", "bvh"),
    "rays/build": ("triangles/s", None),
    "obb_obbs": ("OBB tests/s", "sat"), "sphere_spheres": ("sphere tests/s", "batch"),
    "sphere_boxes": ("sphere-box tests/s", "batch"), "point_boxes": ("point-box tests/s", "batch"),
    "closest_boxes": ("closest points/s", "batch"),
    "pairs2d": ("pairs/s", "banded_sweep"), "narrow2d": ("candidate pairs/s", None),
    "scene_build": ("boxes/s", None),
    "particles": ("particle steps/s", "w4"), "world_step": ("steps/s", None),
    "cloth": ("spring updates/s", None), "pyramid": ("body steps/s", None),
    "integrate_projectile": ("particle steps/s", None),
    "integrate_oscillator": ("particle steps/s", None),
}
BATCH2D = ["batch2d_circle_circles", "batch2d_rect_rects", "batch2d_orect_orects",
           "batch2d_point_circles", "batch2d_point_rects", "batch2d_point_orects"]
TASKS.update({t: ("element tests/s", "batch") for t in BATCH2D})
# Units always shown at one scale, whatever the value: (factor, label).
FIXED_UNITS = {"rays/s": (1e6, "Mrays/s")}
# Report sections: title, tasks, image name (or None), what is compared. A task name takes every
# method of the task; a tuple (task, method, ...) only those methods.
SECTIONS = [
    ("W1 query: batched AABB overlap counts", ["aabb_query"], "aabb_query",
     "1,024 query boxes against N boxes, overlaps counted; throughput is box tests per second "
     "(Q x N / s) whatever the algorithm, so the tree (bvh) and the brute-force loop (brute, "
     "the book's algorithm: every box tested) are on one scale. 'vs autovec' is the "
     "compiler-vectorised brute-force loop: a like-for-like ratio for brute, an algorithm "
     "ratio for bvh. 'vs ref brute' compares with the scalar reference's brute-force loop. Peer: "
     "Bullet's btDbvt (bullet_dbvt), aabbTest on the tree createProxy builds."),
    ("W1 build: SAH tree build", ["aabb_build"], None,
     "Building the bounding volume hierarchy over the N boxes (one path only)."),
    ("W1 pairs: broadphase", ["aabb_pairs"], "aabb_pairs",
     "All overlapping pairs among N boxes; throughput is boxes per second. grid is the default "
     "method and the only one run on the reference path ('vs ref grid' compares every method "
     "with it); autovec is the grid sweep with its inner loop left to the compiler. Each "
     "method runs on a persistent PairFinder. Peer: Bullet's btDbvtBroadphase in deferred mode "
     "(bullet_dbvt), persistent too, as a world keeps it: a step sets the N boxes (setAabb) "
     "and calls calculateOverlappingPairs, which in deferred mode collides the dynamic tree "
     "with itself, a complete pair search."),
    ("W2 rays: closest hits on a heightfield", ["rays/coherent", "rays/incoherent"], "w2_rays",
     "Closest hits of the 786,432 rays of a 1024 x 768 camera (coherent) and of 1,000,000 rays "
     "from random points in random directions (incoherent) against the 524,288 triangles of the "
     "W2 heightfield, through the mesh BVH; throughput is millions of rays per second. bvh "
     "traces single rays in stream order, and is the only method also run on the reference path "
     "('vs ref bvh' compares every method with that scalar traversal); auto is the default "
     "stream options: coherent groups of 16 rays traced as packets, the other rays sorted by "
     "where they enter the tree and traced singly; packet16 and packet8 trace the image's "
     "4 x 4 and 4 x 2 tiles as packets (coherent set only). Peers: Embree 3 used as its "
     "documentation asks, the camera rays with a COHERENT intersect context and the random "
     "rays with the default INCOHERENT one: rtcIntersect1 (embree_intersect1, single rays), "
     "rtcIntersect8 and rtcIntersect16 on the same 4 x 2 and 4 x 4 tiles (embree_intersect8, "
     "embree_intersect16, coherent set) and its stream API rtcIntersect1M "
     "(embree_intersect1M), on a scene with the default flags (Embree's fast triangle test) "
     "and, as embree_robust_*, with RTC_SCENE_FLAG_ROBUST (its watertight test); Bullet's "
     "btBvhTriangleMeshShape (bullet_bvh_triangle_mesh). Check: the hit count against W2's "
     "figure (a simdphys run fails if it differs; a peer is measured whatever it answers); "
     "'differ' counts the rays whose answer differs from the double-precision reference, "
     "'excused' those whose difference W2 excuses (a hit within 1e-5 of a triangle edge); the "
     "sum of hit triangle ids is shown where it is off its figure."),
    ("W2 build: mesh BVH over 524,288 triangles", ["rays/build"], "w2_build",
     "Building the mesh BVH over the W2 heightfield's 524,288 triangles, on each path (the "
     "binning and partitioning run on the path's SIMD target); ms/iter is the build time, "
     "throughput triangles per second. The mesh's copy is not timed, nor is the copy of the "
     "geometry into Embree's buffers. Peers: Embree's build at its default quality "
     "(embree_medium) and at high quality (embree_high), and Bullet's btBvhTriangleMeshShape "
     "(bullet_bvh_triangle_mesh)."),
    ("W6 cull: frustum culling",
     ["cull_spheres", ("cull_boxes", "planes", "autovec", "planes_dram")], "cull",
     "1,000,000 spheres (16 bytes each) or AABBs (24 bytes each) tested against six planes; "
     "planes and autovec cull the same 16 or 24 MiB every iteration, which stays largely in "
     "a 32 MiB last-level cache; planes_dram (best path) cycles through copies of the data, "
     "at least 128 MiB in all, so each iteration reads from main memory (its bytes/s are "
     "read against the 512 MiB streaming read in the targets). 'double-ref diff' is the "
     "number of objects whose visibility differs from a double-precision cull. The culls of "
     "the same boxes through the octree and the BVH are in the scene section below."),
    ("Scene: culling through the octree and the BVH, and their build",
     [("cull_boxes", "octree", "bvh"), "scene_build"], "scene",
     "The 1,000,000 W6 boxes culled through the scene's structures rather than as a flat "
     "stream: octree walks the octree and tests its leaves' boxes on each path; bvh walks the "
     "top-level BVH, scalar code whatever the path (its leaves are single boxes). 'vs ref "
     "planes' compares with the flat cull on the reference path, 'vs autovec' with the flat "
     "cull's plain loop on the same path. Both must find the 102,099 "
     "visible boxes. scene_build is what building each structure over the same boxes costs: "
     "the octree (scalar code) and the BVH (best path)."),
    ("Batch raycasts: one ray against a stream", ["ray_boxes", "ray_spheres", "ray_triangles"],
     "rays",
     "256 rays (seed 3) each find their closest hit among 100,000 W1 boxes, 100,000 spheres "
     "(seed 7) or the 32,768 triangles of a 129 x 129 W2 heightfield, testing every element; "
     "throughput is element tests per second. 'error' is the largest |t - t_double| / "
     "max(1, t_double) against the same query in double; 'differing' counts rays whose hit or "
     "element differs from it. 'autovec' is the same test as a plain loop compiled for the "
     "path."),
    ("Batch 3D overlap: one shape against a stream",
     ["obb_obbs", "sphere_spheres", "sphere_boxes", "point_boxes", "closest_boxes"], "overlap3d",
     "Every query against a whole stream, counted as element tests per second: 16 OBBs (seed 9) "
     "against 100,000 OBBs by the separating-axis test (sat); 64 spheres (seed 11, radii 2 to "
     "10) against 100,000 spheres or the 100,000 W1 boxes; 64 points against the W1 boxes "
     "(point_boxes); and the closest point of each W1 box to 64 points (closest_boxes). batch "
     "is the library's call on the path, autovec the same test as a plain loop compiled for "
     "it. Every path must find exactly what the scalar functions find (count and indices, else "
     "the run fails); 'differ from double' counts the (query, element) answers that differ "
     "from the same test in double, the same on every path."),
    ("W7 pairs: 2D broadphase and narrowphase", ["pairs2d", "narrow2d"], "pairs2d",
     "All overlapping pairs among the bounding rectangles of N circles and oriented rectangles "
     "(W7, 40 square units per shape); throughput is pairs found per second. banded_sweep (the "
     "default from a few hundred shapes up) sweeps along x inside horizontal bands; sweep is "
     "the textbook sweep and prune in a single band; brute tests every pair; quadtree is scalar "
     "code; the _autovec variants are the same methods with their inner loop left to the "
     "compiler ('vs autovec' compares each method with its own). Below 100,000 shapes the "
     "methods run on the best path only, for the crossover between them; at 100,000 (W7's "
     "size) every path runs, and the reference path for banded_sweep and sweep. quadtree and "
     "narrow2d, intersects() on each candidate pair's two shapes (candidate pairs per second), "
     "run at every size. Check: the pair count and the colliding pairs among them against the "
     "reference figures (61,074 and 43,894 at 100,000)."),
    ("W7 batch kernels: one 2D shape against a stream", BATCH2D, "batch2d",
     "The 256 W7 query shapes (128 circles and 128 oriented rectangles, with their bounding "
     "rectangles and centres as the rectangle and point queries), each against a stream of the "
     "N = 100,000 workload: its 50,000 circles, 50,000 oriented rectangles or 100,000 bounding "
     "rectangles; throughput is element tests per second. batch is the library's call on the "
     "path, autovec the same kernel as a plain loop compiled for it; every path must find the "
     "reference path's hit total."),
    ("W4 particles: bouncing off a ground box and a ramp", ["particles", "world_step"],
     "particles",
     "N particles dropped from rest onto a ground box and a ramp rotated 0.35 rad about z (W4: "
     "restitution 0.7, damping 0.95 a step, friction 0, the default integrator, velocity "
     "Verlet), 300 frames at 60 Hz a run, one iteration a frame: ms/iter is the time of a "
     "frame, throughput particle steps per second, and beside it the bytes a step must move "
     "(position, velocity and inverse mass read, position and velocity written: 52 B a "
     "particle). w4 steps the world on the path; autovec with the step's plain loop over the "
     "streams, compiled for the path. Check, at the end of the 300 frames: particles inside an "
     "obstacle (must be 0, else the run fails), the mean height, the distance from the same "
     "world stepped by the double-precision reference (largest, root mean square, and the "
     "fraction of particles more than 1e-3 m from it), and the bytes/s as a share of the 512 "
     "MiB streaming read of this run. world_step: one step of an empty world, and of a world "
     "holding W4's obstacles and one particle (resting after the first second)."),
    ("W3 cloth: a hanging cloth over a sphere", ["cloth"], "cloth",
     "An n x n cloth (spacing 0.05, pinned at two corners, structural, shear and bend springs) "
     "falling onto a sphere of radius 0.5 for 300 frames at 60 Hz, one iteration a frame. At "
     "the end: the relative stretch of the structural springs (mean, 99th percentile, largest, "
     "largest away from the pinned corners), and over every frame the deepest penetration into "
     "the true sphere; finite: every position stayed finite; exploded: the frame where the "
     "99th-percentile stretch first passed 1. Peer: Bullet's btSoftBody set up as its SoftDemo "
     "cloth, at its default position iterations and at 10 and 30. simdphys: xpbd is the grid "
     "cloth at the defaults (XPBD, 10 substeps, tethers) on every path; autovec the same step "
     "as plain loops; xpbd_network the same springs as a general network (greedy colours, "
     "indexed loads); xpbd_s<k> other substeps and _untethered without tethers; "
     "mass_spring_k1e<e> the mass-spring model with every spring at 10^e N/m (its substeps set "
     "by the stability bound). error: the largest distance from the same cloth stepped by the "
     "double-precision reference, after 10 frames and at the end. The plot sets the mean "
     "stretch against the time of a frame."),
    ("W5 pyramid: a square pyramid of unit boxes", ["pyramid"], "pyramid",
     "A pyramid of unit boxes (base B = 10: 385 boxes, B = 20: 2,870; mass 1, friction 0.6, "
     "no restitution, no sleeping) on a ground box, 600 frames at 60 Hz, one iteration a frame. "
     "At the end: the largest displacement of any box from its start (a stable solver keeps it "
     "below 0.05) and whether every box is within 0.5 of its start; over every frame the "
     "deepest penetration of any contact, by the engine's own measure. soft_step_s<k>_i<i> is the "
     "soft step (60 Hz contacts) with k substeps and i iterations, the default k = 6; "
     "baumgarte and projection the rigid models over their iterations. error: the largest and "
     "RMS distance of a box from the same pyramid stepped by the double-precision reference "
     "(B = 10, the three models' usual settings). The defaults run on every path (the contact "
     "passes as kernels; contact_passes: their time a frame) and as the kernels' plain loops "
     "(autovec); the sweeps on the reference. Peers: Bullet's sequential impulses "
     "(10 iterations) and ODE's QuickStep (20 iterations) at its defaults and at its stacking "
     "settings. The plot sets the displacement and the penetration against the time of a frame."),
    ("Integrators: error against cost on closed forms",
     ["integrate_projectile", "integrate_oscillator"], "integrators",
     "The four integrators at time steps 1/30 to 1/480 s. projectile: 10,000 particles thrown "
     "from random points at random velocities, stepped for 1 s by a World on the best path (no "
     "obstacles, no damping); error: the largest distance from x0 + v0 t + g t^2 / 2. "
     "oscillator: 1,000 particles on x'' = -(2 pi)^2 x, 10 periods, through the scalar "
     "reference's integrate() in float with the spring evaluated each step (a World holds a "
     "force for a whole step, so it cannot pose this case); error: the largest distance from "
     "x0 cos wt + v0 / w sin wt. Position Verlet starts from the velocity half a step back, "
     "the mean over the step before the start that its state holds. A step costs the same at "
     "every dt, so the plot sets the error against the cost of a simulated second (ns a "
     "particle step / dt)."),
    ("Bandwidth: streaming read", ["bandwidth"], "bandwidth",
     "A plain reduction over a buffer at the W6 working-set sizes and at 512 MiB (main "
     "memory): the ceiling the memory-bound kernels are read against."),
]
AVX512 = ("avx512dl", "avx512")
# rate: throughput in the task's unit (bytes/s for bandwidth); bps: bytes/s where reported.
# ms: wall-clock (real) time per iteration, what ratios use; cpu_ms: the CPU time beside it.
Run = namedtuple("Run", "task method path n ms cpu_ms rate bps counters error")


def load(path):
    """Reads the JSON; returns (context, {(task, method, path, n): Run}). With repetitions the
    median is used, and context["_runs"] says so."""
    with open(path) as f:
        data = json.load(f)
    entries = data.get("benchmarks", [])
    context = data.get("context", {})
    context["_runs"] = "one run each"
    if any(e.get("aggregate_name") == "median" for e in entries):
        entries = [e for e in entries if e.get("aggregate_name") == "median"]
        context["_runs"] = (f"median of {entries[0].get('repetitions', '?')} repetitions; "
                            "scripts/demo runs them in random order across all benchmarks")
    else:
        entries = [e for e in entries if e.get("run_type", "iteration") == "iteration"]
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    runs = {}
    for e in entries:
        # Google Benchmark appends /iterations:<k> to runs of a fixed iteration count and
        # /real_time to runs timed in wall-clock time.
        name = e.get("run_name", e["name"]).removesuffix("/real_time")
        parts = re.sub(r"/iterations:\d+$", "", name).split("/")
        if len(parts) < 4 or not parts[-1].isdigit():
            continue
        # The task may hold a slash itself (rays/coherent): n, path and method are the last three.
        task, method, p, n = "/".join(parts[:-3]), *parts[-3:]
        unit = scale[e.get("time_unit", "ns")]
        ms = e.get("real_time", 0) * unit
        failed = bool(e.get("error_occurred"))
        runs[(task, method, p, int(n))] = Run(
            task, method, p, int(n), ms if ms > 0 and not failed else None,
            e.get("cpu_time", 0) * unit,
            e.get("bytes_per_second" if unit_of(task) == "B/s" else "items_per_second"),
            e.get("bytes_per_second"), e, e.get("error_message", "failed") if failed else None)
    return context, runs


def names(tasks):
    """The task names of a section's tasks (a name, or a tuple of a name and its methods)."""
    return [t if isinstance(t, str) else t[0] for t in tasks]


def picks(tasks, r):
    """Whether run r belongs to a section's tasks: a task name takes every method of the task,
    a tuple (task, method, ...) only those methods."""
    return any(r.task == t if isinstance(t, str) else r.task == t[0] and r.method in t[1:]
               for t in tasks)


def sections(runs):
    """The report's sections that have runs, plus one for the runs no section describes."""
    left = {}
    for r in runs.values():
        if not any(picks(ts, r) for _, ts, _, _ in SECTIONS):
            left.setdefault(r.task, set()).add(r.method)
    other = [(t, *sorted(ms)) for t, ms in sorted(left.items())]
    return [s for s in SECTIONS + [("Other", other, None, "Tasks not described here.")]
            if any(picks(s[1], r) for r in runs.values())]


def baselines(runs, r):
    """The ratios of one run (baseline time / this time): vs the same method on the reference
    path, vs the task's base method on it, vs the plain loop on the same path (the method's own,
    <method>_autovec, where there is one, else autovec), vs the fastest peer."""
    base = TASKS.get(r.task, ("", None))[1]
    peers = [p.ms for p in runs.values()
             if p.task == r.task and p.n == r.n and p.path == "peer" and p.ms]
    plain = r.method if r.method.endswith("autovec") else r.method + "_autovec"
    if (r.task, plain, r.path, r.n) not in runs:
        plain = "autovec"
    keys = {"ref": (r.task, r.method, "reference", r.n), "base": (r.task, base, "reference", r.n),
            "autovec": (r.task, plain, r.path, r.n)}
    dram = r.method.endswith("_dram")  # read from main memory: no baseline reads the same way
    out = {k: runs[key].ms / r.ms if not dram and key in runs and runs[key].ms and r.ms else None
           for k, key in keys.items()}
    out["peer"] = min(peers) / r.ms if peers and r.ms else None
    return out


def unit_of(task):
    """The throughput unit of a task ('B/s' for bandwidth)."""
    return TASKS.get(task, ("items/s", None))[0]


def prefix(value, unit):
    """Engineering scale and unit label: (1.31e9, 'objects/s') -> (1e9, 'G objects/s')."""
    if unit in FIXED_UNITS:
        return FIXED_UNITS[unit]
    exp = 0
    while exp < 4 and abs(value) >= 1000 ** (exp + 1):
        exp += 1
    pre = ["", "k", "M", "G", "T"][exp]
    return 1000 ** exp, pre + unit if unit == "B/s" else f"{pre} {unit}".strip()


def eng(value, unit):
    """Engineering notation: (1.31e9, 'objects/s') -> '1.31 G objects/s', 5.2e10 B/s -> GB/s."""
    if value is None:
        return "-"
    factor, label = prefix(value, unit)
    scaled = value / factor
    return f"{scaled:.{0 if scaled >= 100 else 1 if scaled >= 10 else 2}f} {label}"


def fixed(v, suffix=""):
    """A number to about three significant digits: 0.0042, 0.481, 5.25, 28.5, 2068."""
    if v is None:
        return "-"
    return (f"{v:.2g}" if v < 0.1 else f"{v:.3f}" if v < 1 else f"{v:.2f}" if v < 10
            else f"{v:.1f}" if v < 100 else f"{v:.0f}") + suffix


def times(v):
    """A ratio as printed: '-', '0.0072x', '0.93x', '28.5x', '2068x'."""
    return f"{v:.2f}x" if v is not None and 0.1 <= v < 10 else fixed(v, "x")


def size(r):
    """N as printed: thousands separated, bytes of the bandwidth runs in MiB."""
    return f"{r.n >> 20} MiB" if r.task == "bandwidth" else f"{r.n:,}"


def check(r, runs):
    """The correctness column: exact/checksum, the double-reference difference, or the error."""
    c = r.counters
    if r.error:
        return "FAILED: " + r.error
    if r.task.startswith("rays/") and "differ" in c:
        return rays_check(c)
    if r.task == "particles" and "inside" in c:
        return particles_check(r, runs)
    if "ns_per_step" in c and r.task == "world_step":
        return f"{c['ns_per_step']:.0f} ns a step"
    notes = []
    if "exact" in c:
        notes.append("exact" if c["exact"] == 1 else f"result {c.get('result', 0):.0f} inexact")
    if "checksum_ok" in c:
        notes.append("checksum OK" if c["checksum_ok"] == 1 else "checksum WRONG")
    if "colliding_ok" in c:
        notes.append(f"{c.get('colliding', 0):,.0f} colliding"
                     + ("" if c["colliding_ok"] == 1 else " (WRONG)"))
    if r.task.startswith("cull") and "error" in c:
        notes.append(f"double-ref diff: {c['error']:.0f}")
    if r.task.startswith("ray_") and "error" in c:
        notes.append(f"{c.get('result', 0):.0f} hits, t error {c['error']:.2g} vs double, "
                     f"{c.get('differing', 0):.0f} rays differ")
    elif "differing" in c:
        notes.append(f"{c['differing']:.0f} differ from double")
    if "nodes" in c:
        notes.append(", ".join(f"{c[k]:,.0f} {k}" for k in ("nodes", "entries", "blocks")
                               if k in c) + (f", depth {c['depth']:.0f}" if "depth" in c else ""))
    return ", ".join(notes)


def rays_check(c):
    """The W2 checks: the hit count against its figure, the rays whose answer differs from the
    double reference (not counting the excused ones) and the excused ones, and the sum of hit
    triangle ids where it is off its figure."""
    notes = ["hits exact" if c.get("exact") == 1 else
             f"{c.get('result', 0):,.0f} hits of {c.get('expected', 0):,.0f}",
             f"{c['differ']:.0f} differ", f"{c.get('excused', 0):.0f} excused"]
    off = c.get("sum_id", 0) - c.get("sum_id_expected", 0)
    if off:
        notes.append(f"id sum {off:+,.0f} vs figure")
    return ", ".join(notes)


def particles_check(r, runs):
    """The W4 checks: particles inside an obstacle (and how deep), the mean final height, the
    distance from the double reference, and bytes/s as a share of this run's streaming read from
    memory."""
    c = r.counters
    bw = runs.get(("bandwidth", "read", "scalar", 512 << 20))
    share = (f", {100 * r.bps / bw.bps:.0f}% of the 512 MiB streaming read"
             if bw and bw.bps and r.bps else "")
    inside = (f"{c['inside']:.0f} inside (must be 0; deepest {c.get('inside_depth', 0):.2g} m)"
              if c["inside"] else "0 inside")
    if c.get("pushed_out"):  # found inside at a step's start: a frame before ended inside
        inside += f" ({c['pushed_out']:.0f} pushed out on the way)"
    return (f"{inside}, mean height {c['mean_height']:.3f} m, vs double: max "
            f"{c['error_max']:.2g} m, rms {c['error_rms']:.2g} m, "
            f"{100 * c['apart_fraction']:.2f}% > 1e-3 m" + share)


INTEGRATORS = ["explicit Euler", "semi-implicit Euler", "velocity Verlet", "position Verlet"]


def integrator_rows(runs):
    """The integrator runs by (integrator, steps a second): {case: run}, case 'projectile' or
    'oscillator'."""
    rows = {}
    for r in runs.values():
        if r.task.startswith("integrate_") and r.ms and "dt" in r.counters:
            key = (int(r.counters["integrator"]), round(1 / r.counters["dt"]))
            rows.setdefault(key, {})[r.task.removeprefix("integrate_")] = r
    return dict(sorted(rows.items()))


def small_table(head, body, left, markdown):
    """A section's own table: the first `left` columns text, the others numbers (right-aligned);
    Markdown or plain text."""
    if markdown:
        rule = "|" + "---|" * left + "--:|" * (len(head) - left)
        return "\n".join(["| " + " | ".join(head) + " |", rule]
                         + ["| " + " | ".join(row) + " |" for row in body])
    width = [max(len(row[i]) for row in [head] + body) for i in range(len(head))]
    return "\n".join("  ".join(c.ljust(w) if i < left else c.rjust(w)
                               for i, (c, w) in enumerate(zip(row, width))).rstrip()
                     for row in [head] + body)


def integrator_table(runs, tasks, markdown):
    """Integrator, dt, and per case the ns a particle step and the error at the end."""
    head = ["integrator", "dt", "projectile ns/step", "projectile error (m)",
            "oscillator ns/step", "oscillator error (m)"]
    cell = lambda r, k, f: f(r.counters[k]) if r else "-"  # noqa: E731
    body = []
    for (i, hz), cases in integrator_rows(runs).items():
        row = [INTEGRATORS[i] if i < len(INTEGRATORS) else str(i), f"1/{hz} s"]
        for case in ("projectile", "oscillator"):
            r = cases.get(case)
            row += [cell(r, "ns_per_step", lambda v: f"{v:.2f}"),
                    cell(r, "error", lambda v: f"{v:.2e}")]
        body.append(row)
    return small_table(head, body, 2, markdown)


def integrator_plot(runs, tasks, title, filename):
    """Error against the cost of a simulated second (log-log), a line per integrator through
    its time steps, a panel per case."""
    rows = integrator_rows(runs)
    cases = [c for c in ("projectile", "oscillator") if any(c in v for v in rows.values())]
    if not cases:
        return False
    fig, axes = plt.subplots(1, len(cases), figsize=(6 * len(cases), 4.5), squeeze=False)
    for ax, case in zip(axes[0], cases):
        for i, name in enumerate(INTEGRATORS):
            pts = sorted((hz, r) for (k, hz), v in rows.items() if k == i
                         for c, r in v.items() if c == case)
            if not pts:
                continue
            # ns a particle step / dt: the cost of a simulated second; errors of 0 (exact to
            # the last bit) are drawn at 1e-12 to stay on the log scale.
            xs = [r.counters["ns_per_step"] * hz for hz, r in pts]
            ys = [max(r.counters["error"], 1e-12) for _, r in pts]
            ax.plot(xs, ys, marker="o", label=name)
            for (hz, _), x, y in zip(pts, xs, ys):
                ax.annotate(f"1/{hz}", (x, y), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(case, fontsize=10)
        ax.set_xlabel("ns a particle per simulated second (lower is cheaper)", fontsize=9)
        ax.set_ylabel("largest position error at the end (m)", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle(title, x=0.02, ha="left", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(filename, dpi=100)
    plt.close(fig)
    return True


def frame_axes(ax, title, ylabel):
    """A simulation's panel: log-log, ms a frame along x."""
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("ms a frame, one thread (lower is faster)", fontsize=9)
    ax.set_ylabel(ylabel, fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="lower left")


def cloth_runs(runs):
    """The W3 runs that finished, by n then method."""
    return sorted((r for r in runs.values() if r.task == "cloth" and r.ms and not r.error),
                  key=lambda r: (r.n, r.path != "peer", r.method))


def cloth_table(runs, tasks, markdown):
    """Per run: ms a frame, spring updates a second, the stretch figures, the penetration,
    finiteness, the explosion, and the error against the double reference."""
    head = ["method", "path", "n", "substeps", "ms/frame", "spring updates/s", "stretch mean",
            "p99", "max", "max off pins", "deepest in sphere", "finite", "exploded",
            "error max at 0.17 s / end"]
    body = []
    for r in cloth_runs(runs):
        c = r.counters
        g = lambda k, f="{:.3g}": f.format(c[k]) if k in c else "-"  # noqa: E731
        boom = (f"frame {c['exploded_frame']:.0f}" if c.get("exploded") else "no")
        steps = g("substeps", "{:.0f}") if "substeps" in c else g("position_iterations", "{:.0f} it")
        err = f"{g('error_max_early')} / {g('error_max')}" if "error_max" in c else "-"
        body.append([r.method, r.path, f"{r.n}", steps, f"{r.ms:.3g}",
                     eng(c.get("spring_updates_per_second", 0), "updates/s"), g("stretch_mean"),
                     g("stretch_p99"), g("stretch_max"), g("stretch_max_away_from_pins"),
                     g("penetration"), "yes" if c.get("finite", 0) == 1 else "NO", boom, err])
    if not body:
        return ""
    return small_table(head, body, 3, markdown)


def cloth_family(method):
    """The series a W3 run belongs to in the plot: XPBD over its substeps (with or without
    tethers), the mass-spring model over its stiffness; None for a lone point."""
    if method == "xpbd" or re.fullmatch(r"xpbd_s\d+", method):
        return "XPBD, tethers"
    if method.startswith("xpbd") and method.endswith("_untethered"):
        return "XPBD, no tethers"
    if method.startswith("mass_spring"):
        return "mass-spring"
    return None


def cloth_plot(runs, tasks, title, filename):
    """Mean structural stretch against ms a frame (log-log), a panel per n: simdphys's models on
    the best path as lines over their substeps or stiffness, other runs as points, peers grey."""
    rs = cloth_runs(runs)
    ns = sorted({r.n for r in rs})
    if not ns:
        return False
    # The best path: the one the best-path-only runs (xpbd_s2, ...) ran on.
    best = next((r.path for r in rs if r.method != "xpbd" and cloth_family(r.method)), None)
    fig, axes = plt.subplots(1, len(ns), figsize=(7 * len(ns), 5), squeeze=False)
    for ax, n in zip(axes[0], ns):
        mine = [r for r in rs if r.n == n]
        families = {}
        for r in mine:
            f = cloth_family(r.method) if r.path == best else None
            if f:
                families.setdefault(f, []).append(r)
        for f, pts in families.items():
            pts.sort(key=lambda r: r.ms)
            ax.plot([r.ms for r in pts], [max(r.counters.get("stretch_mean", 0), 1e-6) for r in pts],
                    marker="o", label=f"simdphys {f} ({best})")
            for r in pts:
                ax.annotate(f"{r.counters.get('substeps', 0):.0f}", (r.ms, r.counters["stretch_mean"]),
                            fontsize=7, xytext=(3, -9), textcoords="offset points")
        for r in mine:
            if r.path != best or not cloth_family(r.method):
                if r.path not in ("peer", "reference") and r.path != best:
                    continue
                peer = r.path == "peer"
                y = max(r.counters.get("stretch_mean", 0), 1e-6)
                ax.plot([r.ms], [y], marker="s" if peer else "D", color="grey" if peer else "black",
                        linestyle="none")
                boom = " (exploded)" if r.counters.get("exploded") else ""
                ax.annotate(f"{r.method} {r.path}{boom}", (r.ms, y), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
        frame_axes(ax, f"n = {n} (numbers: substeps)",
                   "mean structural stretch at the end (lower holds better)")
    fig.suptitle(title, x=0.02, ha="left", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(filename, dpi=100)
    plt.close(fig)
    return True


def pyramid_runs(runs):
    """The W5 runs that finished, by B, peers last, then method."""
    return sorted((r for r in runs.values() if r.task == "pyramid" and r.ms and not r.error),
                  key=lambda r: (r.n, r.path == "peer", r.method))


def pyramid_table(runs, tasks, markdown):
    """Per run: ms a frame, body steps a second, displacement, penetration, standing, error."""
    head = ["method", "path", "B", "ms/frame", "body steps/s", "largest displacement",
            "deepest penetration", "standing", "error max / rms"]
    body = []
    for r in pyramid_runs(runs):
        c = r.counters
        err = (f"{c['error_max']:.2g} / {c['error_rms']:.2g}" if "error_max" in c else "-")
        body.append([r.method, r.path, f"{r.n}", f"{r.ms:.3g}",
                     eng(c.get("body_steps_per_s", 0), "steps/s"),
                     f"{c.get('max_displacement', 0):.3g}", f"{c.get('deepest_penetration', 0):.3g}",
                     "yes" if c.get("standing", 0) == 1 else "NO", err])
    return small_table(head, body, 3, markdown) if body else ""


def pyramid_family(method):
    """The series of a simdphys W5 run: a model over its substeps or iterations."""
    m = re.fullmatch(r"(soft_step|baumgarte|projection)_s(\d+)_i(\d+)", method)
    return m.group(1) if m else None


def pyramid_plot(runs, tasks, title, filename):
    """Largest displacement and deepest penetration against ms a frame (log-log), a column per
    B: simdphys's models as lines over their substeps or iterations, peers as grey points."""
    rs = pyramid_runs(runs)
    ns = sorted({r.n for r in rs})
    if not ns:
        return False
    measures = [("max_displacement", "largest displacement at the end (m)"),
                ("deepest_penetration", "deepest penetration, any frame (m)")]
    fig, axes = plt.subplots(2, len(ns), figsize=(7 * len(ns), 9), squeeze=False)
    for col, n in enumerate(ns):
        mine = [r for r in rs if r.n == n]
        for row, (key, label) in enumerate(measures):
            ax = axes[row][col]
            families = {}
            for r in mine:
                if r.path == "reference" and pyramid_family(r.method):
                    families.setdefault(pyramid_family(r.method), []).append(r)
            for f, pts in sorted(families.items()):
                pts.sort(key=lambda r: r.ms)
                ax.plot([r.ms for r in pts], [max(r.counters.get(key, 0), 1e-6) for r in pts],
                        marker="o", label=f"simdphys {f} ({pts[0].path})")
                for r in pts:
                    k = r.counters.get("substeps" if f == "soft_step" else "iterations", 0)
                    ax.annotate(f"{k:.0f}", (r.ms, max(r.counters.get(key, 0), 1e-6)), fontsize=7,
                                xytext=(3, -9), textcoords="offset points")
            for r in mine:
                if r.path != "reference":  # peers grey; the defaults on each SIMD path black
                    peer = r.path == "peer"
                    y = max(r.counters.get(key, 0), 1e-6)
                    ax.plot([r.ms], [y], marker="s" if peer else "D",
                            color="grey" if peer else "black", linestyle="none")
                    # The paths share one y (the same bits): their names slanted, clear of each
                    # other.
                    name = (r.method if peer else "plain loops" if r.method == "autovec" else
                            "fresh manifolds" if r.method.endswith("_fresh_manifolds") else
                            r.path)
                    ax.annotate(name, (r.ms, y), fontsize=7, xytext=(3, 3),
                                textcoords="offset points", rotation=0 if peer else 50)
            frame_axes(ax, f"B = {n} (numbers: substeps, or iterations)", label)
            ax.legend(fontsize=8, loc="best")
    fig.suptitle(title, x=0.02, ha="left", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(filename, dpi=100)
    plt.close(fig)
    return True


# Sections drawn by their own table and plot (by image name) rather than the generic ones.
CUSTOM = {"integrators": (integrator_table, integrator_plot), "cloth": (cloth_table, cloth_plot),
          "pyramid": (pyramid_table, pyramid_plot)}


def section_table(image, runs, tasks, markdown):
    """The section's table: its own, or the generic one."""
    return CUSTOM[image][0](runs, tasks, markdown) if image in CUSTOM else table(runs, tasks,
                                                                                 markdown)


def order(runs, tasks):
    """Runs of the given tasks: by task, n, simdphys methods before peers, method name (the
    JSON's order is random with interleaved repetitions), then path in the machine's order."""
    paths = ["avx512dl", "avx512", "avx2", "sse4", "hwy_scalar", "scalar", "reference", "peer"]
    rank = lambda p: paths.index(p) if p in paths else len(paths)  # noqa: E731
    index = names(tasks).index
    return sorted((r for r in runs.values() if picks(tasks, r)),
                  key=lambda r: (index(r.task), r.n, r.path == "peer", r.method, rank(r.path)))


def table(runs, tasks, markdown):
    """One table for the given tasks, as Markdown or as aligned text; the baseline columns
    that are '-' on every row are left out."""
    rows = order(runs, tasks)
    bases = {TASKS[t][1] for t in names(tasks) if t in TASKS and TASKS[t][1]}
    cols = [("ref", "vs ref"), ("base", "vs ref " + "/".join(sorted(bases))),
            ("autovec", "vs autovec"), ("peer", "vs peer")]
    ratios = [baselines(runs, r) for r in rows]
    cols = [(k, h) for k, h in cols if any(x[k] is not None for x in ratios)]
    head = ["task", "method", "path", "N", "ms/iter", "cpu ms", "throughput"] + [h for _, h in cols]
    body = [[r.task, r.method, r.path, size(r), fixed(r.ms), fixed(r.cpu_ms),
             eng(r.rate, unit_of(r.task))
             + (f" ({eng(r.bps, 'B/s')})" if r.bps and unit_of(r.task) != "B/s" else "")]
            + [times(x[k]) for k, _ in cols] + [check(r, runs)] for r, x in zip(rows, ratios)]
    head.append("check")
    if markdown:
        lines = ["| " + " | ".join(head) + " |",
                 "|" + "|".join("---" if i < 3 or i == len(head) - 1 else "--:"
                                for i in range(len(head))) + "|"]
        return "\n".join(lines + ["| " + " | ".join(c.replace("|", "\\|") for c in row) + " |"
                                   for row in body])
    width = [max(len(str(c[i])) for c in [head] + body) for i in range(len(head))]
    return "\n".join("  ".join(c.ljust(w) if i < 3 or i == len(row) - 1 else c.rjust(w)
                               for i, (c, w) in enumerate(zip(row, width))).rstrip()
                     for row in [head] + body)


def plot(runs, tasks, title, filename):
    """Horizontal bar chart of throughput, one panel per task and N (one per task if each N has
    a single run); simdphys, auto-vectorised, reference and peer runs in distinct colours."""
    done = [r for r in order(runs, tasks) if r.ms is not None and r.rate]
    # One panel per task and N; one per task when each N has a single run (bandwidth).
    per_n = {t: len([r for r in done if r.task == t]) > len({r.n for r in done if r.task == t})
             for t in names(tasks)}
    groups = {}
    for r in done:
        groups.setdefault((r.task, r.n if per_n[r.task] else None), []).append(r)
    if not groups:
        return False
    heights = [1.0 + 0.27 * len(g) for g in groups.values()]
    fig, axes = plt.subplots(len(groups), 1, figsize=(10, sum(heights) + 0.5), squeeze=False,
                             gridspec_kw={"height_ratios": heights})
    colours = {"simdphys": "#1f77b4", "auto-vectorised loop": "#ff7f0e",
               "scalar reference": "#7f7f7f", "peer engine": "#d62728"}
    kind = lambda r: ("peer engine" if r.path == "peer" else "scalar reference"  # noqa: E731
                      if r.path == "reference" else "auto-vectorised loop"
                      if r.method.endswith("autovec") else "simdphys")
    for ax, ((task, n), rs) in zip(axes[:, 0], groups.items()):
        factor, label = prefix(max(r.rate for r in rs), unit_of(task))
        values = [r.rate / factor for r in rs]
        ax.barh(range(len(rs)), values, color=[colours[kind(r)] for r in rs])
        ax.set_yticks(range(len(rs)),
                      [f"{r.method} / {r.path}" + ("" if n is not None else f" / {size(r)}")
                       for r in rs], fontsize=9)
        ax.invert_yaxis()
        log = max(values) / min(values) > 30
        if log:
            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        for i, v in enumerate(values):
            ax.text(v, i, f" {v:.3g}", va="center", fontsize=8)
        ax.set_xlim(right=max(values) * (3 if log else 1.12))
        ax.set_title(task + (f", N = {size(rs[0])}" if n is not None else ""), fontsize=10)
        ax.set_xlabel(f"throughput ({label}{', log scale' if log else ''}; higher is better)",
                      fontsize=9)
        ax.grid(axis="x", alpha=0.3)
    shown = [k for k in colours if any(kind(r) == k for g in groups.values() for r in g)]
    if len(shown) > 1:
        fig.legend([plt.Rectangle((0, 0), 1, 1, color=colours[k]) for k in shown], shown,
                   loc="upper right", fontsize=8, ncol=len(shown))
    fig.suptitle(title, x=0.02, ha="left", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(filename, dpi=100)
    plt.close(fig)
    return True


def targets(runs, context):
    """The issues' targets on the best AVX-512 path present: (note, rows of target, measured,
    goal, verdict)."""
    path, note = target_path(runs, context)
    rows = [ratio_row(runs, path, *spec) for spec in target_specs()]
    return note, rows + watertight(runs, path) + particle_rows(runs, path)


def target_path(runs, context):
    """The path the targets are evaluated on, the best AVX-512 one present, and a note."""
    present = [p for p in context.get("simdphys_paths", "").split(",") + list(AVX512)
               if p != "reference" and any(r.path == p for r in runs.values())]
    path = next((p for p in AVX512 if p in present), present[0] if present else "-")
    note = (f"Evaluated on path `{path}`." if path in AVX512 else
            f"No AVX-512 path in the results: evaluated on the best path present, `{path}`.")
    return path, note


def target_specs():
    """The targets read as ratios: (what, key, baseline key, goal or None for information).
    '*' in a key stands for the evaluated path; a tuple of methods for the fastest of them."""
    query, mib = ("aabb_query", "bvh", "*", 100000), 1 << 20
    specs = [("aabb_query N=100,000: bvh vs reference bvh", query,
              ("aabb_query", "bvh", "reference", 100000), 20),
             ("aabb_query N=100,000: bvh vs reference brute (algorithm and SIMD)", query,
              ("aabb_query", "brute", "reference", 100000), 20),
             ("aabb_query N=100,000: bvh vs Bullet btDbvt", query,
              ("aabb_query", "bullet_dbvt", "peer", 100000), 1.5)]
    specs += [(f"aabb_pairs N={n:,}: grid (default) vs Bullet btDbvtBroadphase deferred",
               ("aabb_pairs", "grid", "*", n), ("aabb_pairs", "bullet_dbvt", "peer", n), 5)
              for n in (100000, 1000000)]
    for task, size_mib in (("cull_spheres", 16), ("cull_boxes", 24)):
        this = (task, "planes", "*", 1000000)
        specs += [(f"{task} N=1,000,000: planes vs reference", this,
                   (task, "planes", "reference", 1000000), 10),
                  (f"{task} bytes/s vs streaming read at {size_mib} MiB (both re-read each "
                   "iteration: largely from the cache)",
                   this, ("bandwidth", "read", "scalar", size_mib * mib), 0.5),
                  (f"{task} from main memory (planes_dram) bytes/s vs streaming read at 512 MiB",
                   (task, "planes_dram", "*", 1000000),
                   ("bandwidth", "read", "scalar", 512 * mib), 0.5)]
    for task, method, n, goal in (("ray_boxes", "closest", 100000, 10),
                                  ("ray_triangles", "closest", 32768, 10),
                                  ("obb_obbs", "sat", 100000, 6)):
        specs.append((f"{task} N={n:,}: {method} vs reference", (task, method, "*", n),
                      (task, method, "reference", n), goal))
    return specs + rays_specs() + particle_specs()


def particle_specs():
    """Issue 12's W4 targets read as ratios (see target_specs)."""
    w4 = lambda n, method="w4", path="*": ("particles", method, path, n)  # noqa: E731
    return [
        ("particles N=1,000,000: w4 bytes/s vs streaming read at 512 MiB", w4(1000000),
         ("bandwidth", "read", "scalar", 512 << 20), 0.5),
        ("particles N=100,000: w4 vs reference", w4(100000), w4(100000, path="reference"), 10),
        ("particles N=100,000: w4 vs autovec (the plain loop on the same path)", w4(100000),
         w4(100000, "autovec"), 2)]


def particle_rows(runs, path):
    """Issue 12's other targets: no particle inside an obstacle at the end of any W4 run (every
    path and N), and the step of an empty world under a microsecond on the path."""
    w4 = [r for r in runs.values() if r.task == "particles"]
    counted = [r for r in w4 if "inside" in r.counters]
    worst = max((r.counters["inside"] for r in counted), default=None)
    failed = any(r.error for r in w4)
    inside = ("particles inside an obstacle after W4's 300 frames (every path, method and N)",
              "-" if worst is None else f"{worst:.0f}" + (", runs failed" if failed else ""),
              "0", "no data" if worst is None else "met" if worst == 0 and not failed
              else "missed")
    empty = runs.get(("world_step", "empty", path, 0))
    ns = empty.counters.get("ns_per_step") if empty and empty.ms else None
    step = ("world_step: a step of an empty world", "-" if ns is None else f"{ns:.0f} ns",
            "< 1000 ns", "no data" if ns is None else "met" if ns < 1000 else "missed")
    return [inside, step]


def rays_specs():
    """Issue 4's targets on W2, as ratios (see target_specs)."""
    co, inc, tris = ("rays/coherent", 786432), ("rays/incoherent", 1000000), 524288
    best = (co[0], ("packet16", "auto"), "*", co[1])
    auto = (inc[0], "auto", "*", inc[1])
    peer = lambda w, method: (w[0], method, "peer", w[1])  # noqa: E731
    return [
        ("rays/coherent N=786,432: best of packet16 and auto vs Embree rtcIntersect16 "
         "(COHERENT context)", best, peer(co, "embree_intersect16"), 1),
        ("rays/coherent N=786,432: best of packet16 and auto vs Embree's robust scene, "
         "rtcIntersect16 (information)", best, peer(co, "embree_robust_intersect16"), None),
        ("rays/coherent N=786,432: packet8 vs Embree rtcIntersect8 (information)",
         (co[0], "packet8", "*", co[1]), peer(co, "embree_intersect8"), None),
        ("rays/coherent N=786,432: bvh (single rays) vs Embree rtcIntersect1 (information)",
         (co[0], "bvh", "*", co[1]), peer(co, "embree_intersect1"), None),
        ("rays/coherent N=786,432: best of packet16 and auto vs Bullet btBvhTriangleMeshShape",
         best, peer(co, "bullet_bvh_triangle_mesh"), 8),
        ("rays/incoherent N=1,000,000: auto vs Embree rtcIntersect1", auto,
         peer(inc, "embree_intersect1"), 0.8),
        ("rays/incoherent N=1,000,000: auto vs Bullet btBvhTriangleMeshShape", auto,
         peer(inc, "bullet_bvh_triangle_mesh"), 8),
        ("rays/incoherent N=1,000,000: bvh (single rays in order) vs Embree rtcIntersect1 "
         "(information)", (inc[0], "bvh", "*", inc[1]), peer(inc, "embree_intersect1"), None),
        ("rays/incoherent N=1,000,000: auto vs Embree's stream API rtcIntersect1M "
         "(information)", auto, peer(inc, "embree_intersect1M"), None),
        ("rays/build N=524,288: sah vs Embree's default build, embree_medium (goal: no slower "
         "than 1.5x Embree's time)", ("rays/build", "sah", "*", tris),
         ("rays/build", "embree_medium", "peer", tris), 1 / 1.5)]


def fastest(runs, key, path):
    """The run of a target key ('*': the path); of a tuple of methods, the fastest one."""
    task, methods, p, n = key
    found = [runs.get((task, m, path if p == "*" else p, n))
             for m in ((methods,) if isinstance(methods, str) else methods)]
    return min((r for r in found if r), key=lambda r: r.ms or float("inf"), default=None)


def ratio_row(runs, path, what, key, base_key, goal):
    """One target row: the baseline's time over this run's (bytes/s over bytes/s against the
    bandwidth runs), the goal and the verdict; with several methods, the fastest is named."""
    a, b = fastest(runs, key, path), fastest(runs, base_key, path)
    value = None
    if a and b and a.ms and b.ms:  # bandwidth: bytes/s over bytes/s, else time over time
        value = (a.bps or 0) / b.bps if base_key[0] == "bandwidth" else b.ms / a.ms
    verdict = ("-" if goal is None else "met" if value and value >= goal else "missed"
               if value else "run failed" if (a and a.error) or (b and b.error) else "no data")
    measured = times(value) + (f" ({a.method})" if value and not isinstance(key[1], str) else "")
    return what, measured, "-" if goal is None else f">= {round(goal, 2):g}x", verdict


def watertight(runs, path):
    """Issue 4's watertightness rows: per W2 ray set, the rays whose answer differs from the
    double reference (not counting the excused ones) on the path, the most over the methods
    run; met at 0."""
    rows = []
    for task, n in (("rays/coherent", 786432), ("rays/incoherent", 1000000)):
        rs = [r for r in runs.values() if (r.task, r.path, r.n) == (task, path, n)]
        counted = [r for r in rs if "differ" in r.counters]
        worst = max(counted, key=lambda r: r.counters["differ"], default=None)
        value = worst.counters["differ"] if worst else None
        verdict = ("missed" if value else "run failed" if any(r.error for r in rs)
                   else "met" if value == 0 else "no data")
        measured = ("-" if value is None else f"{value:.0f} ({worst.method})" if value
                    else f"{value:.0f}")
        rows.append((f"{task} N={n:,}: watertight, rays differing from the double reference "
                     "beyond the excused ones (worst method)", measured, "0", verdict))
    return rows


def cpu_model(context):
    """The CPU model: from the JSON if recorded, else /proc/cpuinfo of the reporting machine."""
    if context.get("cpu_model"):
        return context["cpu_model"]
    try:
        with open("/proc/cpuinfo") as f:
            names = [l.split(":", 1)[1].strip() for l in f if l.startswith("model name")]
    except OSError:
        names = []
    return names[0] + " (read at report time)" if names else "unknown"


def markdown(runs, context, source, images, mdpath):
    """The Markdown report: header, machine, one section per workload with its plot (images:
    section title -> PNG path), targets."""
    busy = sum(1 for r in runs.values() if r.ms and r.ms > 1.3 * r.cpu_ms)
    load = ", ".join(f"{x:.2f}" for x in context.get("load_avg", []))
    c = lambda key: context.get(key, "unknown")  # noqa: E731
    out = [f"<!-- Generated by bench/report.py from {source}; do not edit by hand. -->",
           "# simdphys benchmarks", "",
           f"Generated by `bench/report.py` from `{source}`; do not edit by hand.", "",
           f"- Date: {c('date')}",
           f"- Machine: {cpu_model(context)}, host `{c('host_name')}`, {c('num_cpus')} CPUs at "
           f"{c('mhz_per_cpu')} MHz" + (f", load average {load} at the start" if load else ""),
           f"- Compiler: {c('compiler')}; simdphys built as Release (the Google Benchmark "
           f"library itself: {c('library_build_type')} build)",
           f"- SIMD paths available: {c('simdphys_paths').replace(',', ', ')}; active (default) "
           f"path: {c('simdphys_active_path')}. Each run forces one path.",
           f"- Timings are single-threaded wall-clock time per iteration (Google Benchmark "
           f"`real_time`, {context['_runs']}), with the CPU time beside it ('cpu ms'); ratios "
           "are the baseline's time over the row's time (higher = faster). 'vs ref': the same "
           "method on the scalar reference path; 'vs ref <method>': that method on the reference "
           "path; 'vs autovec': the auto-vectorised loop on the "
           "same path; 'vs peer': the fastest peer engine at the same N; '-': no baseline run."]
    if busy:
        out.append(f"- {busy} of {len(runs)} runs had a wall time more than 30% above their CPU "
                   "time, a sign that other work shared the cores during the run.")
    for title, tasks, image, sentence in sections(runs):
        out += ["", f"## {title}", "", sentence, "", section_table(image, runs, tasks, True)]
        if title in images:
            rel = os.path.relpath(images[title], os.path.dirname(os.path.abspath(mdpath)))
            out += ["", f"![{title}]({rel})"]
    note, rows = targets(runs, context)
    out += ["", "## Targets", "", note + " Ratios are times (or bytes/s for bandwidth) of the "
            "baseline over this path; a target is met when the ratio reaches the goal. Where "
            "two methods are named, the faster is taken and shown beside the ratio. The "
            "watertightness rows count rays instead, and are met at 0; the particle rows count "
            "particles, or time a step.", "",
            "| target | measured | goal | verdict |", "|---|--:|--:|---|"]
    out += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(out) + "\n"


def main():
    """Parses the arguments, prints the table, writes the Markdown and the plots."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", help="Google Benchmark JSON (--benchmark_out)")
    ap.add_argument("--md", help="write the Markdown report here")
    ap.add_argument("--img", help="write the PNG plots into this directory")
    ap.add_argument("--quiet", action="store_true", help="do not print the table")
    args = ap.parse_args()
    context, runs = load(args.results)
    if not runs:
        sys.exit(f"report.py: no task/method/path/n benchmarks in {args.results}")
    if not args.quiet:
        for title, tasks, image, _ in sections(runs):
            print(f"== {title}\n{section_table(image, runs, tasks, False)}\n")
    images = {}
    if args.img:
        os.makedirs(args.img, exist_ok=True)
        for title, tasks, image, _ in sections(runs):
            png = os.path.join(args.img, f"{image}.png")
            draw = CUSTOM[image][1] if image in CUSTOM else plot
            if image and draw(runs, tasks, title, png):
                images[title] = png
    if args.md:
        os.makedirs(os.path.dirname(os.path.abspath(args.md)), exist_ok=True)
        with open(args.md, "w") as f:
            f.write(markdown(runs, context, os.path.basename(args.results), images, args.md))


if __name__ == "__main__":
    main()
