#!/usr/bin/env python3
"""Charts of a "contact patch" step: creep-force curves (every theory on one chart, force along
the creepage that varies across the cases, over N) and traction maps (|q|, slip elements
outlined) for FASTSIM and the exact solver, of the case whose adhesion share is nearest a half.

    /usr/bin/python3 regression/charts/contact_patch_chart.py patch_forces.csv \\
        patch_tractions.csv|- creep.png tractions.png
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


def creep_chart(forces, png):
    columns = {"xi": ("Fx_N", "longitudinal creepage ξ"), "eta": ("Fy_N", "lateral creepage η"),
               "phi_per_m": ("Fy_N", "spin φ (1/m), lateral force")}
    spread = {k: max(float(r[k]) for r in forces) - min(float(r[k]) for r in forces) for k in columns}
    varying = max(spread, key=spread.get)
    force, label = columns[varying]
    fig, ax = plt.subplots(figsize=(8, 5))
    for theory in dict.fromkeys(r["theory"] for r in forces):
        mine = [r for r in forces if r["theory"] == theory and r["status"] == "ok"]
        mu_n = [float(r["FN_N"]) for r in mine]
        ax.plot([float(r[varying]) for r in mine],
                [-float(r[force]) / n for r, n in zip(mine, mu_n)], "o-", ms=3, label=theory)
    ax.set_xlabel(label)
    ax.set_ylabel(f"−{force.split('_')[0]} / N")
    ax.set_title("Creep force against creepage, every theory")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110, format="png")


def traction_chart(forces, tractions, png):
    shares = {int(r["case"]): float(r["adhesion_fraction"]) for r in forces
              if r["theory"] in ("exact", "fastsim") and r["adhesion_fraction"] not in ("", "nan")}
    last = min(shares, key=lambda k: abs(shares[k] - 0.5))
    theories = [t for t in ("fastsim", "exact") if any(r["theory"] == t for r in tractions)]
    fig, axes = plt.subplots(1, len(theories), figsize=(6 * len(theories), 5), squeeze=False)
    for ax, theory in zip(axes[0], theories):
        mine = [r for r in tractions if r["theory"] == theory and int(r["case"]) == last]
        x = [1e3 * float(r["x_m"]) for r in mine]
        y = [1e3 * float(r["y_m"]) for r in mine]
        q = [math.hypot(float(r["qx_Pa"]), float(r["qy_Pa"])) / 1e6 for r in mine]
        shade = ax.scatter(x, y, c=q, cmap="viridis", marker="s", s=18)
        slip = [(a, b) for a, b, r in zip(x, y, mine) if r["state"] == "slip"]
        ax.scatter([a for a, _ in slip], [b for _, b in slip], marker="s", s=18, facecolors="none",
                   edgecolors="red", linewidths=0.5, label="slip")
        ax.set_aspect("equal")
        ax.set_xlabel("x, rolling direction (mm; material enters at +x)")
        ax.set_ylabel("y (mm)")
        ax.set_title(f"{theory}: |q| (MPa), case {last}")
        fig.colorbar(shade, ax=ax)
        ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=110, format="png")


def main():
    forces_path, tractions_path, creep_png, traction_png = sys.argv[1:5]
    forces = rows(forces_path)
    creep_chart(forces, creep_png)
    if tractions_path != "-":
        traction_chart(forces, rows(tractions_path), traction_png)


if __name__ == "__main__":
    main()
