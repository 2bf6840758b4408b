#!/usr/bin/env python3
"""Where the online contact search breaks: the S1002 wheel on the 60E1 rail (Manchester
benchmark profiles), right wheel, shifts 0 to 15 mm in the rigid wheelset's pose from a 0.01 mm
table. Four searches per shift: plain Newton or trust region, started from the centred contact or
from a 0.25 mm lookup table. A search is correct when it returns a valid point at the table's
contact (rail y within 1 nm).

    /usr/bin/python3 regression/studies/contact_search_stability.py build/bin/railfe-contact-geometry

Writes docs/data/contact_search_stability.csv and docs/img/contact_search_stability.png.
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "contact_search_stability.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_search_stability.png")


def main():
    tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe-contact-geometry")
    subprocess.run([tool, "stability", CSV], check=True)
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    flange = min(float(r["shift_mm"]) for r in rows if r["part"] == "flange")
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True, sharey=True)
    for ax, (method, start) in zip(axes.flat, [("plain Newton", "centred"), ("plain Newton", "table"),
                                              ("trust region", "centred"), ("trust region", "table")]):
        mine = [r for r in rows if r["method"] == method and r["start"] == start]
        good = [r for r in mine if r["correct"] == "1"]
        bad = [r for r in mine if r["correct"] == "0"]
        ax.scatter([float(r["shift_mm"]) for r in good], [int(r["iterations"]) for r in good], s=6,
                   color="tab:green", label=f"correct ({len(good)})")
        for status, colour in [("part boundary", "tab:orange"), ("not converged", "tab:red"),
                               ("not a minimum", "tab:purple"), ("converged", "tab:blue")]:
            these = [r for r in bad if r["status"] == status]
            if these:
                label = "another minimum" if status == "converged" else status
                ax.scatter([float(r["shift_mm"]) for r in these], [int(r["iterations"]) for r in these],
                           s=10, marker="x", color=colour, label=f"{label} ({len(these)})")
        ax.axvline(flange, color="grey", lw=0.8, ls="--")
        ax.set_title(f"{method}, {start} start ({len(good)}/{len(mine)} correct)", fontsize=10)
        ax.set_yscale("log")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    for ax in axes[1]:
        ax.set_xlabel("lateral shift towards the right flange (mm)")
    for ax in axes[:, 0]:
        ax.set_ylabel("Newton iterations")
    fig.suptitle(f"Online contact search, S1002 on 60E1 1:40 (dashed: flange contact from {flange:.2f} mm)")
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
