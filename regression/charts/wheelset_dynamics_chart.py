#!/usr/bin/python3
"""Chart of a wheelset dynamics step: the wheelset's lateral shift and yaw, each wheel's vertical
and lateral force, and Y/Q, against time, from <step>_wheelset.csv and <step>_contacts.csv.

Usage: wheelset_dynamics_chart.py WHEELSET.csv CONTACTS.csv OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def columns(path):
    rows = list(csv.DictReader(open(path)))
    return {k: [float(r[k]) if r[k] else float("nan") for r in rows] for k in rows[0]}


def main():
    wheelset, contacts, out = sys.argv[1:4]
    w, c = columns(wheelset), columns(contacts)
    fig, axes = plt.subplots(4, 1, figsize=(8, 9), sharex=True)
    axes[0].plot(w["time_s"], [1e3 * y for y in w["y_m"]], label="lateral shift (mm)")
    axes[0].plot(w["time_s"], [1e3 * p for p in w["yaw_rad"]], label="yaw (mrad)")
    axes[0].set_ylabel("wheelset")
    for side, colour in (("right", "C0"), ("left", "C1")):
        axes[1].plot(c["time_s"], [q / 1e3 for q in c[side + "_Q_N"]], colour, label=side)
        axes[2].plot(c["time_s"], [y / 1e3 for y in c[side + "_Y_N"]], colour, label=side)
        axes[3].plot(c["time_s"], c[side + "_Y_over_Q"], colour, label=side)
        flange = [t for t, a in zip(c["time_s"], c[side + "_flange_active"]) if a > 0]
        if flange:
            axes[3].plot(flange, [0] * len(flange), "|", color=colour, ms=8,
                         label=side + " flange in contact")
    axes[1].set_ylabel("Q (kN)")
    axes[2].set_ylabel("Y, towards the\ntrack centre (kN)")
    axes[3].set_ylabel("Y/Q")
    axes[3].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=110, format="png")  # the run stages it as NAME.part


if __name__ == "__main__":
    main()
