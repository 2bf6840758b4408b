#!/usr/bin/env bash
# Checkpoint and restart of an explicit run: runs DECK straight through, then again with
# checkpoints every 50 steps (RESTART_INTERVAL steps when set) and an interruption 37 steps after
# the second (between checkpoints), then resumes it; the resumed results must equal the uninterrupted ones to the last bit (summary
# files aside: their wall times differ; their contact diagnostics must agree).
# usage: restart_case.sh RAILFE COMPARE RANKS DECK OUTPUT_DIR [MPIEXEC ARGS...]
set -u
railfe=$1 compare=$2 ranks=$3 deck=$4 output=$5
shift 5
rm -rf "$output"
mkdir -p "$output"
source "$(dirname "$0")/checkpoint_variants.sh"
variant straight ""
write_checkpoint_variants
"$@" -np "$ranks" "$railfe" "$output/straight.xml" --output "$output/straight" --quiet ||
  { echo "FAIL: the straight run failed"; exit 1; }
run_interrupted "$@"
"$@" -np "$ranks" "$railfe" "$output/resumed.xml" --output "$output/resumed" --quiet ||
  { echo "FAIL: the resumed run failed"; exit 1; }
grep -q "resumed from checkpoint at step *$resume_step$" "$output/resumed/summary.txt" ||
  { echo "FAIL: the resumed run did not start from the checkpoint at step $resume_step"; exit 1; }
same_diagnostics "$output/straight/summary.txt" "$output/resumed/summary.txt"
# Compare everything but the summaries, which hold wall times.
for dir in straight resumed; do
  mkdir -p "$output/$dir-results"
  find "$output/$dir" -maxdepth 1 -type f \( -name '*.csv' -o -name '*.exo' \) \
    -exec cp {} "$output/$dir-results/" \;
done
# The resumed Exodus file starts at the restart: compare the CSV results only.
rm -f "$output"/*-results/*.exo
"$compare" diff "$output/straight-results" "$output/resumed-results" --relative 0 --floor 0
