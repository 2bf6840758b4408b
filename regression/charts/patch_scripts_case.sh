#!/usr/bin/env bash
# Smoke test of the patch scripts on the committed sample patches (regression/charts/samples):
# the centre-line chart of two instants, and the exact solver's patch beside the second, whose
# summed forces and found creepages must come back in the Table-3 row.
# usage: patch_scripts_case.sh RAILFE PYTHON OUTPUT_DIR
set -eu
railfe=$1 python=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
samples=$here/samples
rm -rf "$out" && mkdir -p "$out"
"$python" "$here/patch_centre_line.py" --mu 0.45 --png "$out/centre_line.png" \
  --csv "$out/centre_line.csv" "$samples/squeal_probe_lateral_patch_4.csv" \
  "$samples/squeal_probe_lateral_patch_8.csv"
# Falling friction: each node's own bound mu(v) p from its slip speed (case 5's law).
"$python" "$here/patch_centre_line.py" --falling 0.5 0.32 6 --png "$out/centre_line_falling.png" \
  --csv "$out/centre_line_falling.csv" "$samples/squeal_probe_lateral_patch_8.csv"
# Two friction laws at once, or a falling law that rises with speed, are refused by name.
for bad in "--mu 0.45 --falling 0.5 0.32 6" "--falling 0.3 0.32 6"; do
  # shellcheck disable=SC2086
  if "$python" "$here/patch_centre_line.py" $bad --png "$out/bad.png" \
      "$samples/squeal_probe_lateral_patch_8.csv" 2> "$out/bad.txt"; then
    echo "patch_centre_line.py accepted $bad"; exit 1
  fi
  grep -q -- "--falling" "$out/bad.txt" || { cat "$out/bad.txt"; exit 1; }
done
"$python" "$here/patch_vs_exact.py" --railfe "$railfe" --mu 0.45 --table "$out/table3.csv" \
  --png "$out/patch_vs_exact.png" --work "$out/work" "$samples/squeal_probe_lateral_patch_8.csv"
# The same patch on the profiles' separation (no ellipse): the creepages found must carry the
# forces (checked inside patch_vs_exact.py), the row must say so and the patch be the profiles'.
"$python" "$here/patch_vs_exact.py" --railfe "$railfe" --mu 0.45 --table "$out/table3.csv" \
  --geometry separation --A 1.086 --spin 0.1 \
  --separation "$here/../../docs/data/squeal_separation_s1002_54e1.csv" \
  --png "$out/patch_vs_exact_profiles.png" --work "$out/work_profiles" \
  "$samples/squeal_probe_lateral_patch_8.csv"
test -s "$out/centre_line.png" && test -s "$out/patch_vs_exact.png" \
  && test -s "$out/patch_vs_exact_profiles.png"
# Three nodes on the centre line at each instant; FN, Fx, Fy summed from pressure, shear and
# area (the run's own history reads 104.75 kN, -1.56 kN, -4.85 kN 1.3 us later); the creepages
# found carry them (checked inside patch_vs_exact.py); values from the scripts' first run.
"$python" - "$out" "$samples" <<'PY'
import csv, math, sys
out, samples = sys.argv[1:3]
line = list(csv.DictReader(open(f"{out}/centre_line.csv")))
assert len(line) == 6, f"{len(line)} centre-line rows, expected 6"
# Falling friction: each centre-line node's bound is mu(|v|) p of its own row in the sample.
nodes = {round(1e3 * float(r["s1_m"]), 6): r
         for r in csv.DictReader(open(f"{samples}/squeal_probe_lateral_patch_8.csv"))}
falling = list(csv.DictReader(open(f"{out}/centre_line_falling.csv")))
assert len(falling) == 3, f"{len(falling)} falling centre-line rows, expected 3"
for r in falling:
    node = nodes[round(float(r["s1_mm"]), 6)]
    v = math.hypot(float(node["slip_velocity_1_m/s"]), float(node["slip_velocity_2_m/s"]))
    bound = (0.32 + 0.18 * math.exp(-6 * v)) * float(node["pressure_Pa"]) / 1e6
    assert math.isclose(float(r["mu_p_MPa"]), bound, rel_tol=1e-12), (r, bound)
rows = list(csv.DictReader(open(f"{out}/table3.csv")))
row, profiles = rows[0], rows[1]
# The profiles' patch is wider across than the probe's ellipse (the conformal S1002 on 54E1).
assert profiles["geometry"] == "separation", profiles["geometry"]
assert float(profiles["b_m"]) > 1.2 * float(row["b_m"]), (profiles["b_m"], row["b_m"])
expected = {"FN_N": 104837.15577497277, "Fx_N": -1570.8802307167803, "Fy_N": -4808.361821655628,
            "xi": 7.06837004430585e-05, "eta": 2.4718794206182737e-04}
for key, value in expected.items():
    assert math.isclose(float(row[key]), value, rel_tol=1e-6), f"{key} {row[key]}, expected {value}"
print("patch scripts: centre line and Table-3 row as expected")
PY
