#!/usr/bin/env python3
"""Where the exact steady-rolling solver breaks under friction that falls with slip velocity,
mu = mu_d + (mu_s - mu_d) exp(-c |v|): the issue's Hertz patch (0.46 m wheel on a 0.30 m crown,
100 kN), 20 x 20 grid, xi = 2e-3, V = 30 m/s, mu_s = 0.4. Each case is solved from no traction
and from full slip; where the two steady states differ by more than 1e-6 mu_s N the solver
reports "not unique" and returns no force.

    /usr/bin/python3 regression/studies/contact_falling_friction.py [build/bin/railfe-contact-mechanics]

Writes docs/data/contact_falling_friction.csv and docs/img/contact_falling_friction.png.
"""
import csv
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "contact_falling_friction.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_falling_friction.png")


def main():
    tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe-contact-mechanics")
    subprocess.run([tool, "falling-friction", CSV], check=True)
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    drops = [float(r["mu_static"]) - float(r["mu_dynamic"]) for r in rows]
    decays = [max(float(r["decay_s_per_m"]), 0.3) for r in rows]  # c = 0 drawn at the left edge
    spreads = [max(float(r["spread_of_starts"]), 1e-16) for r in rows]
    scatter = ax.scatter(decays, drops, c=[math.log10(s) for s in spreads], cmap="viridis", s=120,
                         marker="s", vmin=-16, vmax=-2)
    refused = [(d, m) for d, m, r in zip(decays, drops, rows) if r["unique"] == "0"]
    ax.scatter([d for d, _ in refused], [m for _, m in refused], s=160, facecolors="none",
               edgecolors="red", linewidths=1.5, label=f"reported not unique ({len(refused)})")
    ax.set_xscale("log")
    ax.set_xlabel("decay c (s/m; c = 0 drawn at 0.3)")
    ax.set_ylabel("friction drop μs − μd")
    ax.set_title("Exact steady rolling with falling friction: spread between two starts")
    fig.colorbar(scatter, label="log10 |ΔF| / (μs N)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
