#!/usr/bin/env bash
# Checkpoint and restart of an explicit run: runs DECK straight through, then again with
# checkpoints every 50 steps and an interruption after 137 steps (between checkpoints), then
# resumes it; the resumed results must equal the uninterrupted ones to the last bit (summary
# files aside: their wall times differ).
# usage: restart_case.sh RAILFE COMPARE RANKS DECK OUTPUT_DIR [MPIEXEC ARGS...]
set -u
railfe=$1 compare=$2 ranks=$3 deck=$4 output=$5
shift 5
rm -rf "$output"
mkdir -p "$output"
variant() {  # variant NAME CHECKPOINT_XML
  sed "s#<Parameter name=\"Module\" type=\"string\" value=\"explicit\"/>#&$2#" "$deck" \
    >"$output/$1.xml"
}
variant straight ""
variant interrupted '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="50"/><Parameter name="Stop after steps" type="int" value="137"/></ParameterList>'
variant resumed '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="50"/><Parameter name="Restart" type="bool" value="true"/></ParameterList>'
"$@" -np "$ranks" "$railfe" "$output/straight.xml" --output "$output/straight" --quiet ||
  { echo "FAIL: the straight run failed"; exit 1; }
"$@" -np "$ranks" "$railfe" "$output/interrupted.xml" --output "$output/resumed" --quiet \
  >"$output/interrupted.log" 2>&1
if ! grep -q "stopped after 137 steps" "$output/interrupted.log"; then
  cat "$output/interrupted.log"
  echo "FAIL: the interrupted run did not stop after 137 steps"
  exit 1
fi
"$@" -np "$ranks" "$railfe" "$output/resumed.xml" --output "$output/resumed" --quiet ||
  { echo "FAIL: the resumed run failed"; exit 1; }
grep -q "resumed from checkpoint at step *100" "$output/resumed/summary.txt" ||
  { echo "FAIL: the resumed run did not start from the checkpoint at step 100"; exit 1; }
# Compare everything but the summaries, which hold wall times.
for dir in straight resumed; do
  mkdir -p "$output/$dir-results"
  find "$output/$dir" -maxdepth 1 -type f \( -name '*.csv' -o -name '*.exo' \) \
    -exec cp {} "$output/$dir-results/" \;
done
# The resumed Exodus file starts at the restart: compare the CSV results only.
rm -f "$output"/*-results/*.exo
"$compare" diff "$output/straight-results" "$output/resumed-results" --relative 0 --floor 0
