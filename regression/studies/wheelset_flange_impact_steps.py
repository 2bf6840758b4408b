#!/usr/bin/python3
"""Time step against stability and accuracy for a flange impact: the S1002 wheelset of
wheelset_speed_accuracy.py (creep-force table, alpha -0.05) runs at 40 m/s over a 12 mm, 12 m
lateral irregularity, where its left flange strikes the rail, for time steps from 4 ms down to
0.0625 ms. For each: whether it finishes, the peak Y/Q, the peak flange normal force, the peak
lateral shift, Newton iterations and wall time; errors against the finest step.

Usage: wheelset_flange_impact_steps.py RAILFE [--out DIR]
Writes DIR/wheelset_flange_impact_steps.csv and .png (default docs/img).
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile

from wheelset_speed_accuracy import ROOT, deck

STEPS = [0.004, 0.002, 0.001, 0.0005, 0.00025, 0.000125, 0.0000625]


def run(railfe, work, step):
    name = "dt_%g" % step
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(deck(step=step, speed=40, amplitude=0.012, end=0.75))
    out = os.path.join(work, name)
    done = subprocess.run([railfe, path, "--output", out, "--quiet"], capture_output=True,
                          text=True)
    row = dict(step=step, finished=done.returncode == 0, y_over_q=float("nan"),
               flange_force=float("nan"), shift=float("nan"), iterations=float("nan"),
               wall=float("nan"), reason="")
    if not row["finished"]:
        row["reason"] = done.stderr.strip().splitlines()[-1][:160]
        return row
    peak_q = peak_n = peak_y = 0.0
    for r in csv.DictReader(open(os.path.join(out, "run_contacts.csv"))):
        peak_q = max(peak_q, abs(float(r["left_Y_over_Q"])), abs(float(r["right_Y_over_Q"])))
        peak_n = max(peak_n, float(r["left_flange_N_N"]), float(r["right_flange_N_N"]))
    for r in csv.DictReader(open(os.path.join(out, "run_wheelset.csv"))):
        peak_y = max(peak_y, abs(float(r["y_m"])))
    summary = json.load(open(os.path.join(out, "summary.json")))
    section = next(v for k, v in summary.items() if "wheelset dynamics" in k)
    row.update(y_over_q=peak_q, flange_force=peak_n, shift=peak_y,
               iterations=section["Newton iterations per step"], wall=section["wall time [s]"])
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("railfe")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "img"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        rows = [run(args.railfe, work, step) for step in STEPS]
    finest = rows[-1]
    for r in rows:
        for key in ("y_over_q", "flange_force", "shift"):
            r[key + "_error"] = r[key] / finest[key] - 1 if finest["finished"] else float("nan")
        print("dt %7.4f ms: %s Y/Q %.4f (%+.2f %%), flange N %.0f (%+.2f %%), shift %.4f mm "
              "(%+.3f %%), %.2f it/step, %.2f s %s" % (
                  1e3 * r["step"], "ok  " if r["finished"] else "STOP", r["y_over_q"],
                  100 * r["y_over_q_error"], r["flange_force"], 100 * r["flange_force_error"],
                  1e3 * r["shift"], 100 * r["shift_error"], r["iterations"], r["wall"],
                  r["reason"]))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "wheelset_flange_impact_steps.csv"), "w") as f:
        writer = csv.writer(f)
        writer.writerow(["time_step_s", "finished", "peak_Y_over_Q", "peak_flange_force_N",
                         "peak_shift_m", "newton_iterations_per_step", "wall_time_s",
                         "Y_over_Q_error", "flange_force_error", "shift_error", "reason"])
        for r in rows:
            writer.writerow([r["step"], int(r["finished"]), "%.6g" % r["y_over_q"],
                             "%.6g" % r["flange_force"], "%.6g" % r["shift"],
                             "%.4g" % r["iterations"], "%.4g" % r["wall"],
                             "%.4g" % r["y_over_q_error"], "%.4g" % r["flange_force_error"],
                             "%.4g" % r["shift_error"], r["reason"]])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3))
    done = [r for r in rows[:-1] if r["finished"]]
    for key, label, marker in (("y_over_q", "peak Y/Q", "o"),
                               ("flange_force", "peak flange force", "s"),
                               ("shift", "peak lateral shift", "^")):
        axes[0].loglog([1e3 * r["step"] for r in done],
                       [max(abs(r[key + "_error"]), 1e-6) * 100 for r in done], marker + "-",
                       label=label)
        axes[1].loglog([r["wall"] for r in done],
                       [max(abs(r[key + "_error"]), 1e-6) * 100 for r in done], marker + "-",
                       label=label)
    for r in rows:
        if not r["finished"]:
            axes[0].axvline(1e3 * r["step"], color="C3", ls=":", lw=1)
            axes[0].annotate("stops", (1e3 * r["step"], 1), color="C3", fontsize=8,
                             rotation=90)
    axes[0].set_xlabel("time step (ms)")
    axes[1].set_xlabel("wall time of 0.75 s simulated (s)")
    for ax in axes:
        ax.set_ylabel("|difference| from dt = %g ms (%%)" % (1e3 * STEPS[-1]))
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle("Flange impact (S1002 wheelset, 40 m/s, 12 mm lateral irregularity): time step "
                 "against accuracy and cost", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "wheelset_flange_impact_steps.png"), dpi=120)


if __name__ == "__main__":
    main()
