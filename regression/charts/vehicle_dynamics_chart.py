#!/usr/bin/python3
"""Chart of a vehicle dynamics step, the published comparison's quantities against time: the
track's lateral deviation under the first wheelset (when the step has one), the car body's
lateral acceleration at the first measuring point, the first wheelset's lateral displacement and
acceleration, and the lateral forces Y on its right and left wheels with each flange impact
marked at its peak.

Usage: vehicle_dynamics_chart.py WHEELSETS.csv WHEELS.csv POINTS.csv IMPACTS.csv DEVIATION.csv
       SPEED START X1 OUT.png [LABEL REF_WHEELSETS.csv REF_WHEELS.csv REF_POINTS.csv REF_LABEL]
(DEVIATION.csv may be '-': none; X1 is the first wheelset's x.) With a reference, that step's
histories are drawn dashed on the same axes, for the comparison of two models of one run.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def columns(path):
    rows = list(csv.DictReader(open(path)))
    if not rows:
        return {}
    return {k: [float(r[k]) if r[k] not in ("", None) else float("nan") for r in rows]
            for k in rows[0] if k not in ("wheel",)}


def main():
    wheelsets, wheels, points, impacts, deviation, speed, start, x1, out = sys.argv[1:10]
    label, ref_wheelsets, ref_wheels, ref_points, reference_label = (sys.argv[10:15] +
                                                                     [""] * 5)[:5]
    speed, start, x1 = float(speed), float(start), float(x1)
    w, c, p = columns(wheelsets), columns(wheels), columns(points)
    refs = None
    if ref_wheelsets:
        refs = (columns(ref_wheelsets), columns(ref_wheels), columns(ref_points))
    impact_rows = list(csv.DictReader(open(impacts)))
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    t = w["time_s"]
    if deviation != "-":
        d = columns(deviation)
        times = [(s - start - x1) / speed for s in d["s_m"]]
        axes[0].plot(times, [1e3 * v for v in d["structure_m"]], "0.6", label="structure")
        axes[0].plot(times, [1e3 * v for v in d["rail_m"]], "k", label="rail (on its pads)")
        axes[0].set_xlim(t[0], t[-1])
    acceleration = [k for k in p if k.endswith("_ay_m_per_s2")]
    tag = (label + ": ") if label else ""
    if acceleration:
        axes[1].plot(p["time_s"], p[acceleration[0]], "C3",
                     label=tag + acceleration[0].replace("_ay_m_per_s2", ""))
        if refs and acceleration[0] in refs[2]:
            axes[1].plot(refs[2]["time_s"], refs[2][acceleration[0]], "k--", lw=0.9,
                         label=reference_label)
    axes[0].set_ylabel("lateral deviation\nunder wheelset 1 (mm)")
    axes[1].set_ylabel("car body lateral\nacceleration (m/s²)")
    axes[2].plot(t, [1e3 * y for y in w["w1_y_m"]], "C0", label=tag + "displacement (mm)")
    if refs:
        axes[2].plot(refs[0]["time_s"], [1e3 * y for y in refs[0]["w1_y_m"]], "k--", lw=0.9,
                     label=reference_label)
    ax2 = axes[2].twinx()
    ax2.plot(t, w["w1_ay_m_per_s2"], "C1", lw=0.7, label="acceleration (m/s²)")
    ax2.set_ylabel("acceleration (m/s²)", color="C1")
    axes[2].set_ylabel("wheelset 1 lateral\ndisplacement (mm)")
    for side, colour in (("right", "C0"), ("left", "C1")):
        axes[3].plot(c["time_s"], [y / 1e3 for y in c["w1_" + side + "_Y_N"]], colour,
                     label=tag + side + " wheel")
        if refs:
            axes[3].plot(refs[1]["time_s"], [y / 1e3 for y in refs[1]["w1_" + side + "_Y_N"]],
                         "--", color=colour, lw=0.9, label=reference_label + ": " + side)
        peaks = [(float(r["start_s"]), float(r["peak_Y_N"]) / 1e3) for r in impact_rows
                 if r["wheelset"] == "1" and r["wheel"] == side]
        if peaks:
            axes[3].plot([a for a, _ in peaks], [b for _, b in peaks], "v", color=colour, ms=6,
                         label=side + " flange impacts")
    axes[3].set_ylabel("wheelset 1: Y towards\nthe track centre (kN)")
    axes[3].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=110, format="png")  # the run stages it as NAME.part


if __name__ == "__main__":
    main()
