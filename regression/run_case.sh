#!/usr/bin/env bash
# Runs one verification case and checks it against its expected results.
# usage: run_case.sh RAILFE COMPARE RANKS DECK EXPECTED OUTPUT_DIR [MPIEXEC ARGS...]
set -u
railfe=$1 compare=$2 ranks=$3 deck=$4 expected=$5 output=$6
shift 6
rm -rf "$output"
echo "== running $deck on $ranks rank(s)"
"$@" -np "$ranks" "$railfe" "$deck" --output "$output" --quiet
status=$?
if [[ $status -ne 0 ]]; then
  echo "railfe exited with status $status"
  exit 1
fi
echo "== checking against $expected"
"$compare" check "$expected" "$output"
