#!/usr/bin/python3
"""Benchmark: the implicit wheel-rail contact element (issue 18). Times, for the S1002 wheel on the
60E1 rail 1:40 (railfe-wheel-rail-benchmark, best of three runs): the contact search of one wheel
(tread and flange, warm started as between Newton iterations), the creep forces of one point by
each theory, and the element's evaluation and tangent per point. Then runs a wheelset (4 potential
contact points) over a lateral irregularity at 30 m/s, dt 1 ms, creep-force table, and reports
the wall time per step and per Newton iteration (timed inside the Newton solver: residuals,
matrices and saddle-point solves, not the predictor or the output), and the per-iteration
estimate of a 4-wheelset vehicle on rigid track (16 points: 4 x the wheelset's iteration).
Targets: search <= 20 us per wheel, creep forces <= 1 us per point by table, a Newton iteration
of the 4-wheelset vehicle on rigid track <= 100 us. No reference program is on this machine, so
the figures are absolute.

Writes docs/data/wheelset_contact_benchmark.csv. Run on an idle machine from the repository
root: /usr/bin/python3 regression/benchmarks/wheelset_contact.py [build/bin]
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

import tool_benchmark

DECK = os.path.join(tool_benchmark.ROOT, "regression", "studies", "wheelset_speed_accuracy.py")


def wheelset_run(railfe):
    """Wall time per step and per Newton iteration of the speed-accuracy study's table case."""
    sys.path.insert(0, os.path.dirname(DECK))
    import wheelset_speed_accuracy as study
    best = None
    with tempfile.TemporaryDirectory() as work:
        for _ in range(3):
            row = study.run(railfe, work, "table", "neglected", 0.001)
            out = os.path.join(work, "table_neglected_0.001", "summary.json")
            summary = json.load(open(out))
            section = next(v for k, v in summary.items() if "wheelset dynamics" in k)
            per_step = section["wall time per step [s]"]
            per_iteration = section["wall time per Newton iteration (solve only) [s]"]
            if best is None or per_step < best[0]:
                best = (per_step, row["iterations"], per_iteration)
    return best


def main():
    bin_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(tool_benchmark.ROOT, "build", "bin")
    out = os.path.join(tool_benchmark.ROOT, "docs", "data", "wheelset_contact_benchmark.csv")
    tool_benchmark.best_of_runs(os.path.join(bin_dir, "railfe-wheel-rail-benchmark"), out)
    per_step, iterations, per_iteration = wheelset_run(os.path.join(bin_dir, "railfe"))
    rows = [("wheelset step (4 points, dt 1 ms, table)", per_step * 1e6, "us", ""),
            ("wheelset Newton iterations per step", iterations, "", ""),
            ("wheelset step / Newton iterations (with the step's output)",
             per_step / iterations * 1e6, "us", ""),
            ("wheelset Newton iteration (4 points, timed inside the solver)",
             per_iteration * 1e6, "us", ""),
            ("4-wheelset vehicle Newton iteration on rigid track, estimated (16 points)",
             4 * per_iteration * 1e6, "us", "100")]
    with open(out, "a", newline="") as f:
        writer = csv.writer(f)
        for name, value, unit, target in rows:
            within = "" if not target else ("yes" if value <= float(target) else "NO")
            writer.writerow([name, f"{value:.4g}", unit, target, within])
            print(f"{name:40s} {value:10.4g} {unit:3s} target {target or '-':>4s} {within}")


if __name__ == "__main__":
    main()
