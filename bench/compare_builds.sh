#!/usr/bin/env bash
# Before/after table for the issue notes: W1, W2 and W6 of two benchmark binaries, run
# interleaved (before, after, before, ...) so that load drifts hit both alike; medians of the
# real times. Usage: bench/compare_builds.sh BEFORE_BIN AFTER_BIN OUTDIR [repetitions, default 3]
set -euo pipefail
before=$1 after=$2 out=$3 reps=${4:-3}
filter='^(rays/(coherent|incoherent)/(bvh|packet16|auto)/avx512dl|aabb_query/bvh/avx512dl/1000000|aabb_pairs/grid/avx512dl/1000000|cull_(spheres|boxes)/planes/avx512dl)/'
mkdir -p "$out"
for r in $(seq 1 "$reps"); do
  for side in before after; do
    bin=$before; [ $side = after ] && bin=$after
    "$bin" --benchmark_filter="$filter" --benchmark_min_time=0.5 \
      --benchmark_out="$out/$side.$r.json" --benchmark_out_format=json >/dev/null 2>&1
  done
done
python3 - "$out" "$reps" <<'PY'
import json, sys, statistics, glob
out, reps = sys.argv[1], int(sys.argv[2])
def load(side):
    d = {}
    for r in range(1, reps + 1):
        for b in json.load(open(f"{out}/{side}.{r}.json"))["benchmarks"]:
            if b.get("run_type") == "aggregate": continue
            d.setdefault(b["name"], []).append(b["real_time"])
    return d
b, a = load("before"), load("after")
print("| benchmark | before (median) | after (median) | after/before | before spread |")
print("|---|--:|--:|--:|--:|")
for k in b:
    if k not in a: continue
    mb, ma = statistics.median(b[k]), statistics.median(a[k])
    sp = (max(b[k]) - min(b[k])) / mb
    print(f"| {k} | {mb:.4g} | {ma:.4g} | {ma/mb:.3f} | {sp:.1%} |")
PY
