#!/usr/bin/env bash
# Runs a deck that must complete (exit 0) with a warning: each line "<!-- warn: TEXT -->" of the
# deck must appear in what railfe prints, and in the step's summary.txt.
# usage: warning_case.sh RAILFE DECK OUTPUT_DIR
set -u
railfe=$1 deck=$2 output=$3
rm -rf "$output"
log=$(mktemp)
"$railfe" "$deck" --output "$output" >"$log" 2>&1
status=$?
cat "$log"
failed=0
if [[ $status -ne 0 ]]; then
  echo "FAIL: exit status $status, expected 0"
  failed=1
fi
while IFS= read -r text; do
  if ! grep -qF -- "$text" "$log"; then
    echo "FAIL: the terminal output lacks: $text"
    failed=1
  fi
  if ! grep -qF -- "$text" "$output/summary.txt"; then
    echo "FAIL: summary.txt lacks: $text"
    failed=1
  fi
done < <(sed -n 's/.*<!-- warn: \(.*\) -->.*/\1/p' "$deck")
rm -f "$log"
exit $failed
