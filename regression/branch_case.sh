#!/usr/bin/env bash
# A checkpoint resumed by another deck: DECK's explicit step, interrupted after 137 steps
# (checkpoints every 50), is resumed twice from the same checkpoint: by DECK itself, and by a
# "branched" deck without the statics step it starts from (what a study does to run variants of
# a long run from one state). Both must give the same results to the last bit: the checkpoint
# carries everything the stepping depends on, the stable step's calibration included, though the
# branched deck starts from the undeformed state instead of the statics step's.
# usage: branch_case.sh RAILFE COMPARE PYTHON RANKS DECK OUTPUT_DIR [MPIEXEC ARGS...]
set -u
railfe=$1 compare=$2 python=$3 ranks=$4 deck=$5 output=$6
shift 6
rm -rf "$output"
mkdir -p "$output"
source "$(dirname "$0")/checkpoint_variants.sh"
write_checkpoint_variants
# The branched deck: the resumed one without the statics step and without "Start from".
"$python" - "$output/resumed.xml" "$output/branched.xml" <<'PY' || { echo "FAIL: no branched deck"; exit 1; }
import sys
import xml.etree.ElementTree as ET
tree = ET.parse(sys.argv[1])
steps = tree.getroot().find("ParameterList[@name='Steps']")
starts = [p for p in steps.iter("Parameter") if p.get("name") == "Start from"]
assert starts, "the deck's explicit step starts from no statics step"
for start in starts:
    name = start.get("value")
    for step in steps.findall("ParameterList"):
        if step.get("name") == name:
            steps.remove(step)
        elif start in list(step):
            step.remove(start)
tree.write(sys.argv[2])
PY
run_interrupted "$@"
rm -f "$output/resumed/FAILED.txt"
cp -r "$output/resumed" "$output/branched"
for run in resumed branched; do
  "$@" -np "$ranks" "$railfe" "$output/$run.xml" --output "$output/$run" --quiet ||
    { echo "FAIL: the $run run failed"; exit 1; }
  grep -q "resumed from checkpoint at step *$resume_step$" "$output/$run/summary.txt" ||
    { echo "FAIL: the $run run did not start from the checkpoint at step $resume_step"; exit 1; }
done
same_diagnostics "$output/resumed/summary.txt" "$output/branched/summary.txt"
# The branched run's results directory holds its explicit step's files only: compare those.
mkdir -p "$output/resumed-results" "$output/branched-results"
for file in "$output"/branched/*.csv; do
  cp "$file" "$output/branched-results/"
  cp "$output/resumed/$(basename "$file")" "$output/resumed-results/" ||
    { echo "FAIL: the resumed run lacks $(basename "$file")"; exit 1; }
done
"$compare" diff "$output/resumed-results" "$output/branched-results" --relative 0 --floor 0
