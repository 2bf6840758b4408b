#!/usr/bin/env python3
"""Chart of a "wheelset on track" step: the profiles of every pose with their contact points
(left and right wheel), the rolling radius difference and the contact angles against the
lateral shift, from the CSV files the step wrote.

    /usr/bin/python3 regression/charts/contact_geometry_chart.py profiles.csv contacts.csv \
        contact_table.csv OUT.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    profiles, contacts, table = (rows(path) for path in sys.argv[1:4])
    # Rows that did not close hold no contact (the summary counts them): leave them out.
    table = [r for r in table if r["converged"] == "1"]
    png = sys.argv[4]
    poses = list(dict.fromkeys(p["pose"] for p in profiles if p["body"] == "wheel"))
    colours = {pose: plt.cm.viridis(i / max(len(poses) - 1, 1)) for i, pose in enumerate(poses)}
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    for ax, side in zip(axes[0], ("left", "right")):
        rail = [p for p in profiles if p["body"] == "rail" and p["side"] == side]
        ax.plot([1e3 * float(p["y_m"]) for p in rail], [1e3 * float(p["z_m"]) for p in rail], "k", lw=1.2, label="rail")
        for pose in poses:
            wheel = [p for p in profiles if p["body"] == "wheel" and p["side"] == side and p["pose"] == pose]
            ax.plot([1e3 * float(p["y_m"]) for p in wheel], [1e3 * float(p["z_m"]) for p in wheel],
                    color=colours[pose], lw=0.8, label=pose)
            touching = [c for c in contacts if c["pose"] == pose and c["side"] == side and c["status"] == "converged"
                        and float(c["gap_m"]) < 1e-6]
            ax.plot([1e3 * float(c["y_m"]) for c in touching], [1e3 * float(c["z_m"]) for c in touching],
                    "o", color=colours[pose], ms=5, mec="k")
        ys = [1e3 * float(p["y_m"]) for p in rail]
        centre = (min(ys) + max(ys)) / 2
        ax.set_xlim(centre - 45, centre + 45)
        ax.set_ylim(25, -35)  # z down: the wheel above the rail
        ax.set_aspect("equal")
        ax.set_title(f"{side} wheel and rail, contact points (dots)", fontsize=10)
        ax.set_xlabel("track y (mm, to the right)")
        ax.set_ylabel("z (mm, down)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower left")
    shift = [1e3 * float(r["lateral_m"]) for r in table]
    axes[1, 0].plot(shift, [1e3 * float(r["delta_r_m"]) for r in table], "b", lw=1)
    axes[1, 0].set_xlabel("lateral shift (mm)")
    axes[1, 0].set_ylabel("rolling radius difference right - left (mm)")
    for side, colour in (("left", "tab:orange"), ("right", "tab:green")):
        axes[1, 1].plot(shift, [math.degrees(float(r[f"{side}_contact_angle_rad"])) for r in table],
                        color=colour, lw=1, label=f"{side} wheel")
        flange = [s for s, r in zip(shift, table) if r[f"{side}_part"] == "flange"]
        if flange:
            edge = min(flange, key=abs)
            for ax in axes[1]:
                ax.axvline(edge, color=colour, ls="--", lw=0.8)
    axes[1, 1].set_xlabel("lateral shift (mm)")
    axes[1, 1].set_ylabel("contact angle (degree, towards the flange)")
    axes[1, 1].legend(fontsize=8)
    for ax in axes[1]:
        ax.grid(alpha=0.3)
        ax.set_title("rigid wheelset (dashed: flange contact)", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110, format="png")  # the step hands a staging name (.part)


if __name__ == "__main__":
    main()
