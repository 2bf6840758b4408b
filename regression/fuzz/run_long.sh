#!/usr/bin/env bash
# The long fuzz check: COUNT mutated decks (default 10000) from SEED (default 1), on JOBS
# parallel runs. Each deck of a seed is reproducible: rerun one with
#   python3 regression/fuzz/fuzz_decks.py --railfe RAILFE --seed SEED --only INDEX
# usage: regression/fuzz/run_long.sh RAILFE [SEED] [COUNT] [JOBS] [WORK_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
railfe=${1:?usage: run_long.sh RAILFE [SEED] [COUNT] [JOBS] [WORK_DIR]}
seed=${2:-1} count=${3:-10000} jobs=${4:-2}
work=${5:-fuzz_long_seed${seed}}
exec python3 "$here/fuzz_decks.py" --railfe "$railfe" --seed "$seed" --count "$count" \
  --jobs "$jobs" --work "$work"
