#!/usr/bin/env python3
"""Speed against accuracy of the wheel's modes: the default wheel (S1002 tread, bore fixed on a
rigid axle) at four element sizes, its first N elastic modes (default 30) against the
Richardson extrapolation (O(h^2)) of the two finest meshes, charted against DOFs and wall time.
The deck's default density (inputs/scenes/wheel_modes.xml) is chosen from it.

    /usr/bin/python3 regression/studies/wheel_convergence.py build/bin/railfe [--sizes ...]

Writes docs/data/wheel_convergence.csv and docs/img/wheel_convergence.png.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import csv_rows, run_deck, step_section, wheel_modal_deck  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("railfe")
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.03, 0.02, 0.014, 0.01])
    parser.add_argument("--modes", type=int, default=30)
    parser.add_argument("--work", default="/tmp/railfe_wheel_convergence")
    args = parser.parse_args()
    runs = []
    for size in args.sizes:
        print(f"element size {size} m", flush=True)
        results, summary = run_deck(os.path.abspath(args.railfe), wheel_modal_deck(size, args.modes),
                                    args.work, f"wheel_{size}")
        step = step_section(summary, "wheel")
        frequencies = np.array([float(m["frequency_hz"])
                                for m in csv_rows(os.path.join(results, "wheel_modes.csv"))])
        wall = summary["Wall time"]["total [s]"]
        runs.append((size, int(step["degrees of freedom"]), wall, frequencies))
        print(f"  {runs[-1][1]} DOFs, {wall:.1f} s, f1 {frequencies[0]:.2f} Hz, "
              f"f{args.modes} {frequencies[-1]:.2f} Hz", flush=True)
    (h1, _, _, f1), (h2, _, _, f2) = runs[-2], runs[-1]
    reference = f2 - (f1 - f2) * h2 ** 2 / (h1 ** 2 - h2 ** 2)
    rows = []
    for size, dofs, wall, frequencies in runs:
        error = np.abs(frequencies - reference) / reference
        rows.append((size, dofs, wall, 100 * error.max(), 100 * error.mean()))
    data = os.path.join(ROOT, "docs", "data", "wheel_convergence.csv")
    with open(data, "w") as out:
        out.write("element_size_m,dofs,wall_s,max_error_percent,mean_error_percent\n")
        for row in rows:
            out.write("{},{},{:.2f},{:.3f},{:.3f}\n".format(*row))
    with open(os.path.join(ROOT, "docs", "data", "wheel_convergence_modes.csv"), "w") as out:
        out.write("mode," + ",".join(f"f_hz_at_{r[0]}m" for r in runs) + ",extrapolated_hz\n")
        for k in range(len(reference)):
            out.write(f"{k + 1}," + ",".join(f"{r[3][k]:.4f}" for r in runs) +
                      f",{reference[k]:.4f}\n")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, column, label in ((axes[0], 1, "degrees of freedom"), (axes[1], 2, "wall time (s)")):
        x = [r[column] for r in rows]
        ax.loglog(x, [r[3] for r in rows], "o-", label=f"largest of the first {args.modes}")
        ax.loglog(x, [r[4] for r in rows], "s--", label="mean")
        for r in rows:
            ax.annotate(f"{1000 * r[0]:g} mm", (r[column], r[3]), textcoords="offset points",
                        xytext=(4, 4), fontsize=8)
        ax.set_xlabel(label)
        ax.set_ylabel("frequency error (%)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("wheel modes: error against the extrapolated frequencies (hex8, consistent mass)")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "wheel_convergence.png"), dpi=120)
    for row in rows:
        print("{:.3f} m  {:8d} DOFs  {:7.1f} s  max {:.2f} %  mean {:.2f} %".format(*row))


if __name__ == "__main__":
    main()
