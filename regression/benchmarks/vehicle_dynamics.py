#!/usr/bin/python3
"""Benchmark: the vehicle on the implicit wheel-rail contact element (issues 18 and 19). Runs the
four published cases of the lateral train-structure interaction scene (inputs/scenes/
lateral_structure_{bs,ts}{20,40}.xml: 2.5 s simulated, dt 1 ms, 2500 steps, one core, best of three)
and reports per case the wall time of the time steps (their CSV output included, the static
balance, the set-up and the chart not), Newton iterations per step, time per step and per
Newton iteration, and the factor on real time (target: at least 5, i.e. <= 0.5 s). Then the
BS 20 m case again with full Newton (the tangent and its factorization at every iteration): the
time per Newton iteration of the 4-wheelset vehicle on rigid track with 16 potential contact
points (issue 18's target: <= 100 us). No reference program is on this machine, so the figures
are absolute.

Writes docs/data/vehicle_dynamics_benchmark.csv. Run on an idle machine from the repository
root: /usr/bin/python3 regression/benchmarks/vehicle_dynamics.py [build/bin/railfe]
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = ["bs20", "bs40", "ts20", "ts40"]


def run(railfe, deck_text, work, name):
    deck = os.path.join(work, name + ".xml")
    with open(deck, "w") as f:
        f.write(deck_text.replace('<Parameter name="Module" type="string" '
                                  'value="vehicle dynamics"/>',
                                  '<Parameter name="Module" type="string" '
                                  'value="vehicle dynamics"/>\n      <Parameter name="Chart" '
                                  'type="bool" value="false"/>'))
    out = os.path.join(work, name + "_out")
    subprocess.run([railfe, deck, "--output", out, "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    summary = json.load(open(os.path.join(out, "summary.json")))
    return next(v for k, v in summary.items() if "vehicle dynamics" in k)


def best(railfe, text, work, name):
    results = [run(railfe, text, work, "%s_%d" % (name, i)) for i in range(3)]
    return min(results, key=lambda s: s["wall time of the time steps (with their output) [s]"])


def main():
    railfe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for case in CASES:
            text = open(os.path.join(ROOT, "inputs", "scenes",
                                     "lateral_structure_%s.xml" % case)).read()
            s = best(railfe, text, work, case)
            wall = s["wall time of the time steps (with their output) [s]"]
            steps = s["steps"]
            rows.append([case.upper(), "modified Newton (once per step)", "%.4f" % wall,
                         "%.3f" % s["Newton iterations per step"], "%.1f" % (1e6 * wall / steps),
                         "%.1f" % (1e6 * s["wall time per Newton iteration (solve only) [s]"]),
                         "%.2f" % (2.5 / wall)])
            if case == "bs20":
                full = text.replace('value="once per step"', 'value="every iteration"')
                s = best(railfe, full, work, case + "_full")
                wall = s["wall time of the time steps (with their output) [s]"]
                rows.append([case.upper(), "full Newton (every iteration)", "%.4f" % wall,
                             "%.3f" % s["Newton iterations per step"],
                             "%.1f" % (1e6 * wall / s["steps"]),
                             "%.1f" % (1e6 * s["wall time per Newton iteration (solve only) [s]"]),
                             "%.2f" % (2.5 / wall)])
    out = os.path.join(ROOT, "docs", "data", "vehicle_dynamics_benchmark.csv")
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "newton", "wall_time_of_time_steps_s", "newton_iterations_per_step",
                    "time_per_step_us", "time_per_newton_iteration_us",
                    "simulated_over_wall_time"])
        w.writerows(rows)
    for r in rows:
        print(", ".join(r))


if __name__ == "__main__":
    main()
