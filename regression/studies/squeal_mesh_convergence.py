#!/usr/bin/env python3
"""Speed against accuracy of the squeal scene's contact mesh (issue 16): case 1 on the demo's
time line (no lateral motion; torque ramped over 0.5 ms, 1.6 ms) with the contact zone meshed at
6, 4 and 3 mm (rail zone, rail head, wheel tread and refined arc alike; the step mass-scaled in
proportion, 25 ns per mm, as the contact's own limit scales). Over the last 0.2 ms: the creep
force, the contact area and the nodes in contact; at 1.6 ms the peak pressure; and the explicit
step's CPU time, each against the finest run.

Writes docs/data/squeal_mesh_convergence.csv and docs/img/squeal_mesh_convergence.png.

    /usr/bin/python3 regression/studies/squeal_mesh_convergence.py [build/bin/railfe] [--replot]
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, HERE)
from railfe_runs import csv_rows, run_deck, step_section, study_parser, typed_rows, write_rows  # noqa: E402
from squeal_simplifications import deck_text  # noqa: E402

SIZES_MM = [6, 4, 3]
WINDOW = (1.4e-3, 1.6e-3)  # s: the end of the run, where the traction has nearly settled
CSV = os.path.join(ROOT, "docs", "data", "squeal_mesh_convergence.csv")


def options(size_mm):
    h = size_mm / 1000
    return ["--zone-size", str(h), "--head-size", str(h), "--tread-size", str(h),
            "--arc-size", str(h), "--mass-scaling", f"{2.5e-5 * h:g}"]


def window_mean(rows, column):
    values = [float(r[column]) for r in rows if WINDOW[0] <= float(r["time_s"]) <= WINDOW[1]]
    return sum(values) / len(values)


def run(railfe, work):
    rows = []
    for size in SIZES_MM:
        text = deck_text(options(size) + ["--case", "1"])  # the last --case wins
        results, summary = run_deck(railfe, text, work, f"zone_{size}mm")
        roll = step_section(summary, "roll")
        history = csv_rows(os.path.join(results, "roll_contact_wheel-rail.csv"))
        last_patch = sorted(f for f in os.listdir(results)
                            if f.startswith("roll_contact_wheel-rail_patch_") and f.endswith(".csv"))
        patch = csv_rows(os.path.join(results, last_patch[-1]))
        rows.append({
            "zone_element_size_mm": float(size),
            "elements": float(roll["elements"]),
            "steps": float(roll["steps"]),
            "explicit_cpu_s": float(roll["time: stepping, CPU of rank 0 [s]"]),
            "creep_force_N": math.hypot(window_mean(history, "tangential_1_N"),
                                        window_mean(history, "tangential_2_N")),
            "normal_force_N": window_mean(history, "normal_force_N"),
            "contact_area_m2": window_mean(history, "contact_area_m2"),
            "active_nodes": window_mean(history, "active_nodes"),
            "peak_pressure_Pa": max(float(r["pressure_Pa"]) for r in patch),
        })
    finest = rows[-1]
    for row in rows:
        for key in ("creep_force_N", "contact_area_m2", "peak_pressure_Pa"):
            row[key.rsplit("_", 1)[0] + "_vs_finest"] = row[key] / finest[key] - 1
    write_rows(CSV, rows)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = typed_rows(CSV, [])
    fig, axis = plt.subplots(figsize=(8, 5))
    cpu = [r["explicit_cpu_s"] for r in rows]
    for key, label in (("creep_force_vs_finest", "creep force (mean, last 0.2 ms)"),
                       ("contact_area_vs_finest", "contact area (mean, last 0.2 ms)"),
                       ("peak_pressure_vs_finest", "peak pressure at 1.6 ms")):
        axis.plot(cpu, [100 * r[key] for r in rows], marker="o", label=label)
    for r in rows:
        axis.annotate(f"{r['zone_element_size_mm']:g} mm\n{r['elements'] / 1e3:.0f} k el.",
                      (r["explicit_cpu_s"], 0), textcoords="offset points", xytext=(0, 12),
                      ha="center", fontsize=8)
    axis.axhline(0, color="grey", linewidth=0.8)
    axis.set_xscale("log")
    axis.set_xlabel("explicit step CPU time, one core (s)")
    axis.set_ylabel("difference from the 3 mm run (%)")
    axis.set_title("Squeal scene, case 1 on the demo's time line: contact mesh size")
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "squeal_mesh_convergence.png"), dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "squeal_mesh_convergence_work", ROOT)
    args = parser.parse_args()
    if not args.replot:
        run(args.railfe, args.work)
    plot()


if __name__ == "__main__":
    main()
