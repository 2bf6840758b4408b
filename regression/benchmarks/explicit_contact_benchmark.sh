#!/usr/bin/env bash
# The cost of explicit penalty contact (issue 15, "Benchmark"): a wheel box pressed on a rail box,
# the slave face 10 % of the nodes, at 3 sizes (about 1e4, 3e4 and 1e5 slave nodes), each run
# with and without the contact pair back to back, 3 times; medians
# (regression/benchmarks/explicit_contact_benchmark.py, docs/data/explicit_contact_benchmark.csv);
# then the wheel of Mesh Type wheel on a rail box at 3 element sizes (..._wheel.csv).
# Then the allocation check: the smallest model run for about 50 and 150 steps under
# malloc_count.so (LD_PRELOAD; counts malloc, calloc, realloc and aligned allocations); the
# difference of the counts over the difference of the steps is the allocations per step.
#   bash regression/benchmarks/explicit_contact_benchmark.sh [BUILD_DIR] [--sizes ...] [--steps ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
shift || true
railfe=$build/bin/railfe
work=${TMPDIR:-/tmp}/explicit_contact_benchmark
mkdir -p "$work"
nice /usr/bin/python3 "$root/regression/benchmarks/explicit_contact_benchmark.py" --railfe "$railfe" \
  --work "$work" "$@"
# The realistic case: a wheel (Mesh Type wheel) whose tread is mostly far from the rail.
nice /usr/bin/python3 "$root/regression/benchmarks/explicit_contact_benchmark.py" --railfe "$railfe" \
  --work "$work" --wheel 0.02 0.012 0.008 --steps 100 60 30 \
  --csv "$root/docs/data/explicit_contact_benchmark_wheel.csv"

cc -O2 -shared -fPIC -o "$work/malloc_count.so" "$root/regression/benchmarks/malloc_count.c"
/usr/bin/python3 - "$root" "$work" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/regression/benchmarks")
import explicit_contact_benchmark as b
for steps in (50, 150):
    for contact in (True, False):
        with open(f"{sys.argv[2]}/alloc_{steps}_{'contact' if contact else 'none'}.xml", "w") as out:
            out.write(b.deck(100, steps, contact))
PY
echo "| model | steps | malloc calls (railfe) |"
echo "|---|---|---|"
for kind in contact none; do
  for steps in 50 150; do
    deck=$work/alloc_${steps}_$kind.xml
    calls=$(LD_PRELOAD=$work/malloc_count.so "$railfe" "$deck" --output "${deck%.xml}" --quiet 2>&1 |
            sed -n 's/^malloc_count: railfe: \([0-9]*\) calls.*/\1/p')
    taken=$(sed -n 's/^ *steps  *\([0-9]*\)$/\1/p' "${deck%.xml}/summary.txt")
    echo "| $kind | $taken | $calls |"
  done
done
