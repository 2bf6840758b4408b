#!/usr/bin/env python3
"""Where HHT-alpha with Newton iterations keeps the energy balance and where Newton needs help
(issue 17, "Stability where the method fails"): a 1 kg ball dropped 10 mm onto a 10 kg block on a
100 kN/m spring, Hertz contact F = k delta^1.5 (k = 1e9 N/m^1.5, no tension), gravity, 1 s
(about a dozen impacts of ~0.9 ms each; framework/tools/hht_impact_study.cpp). Swept over
dt = 1e-5 ... 3.2e-2 s and alpha in {0, -0.05, -0.1, -0.2, -0.3}, with Newton's default
tolerances (1e-8 relative on force and increment), dt halved at most 4 times, and 20 or 5
iterations allowed per step. The energy error is (E - E0) / (m_ball g h) at the end and at its
extremes (the exact motion conserves E). The Hertz impact time is t_c = 2.94 delta_max / v0
(Johnson 1985, sec. 11.1) with 0.5 m* v0^2 = 0.4 k delta_max^2.5.

    /usr/bin/python3 regression/studies/hht_impact_stability.py [build/bin/railfe-hht-study]

Writes docs/data/hht_impact_stability.csv, docs/data/hht_impact_history.csv and
docs/img/hht_impact_stability.png. A few seconds.
"""
import csv
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "hht_impact_stability.csv")
HISTORY = os.path.join(ROOT, "docs", "data", "hht_impact_history.csv")
PNG = os.path.join(ROOT, "docs", "img", "hht_impact_stability.png")

BALL, BLOCK, HERTZ, GRAVITY, DROP = 1.0, 10.0, 1e9, 9.81, 0.01
STATUS_COLOURS = {"converged": "#4caf50", "cut back": "#ff9800", "failed": "#d32f2f"}


def impact_time():
    reduced = BALL * BLOCK / (BALL + BLOCK)
    speed = math.sqrt(2 * GRAVITY * DROP)
    approach = (5 * reduced * speed**2 / (4 * HERTZ)) ** 0.4
    return 2.94 * approach / speed


def grid(rows, key):
    alphas = sorted({float(r["alpha"]) for r in rows}, reverse=True)
    steps = sorted({float(r["dt_s"]) for r in rows})
    table = {(float(r["alpha"]), float(r["dt_s"])): r for r in rows}
    return alphas, steps, [[table[(a, s)][key] for s in steps] for a in alphas], table


def main():
    tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe-hht-study")
    subprocess.run([tool, "impact-map", CSV], check=True, stderr=subprocess.DEVNULL)
    subprocess.run([tool, "impact-history", HISTORY], check=True)
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    with open(HISTORY) as f:
        history = list(csv.DictReader(f))
    t_c = impact_time()
    print(f"Hertz impact time t_c = {t_c * 1e3:.3f} ms")

    fig = plt.figure(figsize=(13, 10))
    top = fig.add_subplot(3, 1, 1)
    full = [r for r in rows if r["max_iterations_allowed"] == "20"]
    alphas, steps, errors, table = grid(full, "final_energy_error")
    values = [[float(e) for e in line] for line in errors]
    image = top.imshow(values, cmap="RdBu_r", aspect="auto",
                       norm=matplotlib.colors.SymLogNorm(linthresh=1e-3, vmin=-100, vmax=100))
    for i, a in enumerate(alphas):
        for j, s in enumerate(steps):
            r = table[(a, s)]
            top.text(j, i, f"{float(r['final_energy_error']):+.2g}\n{r['most_iterations']} it",
                     ha="center", va="center", fontsize=6.5)
    fig.colorbar(image, ax=top, label="(E_end − E0) / (m g h)")
    top.set_title("Energy balance error at 1 s and most Newton iterations in a step "
                  "(20 allowed: every step converged, none cut back)", fontsize=10)

    middle = fig.add_subplot(3, 1, 2)
    tight = [r for r in rows if r["max_iterations_allowed"] == "5"]
    alphas, steps, status, table = grid(tight, "status")
    names = list(STATUS_COLOURS)
    middle.imshow([[names.index(s) for s in line] for line in status], aspect="auto",
                  cmap=matplotlib.colors.ListedColormap(list(STATUS_COLOURS.values())), vmin=0,
                  vmax=len(names) - 1)
    for i, a in enumerate(alphas):
        for j, s in enumerate(steps):
            r = table[(a, s)]
            label = {"converged": "ok", "cut back": f"{r['cut_backs']} cuts",
                     "failed": f"failed\n{float(r['failed_at_s']):.3f} s"}[r["status"]]
            middle.text(j, i, label, ha="center", va="center", fontsize=6.5)
    middle.set_title("Newton with 5 iterations allowed: converged / cut back (Δt halved, up to "
                     "4 times) / failed (reported with time and residuals)", fontsize=10)
    for axis in (top, middle):
        axis.set_yticks(range(len(alphas)), [f"α = {a:g}" for a in alphas])
        axis.set_xticks(range(len(steps)), [f"{s * 1e3:.2g}" for s in steps], fontsize=8)
        axis.set_xlabel("Δt (ms)")
        axis.axvline(math.log10(t_c / steps[0]) * 4, color="black", lw=1.5, ls="--")
    middle.text(math.log10(t_c / steps[0]) * 4 + 0.1, len(alphas) - 0.6, "t_c (Hertz impact time)",
                fontsize=8)

    bottom = fig.add_subplot(3, 1, 3)
    for dt, style in (("0.0001", "-"), ("0.001", "--")):
        for alpha, colour in (("0", "tab:red"), ("-0.3", "tab:blue")):
            line = [r for r in history if r["dt_s"] == dt and r["alpha"] == alpha]
            bottom.plot([float(r["time_s"]) for r in line],
                        [float(r["energy_error"]) for r in line], style, color=colour,
                        label=f"Δt = {float(dt) * 1e3:g} ms, α = {alpha}")
    bottom.set_yscale("symlog", linthresh=1e-2)
    bottom.set_xlabel("time (s)")
    bottom.set_ylabel("(E − E0) / (m g h)")
    bottom.set_title("Energy over time: each impact moves the balance; Δt ≈ t_c creates energy",
                     fontsize=10)
    bottom.grid(alpha=0.3)
    bottom.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
