#!/usr/bin/env python3
"""What the squeal scene's simplifications change (issue 16, "model no more than the scene
needs"): the demo-scale case 3 run as shipped and with one choice changed at a time (sleepers as
point masses between pad and ballast instead of left out, or as coarse solids; a track twice as
long), each
compared with the shipped model on the contact forces and the wheel's response over the run.

Writes docs/data/squeal_simplifications.csv (one row per variant: wall time, elements, steps and
the mean and spread of the normal, longitudinal and lateral forces and of the rim's lateral
velocity, with the largest difference from the shipped run over time) and
docs/img/squeal_simplifications.png (the force histories on the same axes).

    /usr/bin/python3 regression/studies/squeal_simplifications.py [build/bin/railfe] [--replot]
"""
import bisect
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, HERE)
from railfe_runs import csv_rows, run_deck, step_section, study_parser, typed_rows, write_rows  # noqa: E402

VARIANTS = [
    ("shipped", "as shipped: seats on pad and ballast in series; 1.2 m track",
     ["--sleepers", "springs"]),
    ("sleeper masses", "sleepers as 150 kg point masses between pad and ballast",
     ["--sleepers", "bodies"]),
    ("solid sleepers", "sleepers as 12-hex8 concrete solids (156 kg): pads from the seats to "
     "their tops and ballast below; the same in the preload", ["--sleepers", "solids"]),
    ("long track", "2.4 m track (4 seats); the wheel starting at the same place in it",
     ["--rail-length", "2.4", "--start-x", "1.05"]),
]
COLUMNS = {"normal": "normal_force_N", "longitudinal": "tangential_1_N",
           "lateral": "tangential_2_N"}


# The studies' own baseline, the demo as it was when they were run: no transition radii, the
# rail's bulk-modulus penalty at f = 1 (their options come later and win).
STUDY_BASELINE = ["--penalty", "1", "--penalty-stiffness", "bulk modulus", "--transitions",
                  "--contact-mass-scaling", "0"]


def deck_text(options):
    command = [sys.executable, os.path.join(ROOT, "regression", "scenes", "make_squeal_decks.py"),
               "--case", "3", "--scale", "demo"] + STUDY_BASELINE + options
    return subprocess.run(command, check=True, capture_output=True, text=True).stdout


def histories(results):
    rows = csv_rows(os.path.join(results, "roll_contact_wheel-rail.csv"))
    forces = {k: [float(r[c]) for r in rows] for k, c in COLUMNS.items()}
    forces["time"] = [float(r["time_s"]) for r in rows]
    rim = csv_rows(os.path.join(results, "roll_histories.csv"))
    forces["rim_time"] = [float(r["time_s"]) for r in rim]
    forces["rim_vy"] = [float(r["rim vy_velocity_y_m_per_s"]) for r in rim]
    return forces


def stats(values):
    mean = sum(values) / len(values)
    return mean, math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))


def largest_difference(time, values, ref_time, ref_values):
    """Largest |difference| over the shipped run's times (the variant's nearest row; the times
    ascend, so a bisection finds it)."""
    worst = 0.0
    for t, v in zip(ref_time, ref_values):
        i = bisect.bisect_left(time, t)
        k = min((j for j in (i - 1, i) if 0 <= j < len(time)), key=lambda j: abs(time[j] - t))
        worst = max(worst, abs(values[k] - v))
    return worst


def run(railfe, work):
    rows, runs = [], {}
    for name, what, options in VARIANTS:
        results, summary = run_deck(railfe, deck_text(options), work, name.replace(" ", "_"))
        roll = step_section(summary, "roll")
        runs[name] = histories(results)
        row = {"variant": name, "what": what,
               "wall_time_s": float(summary["Wall time"]["total [s]"]),
               "roll_cpu_s": float(roll["time: stepping, CPU of rank 0 [s]"]),
               "elements": float(roll.get("elements", float("nan"))),
               "steps": float(roll.get("steps", float("nan")))}
        for key in ("normal", "longitudinal", "lateral", "rim_vy"):
            mean, spread = stats(runs[name][key])
            row[f"{key}_mean"], row[f"{key}_std"] = mean, spread
        rows.append(row)
    ref = runs["shipped"]
    for row in rows:
        h = runs[row["variant"]]
        for key in ("normal", "longitudinal", "lateral"):
            row[f"{key}_max_difference_N"] = largest_difference(h["time"], h[key], ref["time"],
                                                                ref[key])
        row["rim_vy_max_difference_m_per_s"] = largest_difference(
            h["rim_time"], h["rim_vy"], ref["rim_time"], ref["rim_vy"])
    write_rows(os.path.join(ROOT, "docs", "data", "squeal_simplifications.csv"), rows)
    for name, h in runs.items():
        write_rows(os.path.join(work, name.replace(" ", "_") + "_forces.csv"),
                   [{"time_s": t, "normal_N": n, "longitudinal_N": x, "lateral_N": y}
                    for t, n, x, y in zip(h["time"], h["normal"], h["longitudinal"],
                                          h["lateral"])])


def plot(work):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    for name, what, _ in VARIANTS:
        rows = typed_rows(os.path.join(work, name.replace(" ", "_") + "_forces.csv"), [])
        t = [1e3 * r["time_s"] for r in rows]
        for axis, key in zip(axes, ("normal_N", "longitudinal_N", "lateral_N")):
            axis.plot(t, [1e-3 * r[key] for r in rows], label=what, linewidth=1)
    for axis, label in zip(axes, ("normal force (kN)", "longitudinal force (kN)",
                                  "lateral force (kN)")):
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[1].legend(fontsize=8, loc="upper left")  # that panel is empty there
    axes[-1].set_xlabel("time (ms)")
    fig.suptitle("Squeal demo (case 3): what the track's simplifications change")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "squeal_simplifications.png"), dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "squeal_simplifications_work", ROOT)
    args = parser.parse_args()
    if not args.replot:
        run(args.railfe, args.work)
    plot(args.work)


if __name__ == "__main__":
    main()
