#!/usr/bin/python3
"""Benchmark: a sweep listed in a deck, dealt over MPI ranks (issue 19). Runs the BS 20 m sweep
deck (inputs/scenes/lateral_structure_bs20_sweep.xml: 12 cases, 200-350 km/h x 8, 16, 24 mm,
each over 208 m of track) at 1 and 2 ranks, best of three each, and reports the sweep's wall
time (from the summary: the cases and the table, not the set-up), the cases' time summed over
the ranks, and the speed-up of 2 ranks over 1 side by side on this machine. The sweep's chart
is not drawn. Each case runs on one rank, so the ideal is the rank count, less the imbalance of
unequal cases.

Writes docs/data/vehicle_sweep_benchmark.csv. Run on an idle machine from the repository root:
/usr/bin/python3 regression/benchmarks/vehicle_sweep.py [build/bin/railfe]
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "scenes", "lateral_structure_bs20_sweep.xml")


def run(railfe, ranks, work):
    text = open(DECK).read().replace(
        '<Parameter name="Module" type="string" value="vehicle dynamics"/>',
        '<Parameter name="Module" type="string" value="vehicle dynamics"/>\n'
        '      <Parameter name="Chart" type="bool" value="false"/>')
    deck = os.path.join(work, "sweep.xml")
    with open(deck, "w") as f:
        f.write(text)
    out = os.path.join(work, "out_np%d" % ranks)
    command = [railfe, deck, "--output", out, "--quiet"]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    summary = json.load(open(os.path.join(out, "summary.json")))
    step = next(v for k, v in summary.items() if "vehicle dynamics" in k)
    return step["sweep wall time [s]"], step["sweep wall time of the cases, summed [s]"]


def main():
    railfe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        best = {}
        for ranks in (1, 2):
            runs = [run(railfe, ranks, work) for _ in range(3)]
            best[ranks] = min(runs)
            print("%d rank(s): sweep %.3f s, cases summed %.3f s" % ((ranks,) + best[ranks]))
        for ranks in (1, 2):
            wall, summed = best[ranks]
            rows.append([ranks, "%.4g" % wall, "%.4g" % summed, "%.3g" % (best[1][0] / wall)])
    path = os.path.join(ROOT, "docs", "data", "vehicle_sweep_benchmark.csv")
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["ranks", "sweep_wall_s", "cases_summed_s", "speed_up"])
        writer.writerows(rows)
    print("speed-up on 2 ranks: %.2f (%s)" % (best[1][0] / best[2][0], path))


if __name__ == "__main__":
    main()
