#!/usr/bin/env python3
"""Frequency against number of nodal diameters, one line per family and number of nodal
circles, as wheel modes are drawn in the literature. Reads a modal step's <step>_modes.csv.

    python3 regression/charts/mode_chart.py wheel_modes.csv wheel_modes.png [--max-hz 10000]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

STYLE = {"axial": ("tab:blue", "o"), "radial": ("tab:red", "s"),
         "circumferential": ("tab:green", "^")}


def read_modes(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("modes_csv")
    parser.add_argument("png")
    parser.add_argument("--max-hz", type=float, default=None)
    args = parser.parse_args()
    rows = read_modes(args.modes_csv)
    series = {}
    ambiguous = []
    seen = set()
    for row in rows:
        f = float(row["frequency_hz"])
        if f < 1.0 or (args.max_hz and f > args.max_hz):
            continue  # rigid-body modes and what lies beyond the band
        family, n, m = row["family"], int(row["nodal_diameters"]), int(row["nodal_circles"])
        if family not in STYLE or n < 0 or m < 0:
            ambiguous.append((max(n, 0), f))
            continue
        key = (family, m, n)
        if key in seen:
            continue  # the doublet partner has the same frequency
        seen.add(key)
        series.setdefault((family, m), []).append((n, f))
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for (family, m), points in sorted(series.items()):
        points.sort()
        colour, marker = STYLE[family]
        line = "-" if m == 0 else "--" if m == 1 else ":"
        ax.plot([p[0] for p in points], [p[1] for p in points], line, color=colour,
                marker=marker, label=f"{family}, {m} nodal circle{'s' if m != 1 else ''}")
    if ambiguous:
        ax.plot([a[0] for a in ambiguous], [a[1] for a in ambiguous], "x", color="grey",
                label="ambiguous")
    ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_xlabel("number of nodal diameters n")
    ax.set_ylabel("frequency (Hz)")
    ax.set_title(args.modes_csv.split("/")[-1].replace(".part", ""))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, format="png", dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
