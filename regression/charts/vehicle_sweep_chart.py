#!/usr/bin/python3
"""Chart of a vehicle dynamics sweep (<step>_sweep.csv): running safety and comfort against
speed, a line per (span, amplitude). Panels: peak derailment quotient Y/Q (instantaneous, and
its sliding mean dashed), peak wheel unloading dQ/Q, peak car-body lateral acceleration. A case
that stopped before its end (Newton failed, a wheelset left the rails) is marked with a red x at
the values it reached, and named in the legend: its numbers are not a result.

Usage: vehicle_sweep_chart.py SWEEP.csv OUT.png [LABEL]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    out = sys.argv[2]
    label = sys.argv[3] if len(sys.argv) > 3 else "sweep"
    groups = {}
    for r in rows:
        groups.setdefault((float(r["span_m"]), float(r["amplitude_m"])), []).append(r)
    panels = [("peak_Y_over_Q", "peak Y/Q", "peak_mean_Y_over_Q"),
              ("peak_dQ_over_Q", "peak wheel unloading ΔQ/Q", None),
              ("peak_car_body_ay_m_per_s2", "car body peak lateral acceleration (m/s²)", None)]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    stopped_label = True
    for (span, amplitude), cases in sorted(groups.items()):
        cases.sort(key=lambda r: float(r["speed_km_per_h"]))
        name = "%g m, %g mm" % (span, amplitude * 1e3)
        for ax, (key, title, dashed) in zip(axes, panels):
            done = [r for r in cases if r["status"] == "completed"]
            line, = ax.plot([float(r["speed_km_per_h"]) for r in done],
                            [float(r[key]) for r in done], "o-", label=name)
            if dashed:
                ax.plot([float(r["speed_km_per_h"]) for r in done],
                        [float(r[dashed]) for r in done], "s--", color=line.get_color(),
                        alpha=0.6)
            for r in cases:
                if r["status"] != "completed":
                    ax.plot(float(r["speed_km_per_h"]), float(r[key]), "x", color="red",
                            markersize=11, mew=2.5,
                            label=("stopped: %s" % r["status"]) if stopped_label else None)
                    stopped_label = False
            ax.set_title(title)
            ax.set_xlabel("speed (km/h)")
            ax.grid(alpha=0.3)
    axes[0].axhline(0.8, color="k", lw=0.8, ls=":")
    axes[0].text(axes[0].get_xlim()[0], 0.81, " Y/Q 0.8, a common limit (2 m mean dashed)",
                 fontsize=8)
    axes[1].axhline(0.6, color="k", lw=0.8, ls=":")
    handles, labels = [], []
    for ax in axes:
        for h, l in zip(*ax.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), 6), fontsize=9)
    fig.suptitle("%s: %d cases (span, deviation amplitude)" % (label, len(rows)))
    fig.tight_layout(rect=(0, 0.1, 1, 0.95))
    fig.savefig(out, dpi=110, format="png")


if __name__ == "__main__":
    main()
