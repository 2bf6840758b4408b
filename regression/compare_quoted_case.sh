#!/usr/bin/env bash
# railfe-compare reads a quoted text cell (a label holding a comma, as railfe writes it) as one
# cell: two equal tables agree, and a number changed after the quoted label is found in its own
# column.
# usage: compare_quoted_case.sh COMPARE OUTPUT_DIR
set -u
compare=$1 output=$2
rm -rf "$output"
mkdir -p "$output/a" "$output/b" "$output/c"
printf 'reference,reference_hz,computed_hz\n"umbrella (0,0)",183,199.5\n"the ""(0,3)"" mode",1075,986.25\n' |
  tee "$output/a/t.csv" >"$output/b/t.csv"
sed 's/986.25/990.5/' "$output/a/t.csv" >"$output/c/t.csv"
"$compare" diff "$output/a" "$output/b" --relative 0 --floor 0 ||
  { echo "FAIL: equal tables with quoted labels do not agree"; exit 1; }
if "$compare" diff "$output/a" "$output/c" --relative 0 --floor 0 >"$output/changed.log" 2>&1; then
  cat "$output/changed.log"
  echo "FAIL: a changed number after a quoted label was not found"
  exit 1
fi
cat "$output/changed.log"
grep -q "computed_hz" "$output/changed.log" ||
  { echo "FAIL: the change is not reported in its column computed_hz"; exit 1; }
echo "quoted cells read as one"
