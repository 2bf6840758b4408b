#!/bin/bash
# Strong scaling of railfe's explicit squeal scene on the device machine (16 cores, none of the
# Debian libraries): run from the repository root with $OUT set:
#     OUT=/some/dir bash .devbundle/device_run.sh
# (kept in regression/benchmarks/device/, copied to .devbundle/ by make_bundle.sh there; it must
# run from the .devbundle copy: it finds setup.sh and the decks next to itself)
# Ends within RF_BUDGET_S (default 530) s of wall time; every run is under `timeout`, each one's
# limit clipped to what is left. Estimates below: 0.147 us per element-step measured on one core
# of an AMD EPYC (Zen 4, AVX-512), parallel efficiency guessed 0.9 / 0.8 / 0.6 at 4 / 8 / 16 ranks.
#   (0) bench_mid4mm_case1.xml cut to 0.05 ms (982 steps) on 1 rank: serial baseline   ~20 s
#   (a) bench_mid4mm_case1.xml: full-scale geometry, every refined size 4 mm, 106,940 hex8,
#       dt 5.09e-8 s, 1.5 ms = 29,470 steps, explicit only (no modes step, no preload):
#       16 ranks ~55 s, 8 ranks ~80 s, 4 ranks ~135 s
#   (b) bench_full_case1.xml: squeal_case1.xml as shipped (1 mm), 424,592 hex8, dt 2.13e-8 s,
#       0.3 ms = 14,085 steps, explicit only: 16 ranks ~110 s (~155 s at efficiency 0.4)
#       RF_FULL_TRUE=1: true_full_case1.xml instead, which keeps the statics preload (CHOLMOD
#       on rank 0, estimated well over 5 min at 1.55 M DOFs): expect its 300 s timeout to end it.
# railfe prints "[roll: time] N% done, T s elapsed" every 5 s, so a run cut by its timeout still
# gives its rate. Results under $OUT (3 files): device_run.log (this script's output),
# timings.csv (one row per run) and results.tar.gz (each run's stdout, summary.txt/json, CSVs).
set -u
T0=$(date +%s)
BUDGET=${RF_BUDGET_S:-530}
DEADLINE=$((T0 + BUDGET))
: "${OUT:?set OUT to the folder whose files come back}"
mkdir -p "$OUT"
exec > >(tee -a "$OUT/device_run.log") 2>&1
ts() { echo "[$(date -u +%H:%M:%S) +$(( $(date +%s) - T0 ))s] $*"; }
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$REPO"
RES=/tmp/rfresults
rm -rf "$RES" /tmp/rfrun && mkdir -p "$RES" /tmp/rfrun

ts "device_run.sh in $REPO, budget ${BUDGET}s"
echo "nproc: $(nproc)"
lscpu | head -20
lscpu | grep -iE '^(L2|L3|NUMA node\(s\))' || true
echo "cgroup cpu.max: $(cat /sys/fs/cgroup/cpu.max 2>/dev/null || echo n/a)"
free -g
df -h /tmp /dev/shm 2>/dev/null
uname -a

ts "setup.sh"
. "$REPO/.devbundle/setup.sh"
ts "setup done: RF_HOME=$RF_HOME"
set -- ${RF_NPS:-16 8 4}   # rank counts (a test elsewhere: RF_NPS="2 2 1")
ts "preflight: $1 ranks, --version"
timeout -k 5 60 rfmpirun "$1" --version > "$RES/preflight.log" 2>&1
echo "preflight rc=$?"; tail -5 "$RES/preflight.log"

echo "label,ranks,deck,rc,timeout_s,wall_s,elements,steps,stepping_s,us_per_element_step_wall_x_ranks,contact_s,setup_s,step_roll_s,total_s,last_progress" > "$OUT/timings.csv"

pack() { tar -C "$RES" -czf "$OUT/results.tar.gz" . 2>/dev/null; }

# run LABEL NP DECK CAP_S
run() {
  local label=$1 np=$2 deck=$3 cap=$4
  local left=$((DEADLINE - $(date +%s) - 12))
  local t=$cap; [ "$left" -lt "$t" ] && t=$left
  if [ "$t" -lt 25 ]; then ts "SKIP $label: ${left}s left"; echo "$label,$np,$deck,skipped,,,,,,,,,,," >> "$OUT/timings.csv"; return; fi
  local d=/tmp/rfrun/$label
  rm -rf "$d"; mkdir -p "$RES/$label"
  ts "START $label: $np ranks, $deck, timeout ${t}s"
  local s=$(date +%s.%N)
  timeout -k 10 "$t" rfmpirun "$np" "$deck" --output "$d" > "$RES/$label/stdout.txt" 2>&1
  local rc=$?
  local e=$(date +%s.%N)
  local wall=$(awk -v a="$s" -v b="$e" 'BEGIN{printf "%.1f", b-a}')
  ts "END $label rc=$rc wall=${wall}s"
  grep -E '^\[' "$RES/$label/stdout.txt" | tail -3
  [ "$rc" = 0 ] || grep -vE '^\[' "$RES/$label/stdout.txt" | head -15
  for f in summary.txt summary.json roll_energy.csv roll_contact_wheel-rail.csv roll_histories.csv preload_contact_wheel-rail.csv; do
    [ -f "$d/$f" ] && cp "$d/$f" "$RES/$label/"
  done
  if [ -f "$d/summary.txt" ]; then
    sed -n '/^Wall time/,/^Step /p' "$d/summary.txt" | head -12
    grep -E 'partitioner|elements  |steps  |time: stepping|per element-step|time: contact|peak memory per rank|stable step at start' "$d/summary.txt"
  fi
  python3 - "$label" "$np" "$deck" "$rc" "$t" "$wall" "$d/summary.json" "$RES/$label/stdout.txt" >> "$OUT/timings.csv" <<'PY'
import json, sys, os
label, np_, deck, rc, t, wall, sj, log = sys.argv[1:9]
row = [label, np_, os.path.basename(deck), rc, t, wall]
try:
    s = json.load(open(sj)); r = s.get("Step roll (explicit)", {}); w = s.get("Wall time", {})
    row += [r.get("elements", ""), r.get("steps", ""), r.get("time: stepping [s]", ""),
            r.get("time per element-step (wall x ranks) [us]", ""),
            r.get("time: contact (exchange, search, forces) [s]", ""), r.get("time: setup [s]", ""),
            w.get("step roll [s]", ""), w.get("total [s]", "")]
except Exception:
    row += [""] * 8
last = ""
try:
    lines = [l.strip() for l in open(log, errors="replace") if l.startswith("[")]
    last = lines[-1] if lines else ""
except Exception:
    pass
row.append('"' + last.replace('"', "'") + '"')
print(",".join(str(x) for x in row))
PY
  rm -rf "$d"
  pack
}

B=.devbundle
MID=${RF_MID_DECK:-$B/bench_mid4mm_case1.xml}
FULL=${RF_FULL_DECK:-$B/bench_full_case1.xml}; FULL_CAP=240
if [ "${RF_FULL_TRUE:-0}" = 1 ]; then FULL=$B/true_full_case1.xml; FULL_CAP=300; fi
# the serial baseline: the mid deck cut to 0.05 ms
sed 's/<Parameter name="End time" type="double" value="[^"]*"/<Parameter name="End time" type="double" value="5e-5"/; s/<Parameter name="Patch times" type="Array(double)" value="[^"]*"/<Parameter name="Patch times" type="Array(double)" value="{5e-5}"/' "$MID" > /tmp/rfrun/mid4mm_short.xml

run mid4mm_short_np1 1 /tmp/rfrun/mid4mm_short.xml 60
run mid4mm_np$1 "$1" "$MID" 150
run full1mm_np$1 "$1" "$FULL" "$FULL_CAP"
run mid4mm_np$2 "$2" "$MID" 170
run mid4mm_np$3 "$3" "$MID" 230

ts "timings:"
cat "$OUT/timings.csv"
pack
ls -la "$OUT"
ts "done"
sleep 1
