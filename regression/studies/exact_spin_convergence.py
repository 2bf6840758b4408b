#!/usr/bin/env python3
"""Grid convergence of the exact steady-rolling solver in spin (issue 14, item 13): the issue's
Hertz patch (0.46 m wheel on a 0.30 m crown, 100 kN, steel), 16 to 120 elements a side, with the
transport term of the slip first order, second order (BDF2) on every element, and second order with
the element that leads each row taking the edge's square-root form (now).

Left: C23 and C33 from the initial slope (creepage 1e-6) against Kalker's table
(inputs/kalker/kalker_cij.csv, interpolated at a/b and nu 0.3). Right: the lateral force of the
spin cases of the speed-accuracy study (phi 0.5 and 2 /m) and of lateral creepage with spin
(eta 1e-3, phi 2 /m), mu 0.3, against the second-order solution at 120 x 120.

    /usr/bin/python3 regression/studies/exact_spin_convergence.py [build/bin/railfe-contact-mechanics]
    /usr/bin/python3 regression/studies/exact_spin_convergence.py --plot   (from the stored CSV)

Writes docs/data/exact_spin_convergence.csv and docs/img/exact_spin_convergence.png (a few
minutes on one core).
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "exact_spin_convergence.csv")
PNG = os.path.join(ROOT, "docs", "img", "exact_spin_convergence.png")
SCHEMES = {"first-order": ("first order", ":", "o"),
           "second-order-smooth-edge": ("BDF2, leading elements too", "--", "^"),
           "second-order": ("BDF2, edge form on leading elements (now)", "-", "s")}


def percent(value, reference):
    return 100 * (value / reference - 1)


def main():
    if sys.argv[1:] != ["--plot"]:
        tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe-contact-mechanics")
        subprocess.run([tool, "spin-convergence", CSV], check=True)
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    finest = max(int(r["elements"]) for r in rows)
    reference = next(r for r in rows if r["scheme"] == "second-order" and int(r["elements"]) == finest)
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 6))
    for scheme, (label, style, marker) in SCHEMES.items():
        mine = [r for r in rows if r["scheme"] == scheme]
        m = [int(r["elements"]) for r in mine]
        left.plot(m, [percent(float(r["C33"]), float(r["Kalker_C33"])) for r in mine], style, marker=marker,
                  color="tab:red", label=f"C33, {label}")
        left.plot(m, [percent(float(r["C23_from_spin"]), float(r["Kalker_C23"])) for r in mine], style,
                  marker=marker, color="tab:blue", label=f"C23, {label}")
        for column, color, name in (("spin_2_Fy_N", "tab:red", "spin 2 /m"),
                                    ("combined_Fy_N", "tab:green", "η 1e-3 + spin 2 /m"),
                                    ("spin_05_Fy_N", "tab:blue", "spin 0.5 /m")):
            right.plot(m, [percent(float(r[column]), float(reference[column])) for r in mine], style,
                       marker=marker, color=color, label=f"Fy {name}, {label}")
    for axis in (left, right):
        axis.axhline(0, color="black", linewidth=0.8)
        for bound in (-1, 1):
            axis.axhline(bound, color="grey", linewidth=0.8, linestyle=":")
        axis.axvline(40, color="grey", linewidth=0.8, linestyle="-.")
        axis.set_xscale("log")
        axis.set_xticks([16, 20, 24, 30, 40, 48, 60, 80, 100, 120])
        axis.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
        axis.set_xlabel("elements a side (40: the default grid)")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=7)
    left.set_ylabel("initial slope against Kalker's table (%)")
    left.set_title("Spin coefficients against Kalker (μ-free, creepage 1e-6)")
    right.set_ylabel(f"lateral force against second order at {finest} x {finest} (%)")
    right.set_title("Spin cases, μ 0.3")
    left.set_ylim(-5, 35)
    right.set_ylim(-10, 3)
    fig.suptitle("Exact solver, Hertz patch a/b 1.33: grid convergence of the spin terms")
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", CSV, "and", PNG)


if __name__ == "__main__":
    main()
