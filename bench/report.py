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
}
# Report sections: title, tasks, image name (or None), what is compared.
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
     "with it); autovec is the grid sweep with its inner loop left to the compiler. Peers: "
     "Bullet's btDbvtBroadphase, deferred (bullet_dbvt) and immediate "
     "(bullet_dbvt_immediate), timed from proxy creation to the complete pair cache."),
    ("W6 cull: frustum culling", ["cull_spheres", "cull_boxes"], "cull",
     "1,000,000 spheres (16 bytes each) or AABBs (24 bytes each) tested against six planes; "
     "'double-ref diff' is the number of objects whose visibility differs from a "
     "double-precision cull."),
    ("Batch raycasts: one ray against a stream", ["ray_boxes", "ray_spheres", "ray_triangles"],
     "rays",
     "256 rays (seed 3) each find their closest hit among 100,000 W1 boxes, 100,000 spheres "
     "(seed 7) or the 32,768 triangles of a 129 x 129 W2 heightfield, testing every element; "
     "throughput is element tests per second. 'error' is the largest |t - t_double| / "
     "max(1, t_double) against the same query in double; 'differing' counts rays whose hit or "
     "element differs from it. 'autovec' is the same test as a plain loop (boxes and spheres; none "
     "yet for triangles)."),
    ("Bandwidth: streaming read", ["bandwidth"], "bandwidth",
     "A plain reduction over a buffer at the W6 working-set sizes and at 512 MiB (main "
     "memory): the ceiling the memory-bound kernels are read against."),
]
AVX512 = ("avx512dl", "avx512")
# rate: throughput in the task's unit (bytes/s for bandwidth); bps: bytes/s where reported.
Run = namedtuple("Run", "task method path n ms real_ms rate bps counters error")


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
        context["_runs"] = f"median of {entries[0].get('repetitions', '?')} repetitions"
    else:
        entries = [e for e in entries if e.get("run_type", "iteration") == "iteration"]
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    runs = {}
    for e in entries:
        parts = e.get("run_name", e["name"]).split("/")
        if len(parts) != 4:
            continue
        task, method, p, n = parts
        unit = scale[e.get("time_unit", "ns")]
        ms = e.get("cpu_time", 0) * unit
        failed = bool(e.get("error_occurred"))
        runs[(task, method, p, int(n))] = Run(
            task, method, p, int(n), ms if ms > 0 and not failed else None,
            e.get("real_time", 0) * unit,
            e.get("bytes_per_second" if unit_of(task) == "B/s" else "items_per_second"),
            e.get("bytes_per_second"), e, e.get("error_message", "failed") if failed else None)
    return context, runs


def sections(runs):
    """The report's sections that have runs, plus one for tasks this script does not know."""
    known = {t for _, ts, _, _ in SECTIONS for t in ts}
    other = sorted({r.task for r in runs.values()} - known)
    return [s for s in SECTIONS + [("Other", other, None, "Tasks not described here.")]
            if any(r.task in s[1] for r in runs.values())]


def baselines(runs, r):
    """The ratios of one run (baseline time / this time): vs the same method on the reference
    path, vs the task's base method on it, vs autovec on the same path, vs the fastest peer."""
    base = TASKS.get(r.task, ("", None))[1]
    peers = [p.ms for p in runs.values()
             if p.task == r.task and p.n == r.n and p.path == "peer" and p.ms]
    keys = {"ref": (r.task, r.method, "reference", r.n), "base": (r.task, base, "reference", r.n),
            "autovec": (r.task, "autovec", r.path, r.n)}
    out = {k: runs[key].ms / r.ms if key in runs and runs[key].ms and r.ms else None
           for k, key in keys.items()}
    out["peer"] = min(peers) / r.ms if peers and r.ms else None
    return out


def unit_of(task):
    """The throughput unit of a task ('B/s' for bandwidth)."""
    return TASKS.get(task, ("items/s", None))[0]


def prefix(value, unit):
    """Engineering scale and unit label: (1.31e9, 'objects/s') -> (1e9, 'G objects/s')."""
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


def check(r):
    """The correctness column: exact/checksum, the double-reference difference, or the error."""
    c = r.counters
    if r.error:
        return "FAILED: " + r.error
    notes = []
    if "exact" in c:
        notes.append("exact" if c["exact"] == 1 else f"result {c.get('result', 0):.0f} inexact")
    if "checksum_ok" in c:
        notes.append("checksum OK" if c["checksum_ok"] == 1 else "checksum WRONG")
    if r.task.startswith("cull") and "error" in c:
        notes.append(f"double-ref diff: {c['error']:.0f}")
    if r.task.startswith("ray_") and "error" in c:
        notes.append(f"{c.get('result', 0):.0f} hits, t error {c['error']:.2g} vs double, "
                     f"{c.get('differing', 0):.0f} rays differ")
    if "nodes" in c:
        notes.append(f"{c['nodes']:.0f} nodes, depth {c.get('depth', 0):.0f}")
    return ", ".join(notes)


def order(runs, tasks):
    """Runs of the given tasks: by task, n, method, then path in the machine's order."""
    paths = ["avx512dl", "avx512", "avx2", "sse4", "hwy_scalar", "scalar", "reference", "peer"]
    rank = lambda p: paths.index(p) if p in paths else len(paths)  # noqa: E731
    methods = {}
    for r in runs.values():
        methods.setdefault((r.task, r.method), len(methods))
    return sorted((r for r in runs.values() if r.task in tasks),
                  key=lambda r: (tasks.index(r.task), r.n, methods[(r.task, r.method)],
                                 rank(r.path)))


def table(runs, tasks, markdown):
    """One table for the given tasks, as Markdown or as aligned text; the baseline columns
    that are '-' on every row are left out."""
    rows = order(runs, tasks)
    bases = {TASKS[t][1] for t in tasks if t in TASKS and TASKS[t][1]}
    cols = [("ref", "vs ref"), ("base", "vs ref " + "/".join(sorted(bases))),
            ("autovec", "vs autovec"), ("peer", "vs peer")]
    ratios = [baselines(runs, r) for r in rows]
    cols = [(k, h) for k, h in cols if any(x[k] is not None for x in ratios)]
    head = ["task", "method", "path", "N", "ms/iter", "throughput"] + [h for _, h in cols]
    body = [[r.task, r.method, r.path, size(r), fixed(r.ms), eng(r.rate, unit_of(r.task))
             + (f" ({eng(r.bps, 'B/s')})" if r.bps and unit_of(r.task) != "B/s" else "")]
            + [times(x[k]) for k, _ in cols] + [check(r)] for r, x in zip(rows, ratios)]
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
             for t in tasks}
    groups = {}
    for r in done:
        groups.setdefault((r.task, r.n if per_n[r.task] else None), []).append(r)
    if not groups:
        return False
    heights = [1.0 + 0.27 * len(g) for g in groups.values()]
    fig, axes = plt.subplots(len(groups), 1, figsize=(10, sum(heights) + 0.5), squeeze=False,
                             gridspec_kw={"height_ratios": heights})
    colours = {"simdphys": "#1f77b4", "auto-vectorised loop": "#ff7f0e",
               "scalar reference": "#7f7f7f", "peer (Bullet)": "#d62728"}
    kind = lambda r: ("peer (Bullet)" if r.path == "peer" else "scalar reference"  # noqa: E731
                      if r.path == "reference" else "auto-vectorised loop"
                      if r.method == "autovec" else "simdphys")
    for ax, ((task, n), rs) in zip(axes[:, 0], groups.items()):
        factor, label = prefix(max(r.rate for r in rs), unit_of(task))
        values = [r.rate / factor for r in rs]
        ax.barh(range(len(rs)), values, color=[colours[kind(r)] for r in rs])
        ax.set_yticks(range(len(rs)), [f"{r.method} / {r.path}" + ("" if n else f" / {size(r)}")
                                       for r in rs], fontsize=9)
        ax.invert_yaxis()
        log = max(values) / min(values) > 30
        if log:
            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        for i, v in enumerate(values):
            ax.text(v, i, f" {v:.3g}", va="center", fontsize=8)
        ax.set_xlim(right=max(values) * (3 if log else 1.12))
        ax.set_title(task + (f", N = {size(rs[0])}" if n else ""), fontsize=10)
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
    """The issue's targets on the best AVX-512 path present: (note, rows of target, measured,
    goal, verdict). '*' in a key stands for that path."""
    present = [p for p in context.get("simdphys_paths", "").split(",") + list(AVX512)
               if p != "reference" and any(r.path == p for r in runs.values())]
    path = next((p for p in AVX512 if p in present), present[0] if present else "-")
    note = (f"Evaluated on path `{path}`." if path in AVX512 else
            f"No AVX-512 path in the results: evaluated on the best path present, `{path}`.")
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
                  (f"{task} bytes/s vs streaming read at {size_mib} MiB", this,
                   ("bandwidth", "read", "scalar", size_mib * mib), 0.5),
                  (f"{task} bytes/s vs streaming read at 512 MiB (information)", this,
                   ("bandwidth", "read", "scalar", 512 * mib), None)]
    rows = []
    for what, key, base_key, goal in specs:
        a = runs.get(tuple(path if k == "*" else k for k in key))
        b = runs.get(base_key)
        value = None
        if a and b and a.ms and b.ms:  # bandwidth: bytes/s over bytes/s, else time over time
            value = (a.bps or 0) / b.bps if base_key[0] == "bandwidth" else b.ms / a.ms
        verdict = ("-" if goal is None else "met" if value and value >= goal else "missed"
                   if value else "run failed" if (a and a.error) or (b and b.error) else "no data")
        rows.append((what, times(value), "-" if goal is None else f">= {goal:g}x", verdict))
    return note, rows


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
    busy = sum(1 for r in runs.values() if r.ms and r.real_ms > 1.3 * r.ms)
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
           f"- Timings are single-threaded CPU time per iteration (Google Benchmark `cpu_time`, "
           f"{context['_runs']}); ratios are the baseline's time over the row's time (higher = "
           "faster). 'vs ref': the same method on the scalar reference path; 'vs ref <method>': "
           "that method on the reference path; 'vs autovec': the auto-vectorised loop on the "
           "same path; 'vs peer': the fastest peer engine at the same N; '-': no baseline run."]
    if busy:
        out.append(f"- {busy} of {len(runs)} runs had a wall time more than 30% above their CPU "
                   "time, a sign that other work shared the cores during the run.")
    for title, tasks, _, sentence in sections(runs):
        out += ["", f"## {title}", "", sentence, "", table(runs, tasks, True)]
        if title in images:
            rel = os.path.relpath(images[title], os.path.dirname(os.path.abspath(mdpath)))
            out += ["", f"![{title}]({rel})"]
    note, rows = targets(runs, context)
    out += ["", "## Targets", "", note + " Ratios are times (or bytes/s for bandwidth) of the "
            "baseline over this path; a target is met when the ratio reaches the goal.", "",
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
        for title, tasks, _, _ in sections(runs):
            print(f"== {title}\n{table(runs, tasks, False)}\n")
    images = {}
    if args.img:
        os.makedirs(args.img, exist_ok=True)
        for title, tasks, image, _ in sections(runs):
            png = os.path.join(args.img, f"{image}.png")
            if image and plot(runs, tasks, title, png):
                images[title] = png
    if args.md:
        os.makedirs(os.path.dirname(os.path.abspath(args.md)), exist_ok=True)
        with open(args.md, "w") as f:
            f.write(markdown(runs, context, os.path.basename(args.results), images, args.md))


if __name__ == "__main__":
    main()
