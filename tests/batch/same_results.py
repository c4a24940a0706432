"""Compares two batch reports (simdphys batch --json, simdphys-batch-mpi --json): every job's state
hash and measures must be the same, whichever runner ran it."""
import json
import sys

a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert len(a) == len(b) > 0, f"{len(a)} and {len(b)} jobs"
for x, y in zip(a, b):
    for key in x:
        if key != "seconds":
            assert x[key] == y[key], f"job {x['job']}: {key} is {x[key]} and {y[key]}"
print(f"{len(a)} jobs, the same results from both runners")
