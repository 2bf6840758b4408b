#!/usr/bin/env bash
# A results directory that cannot be written is bad input (exit 1, a message naming --output),
# found before anything runs: here a plain file given as --output, and a directory below a file.
# usage: output_directory_case.sh RAILFE DECK SCRATCH
set -u
railfe=$1 deck=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
echo "not a directory" >"$scratch/file"
failed=0
for target in "$scratch/file" "$scratch/file/results"; do
  log=$("$railfe" "$deck" --output "$target" --quiet 2>&1)
  status=$?
  echo "$log"
  if [[ $status -ne 1 ]]; then
    echo "FAIL: --output $target: exit status $status, expected 1"
    failed=1
  fi
  if ! grep -qF -- "command line: '--output': the results directory cannot be written" <<<"$log"; then
    echo "FAIL: --output $target: the message does not name --output"
    failed=1
  fi
done
if [[ "$(cat "$scratch/file")" != "not a directory" ]]; then
  echo "FAIL: the file given as --output was changed"
  failed=1
fi
exit $failed
