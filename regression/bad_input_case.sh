#!/usr/bin/env bash
# Runs a deck that must be refused and checks how: the exit status, the message (each line
# "<!-- expect: TEXT -->" of the deck must appear, the error once however many ranks run, warnings
# aside), and
# that nothing looking like complete results is left behind. A deck that does not exist (to test
# exactly that) takes its expectations from DECK with .xml replaced by .expect.
# usage: bad_input_case.sh RAILFE RANKS DECK OUTPUT_DIR [MPIEXEC ARGS...]
set -u
railfe=$1 ranks=$2 deck=$3 output=$4
shift 4
rm -rf "$output"
expectations=$deck
[[ -f "$deck" ]] || expectations=${deck%.xml}.expect
log=$(mktemp)
"$@" -np "$ranks" "$railfe" "$deck" --output "$output" --quiet >"$log" 2>&1
status=$?
cat "$log"
expected_status=$(sed -n 's/.*<!-- exit: \([0-9]*\) -->.*/\1/p' "$expectations" | head -n 1)
expected_status=${expected_status:-1}
failed=0
if [[ $status -ne $expected_status ]]; then
  echo "FAIL: exit status $status, expected $expected_status"
  failed=1
fi
while IFS= read -r text; do
  if ! grep -qF -- "$text" "$log"; then
    echo "FAIL: message lacks: $text"
    failed=1
  fi
done < <(sed -n 's/.*<!-- expect: \(.*\) -->.*/\1/p' "$expectations")
# Warnings before the error are allowed (e.g. a conditionally stable scheme announced).
count=$(grep '^railfe: ' "$log" | grep -vc '^railfe: warning: ')
if [[ $count -ne 1 ]]; then
  echo "FAIL: the error was printed $count times (once expected)"
  failed=1
fi
if [[ -d "$output" ]]; then
  complete=$(find "$output" -type f ! -name '*.part' ! -name 'FAILED.txt' ! -name '.railfe-outputs' | wc -l)
  if [[ $complete -ne 0 ]]; then
    echo "FAIL: complete-looking files were left in $output:"
    find "$output" -type f ! -name '*.part' ! -name 'FAILED.txt' ! -name '.railfe-outputs'
    failed=1
  fi
  if [[ $expected_status -eq 1 ]]; then
    echo "FAIL: bad input must not touch the results directory, but $output exists"
    failed=1
  fi
  if [[ $expected_status -eq 2 && ! -f "$output/FAILED.txt" ]]; then
    echo "FAIL: a failed run must leave FAILED.txt"
    failed=1
  fi
fi
rm -f "$log"
[[ $failed -eq 0 ]] && echo "refused as expected"
exit $failed
