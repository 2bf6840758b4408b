#!/usr/bin/env python3
"""Speed against accuracy of the rigid contact table (S1002 on 60E1 1:40, +-15 mm): for table
steps from 1 mm to 5 um, the time to build it against the error of its linearly interpolated
rolling radius difference (median and RMS over 15 001 shifts, against a 2 um table) and of the
flange contact shift. The median shows the smooth stretches (second order in the step); the RMS
is dominated by the contact jumps, which interpolation smears over one step.

    /usr/bin/python3 regression/studies/contact_table_resolution.py build/bin/railfe-contact-geometry

Writes docs/data/contact_table_resolution.csv and docs/img/contact_table_resolution.png.
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "contact_table_resolution.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_table_resolution.png")


def main():
    tool = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe-contact-geometry")
    subprocess.run([tool, "resolution", CSV], check=True)
    with open(CSV) as f:
        rows = list(csv.DictReader(f))
    time = [float(r["build_s"]) for r in rows]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for column, label, style in [("delta_r_median_error_m", "Δr, median error", "o-"),
                                 ("delta_r_rms_error_m", "Δr, RMS error (contact jumps)", "s-"),
                                 ("flange_shift_error_m", "flange contact shift error", "^-")]:
        ax.loglog(time, [max(float(r[column]), 1e-12) for r in rows], style, label=label)
    for r, t in zip(rows, time):
        ax.annotate(f"{1e3 * float(r['resolution_m']):g} mm", (t, float(r["delta_r_median_error_m"])),
                    textcoords="offset points", xytext=(4, -10), fontsize=7)
    ax.axvline(1.0, color="grey", ls="--", lw=0.8)
    ax.text(0.95, 1e-3, "issue: 1 s for\n3000 shifts ", fontsize=8, va="top", ha="right")
    ax.set_xlabel("table build time, one core (s)")
    ax.set_ylabel("error (m)")
    ax.set_title("Contact table, S1002 on 60E1 1:40, ±15 mm: build time against accuracy")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
