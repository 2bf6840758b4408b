#!/usr/bin/env python3
"""Speed against accuracy of the wheel's modes for both hex8 formulations: the default wheel
(S1002 tread, bore fixed on a rigid axle) at several element sizes with the fully integrated
hex8 and with the enhanced-strain hex8 (Materials/.../Element), its first N elastic modes
(default 30) against the Richardson extrapolation (O(h^2)) of the two finest meshes of one
formulation (--reference; the docs use the enhanced 14 and 10 mm runs), charted against DOFs
and wall time. The scene's density (inputs/scenes/wheel_modes.xml) is chosen from it.

    nice /usr/bin/python3 regression/studies/wheel_convergence.py build/bin/railfe \\
        [--sizes ...] [--enhanced-sizes ...] [--reference ELEMENT | --reference-csv CSV] [--reuse]

The 10 mm runs take minutes; --reuse takes the runs already in docs/data/wheel_convergence*.csv
and runs only the others; --reference-csv takes the extrapolated frequencies from an earlier
run's table instead (docs/data/wheel_convergence_reference.csv: the fully integrated series
30/20/14/10 mm and its extrapolation), after checking that the coarsest fully integrated run
reproduces that table's column of the same size (same mesh, same model). The defaults are the
docs' figures.

Writes docs/data/wheel_convergence.csv, docs/data/wheel_convergence_modes.csv and
docs/img/wheel_convergence.png.
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
FULL, ENHANCED = "full integration", "enhanced strain"


def element_deck(size, modes, element):
    """The wheel's modal deck with the material's Element set to `element`."""
    text = wheel_modal_deck(size, modes)
    blocks = '      <Parameter name="Blocks"'
    assert text.count(blocks) == 1
    return text.replace(blocks, f'      <Parameter name="Element" type="string" value="{element}"/>\n'
                        + blocks)


def run(railfe, element, size, modes, work):
    print(f"{element}, element size {size} m", flush=True)
    results, summary = run_deck(railfe, element_deck(size, modes, element), work,
                                f"wheel_{element.replace(' ', '_')}_{size}")
    step = step_section(summary, "wheel")
    frequencies = np.array([float(m["frequency_hz"])
                            for m in csv_rows(os.path.join(results, "wheel_modes.csv"))])
    wall = summary["Wall time"]["total [s]"]
    print(f"  {step['degrees of freedom']} DOFs, {wall:.1f} s, f1 {frequencies[0]:.2f} Hz, "
          f"f{modes} {frequencies[-1]:.2f} Hz", flush=True)
    return {"element": element, "size": size, "dofs": int(step["degrees of freedom"]),
            "wall": wall, "frequencies": frequencies}


def stored_runs(modes):
    """The runs of docs/data/wheel_convergence.csv with their frequencies from
    wheel_convergence_modes.csv, keyed by (element, size)."""
    data = os.path.join(ROOT, "docs", "data")
    table = csv_rows(os.path.join(data, "wheel_convergence_modes.csv"))[:modes]
    runs = {}
    for row in csv_rows(os.path.join(data, "wheel_convergence.csv")):
        element, size = row["element"], float(row["element_size_m"])
        column = f"f_hz_{element.replace(' ', '_')}_{row['element_size_m']}m"
        runs[(element, size)] = {"element": element, "size": size, "dofs": int(row["dofs"]),
                                 "wall": float(row["wall_s"]),
                                 "frequencies": np.array([float(m[column]) for m in table])}
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("railfe")
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.03, 0.02, 0.014],
                        help="element sizes of the fully integrated runs")
    parser.add_argument("--enhanced-sizes", type=float, nargs="+",
                        default=[0.04, 0.03, 0.02, 0.014, 0.01],
                        help="element sizes of the enhanced-strain runs")
    parser.add_argument("--reference-csv", help="take the extrapolated frequencies from here")
    parser.add_argument("--reference", choices=(FULL, ENHANCED), default=ENHANCED,
                        help="whose two finest runs give the O(h^2) extrapolated reference")
    parser.add_argument("--reuse", action="store_true",
                        help="take the runs stored in docs/data/wheel_convergence*.csv and run "
                        "only the sizes not stored there (their wall times were measured then)")
    parser.add_argument("--modes", type=int, default=30)
    parser.add_argument("--work", default="/tmp/railfe_wheel_convergence")
    args = parser.parse_args()
    railfe = os.path.abspath(args.railfe)
    stored = stored_runs(args.modes) if args.reuse else {}
    runs = [stored.get((element, size)) or run(railfe, element, size, args.modes, args.work)
            for element, sizes in ((FULL, args.sizes), (ENHANCED, args.enhanced_sizes))
            for size in sizes]
    full = [r for r in runs if r["element"] == FULL]
    if args.reference_csv:
        table = csv_rows(args.reference_csv)
        reference = np.array([float(row["extrapolated_hz"]) for row in table])[:args.modes]
        stored = np.array([float(row[f"f_hz_at_{full[0]['size']}m"]) for row in table])
        drift = np.abs(full[0]["frequencies"] - stored[:args.modes]).max() / reference.min()
        print(f"{full[0]['size']} m run against the stored one: largest difference "
              f"{drift:.1e} (relative)")
        if drift > 1e-6:
            raise SystemExit("the stored reference is from another model: run without it")
    else:
        finest = [r for r in runs if r["element"] == args.reference][-2:]
        (h1, f1), (h2, f2) = [(r["size"], r["frequencies"]) for r in finest]
        reference = f2 - (f1 - f2) * h2 ** 2 / (h1 ** 2 - h2 ** 2)
    for r in runs:
        error = np.abs(r["frequencies"] - reference) / reference
        r["max"], r["mean"] = 100 * error.max(), 100 * error.mean()
    with open(os.path.join(ROOT, "docs", "data", "wheel_convergence.csv"), "w") as out:
        out.write("element,element_size_m,dofs,wall_s,max_error_percent,mean_error_percent\n")
        for r in runs:
            out.write(f"{r['element']},{r['size']},{r['dofs']},{r['wall']:.2f},{r['max']:.3f},"
                      f"{r['mean']:.3f}\n")
    with open(os.path.join(ROOT, "docs", "data", "wheel_convergence_modes.csv"), "w") as out:
        out.write("mode," + ",".join(f"f_hz_{r['element'].replace(' ', '_')}_{r['size']}m"
                                     for r in runs) + ",extrapolated_hz\n")
        for k in range(len(reference)):
            out.write(f"{k + 1}," + ",".join(f"{r['frequencies'][k]:.4f}" for r in runs) +
                      f",{reference[k]:.4f}\n")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3))
    for ax, key, label in ((axes[0], "dofs", "degrees of freedom"),
                           (axes[1], "wall", "wall time of the whole run, 1 core (s)")):
        for element, color in ((FULL, "tab:blue"), (ENHANCED, "tab:red")):
            series = [r for r in runs if r["element"] == element]
            x = [r[key] for r in series]
            ax.loglog(x, [r["max"] for r in series], "o-", color=color,
                      label=f"{element}: largest of the first {args.modes}")
            ax.loglog(x, [r["mean"] for r in series], "s--", color=color, alpha=0.6,
                      label=f"{element}: mean")
            for r in series:
                ax.annotate(f"{1000 * r['size']:g} mm", (r[key], r["max"]),
                            textcoords="offset points", xytext=(4, 4), fontsize=7, color=color)
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_xlabel(label)
        ax.set_ylabel("frequency error (%)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    source = (f"the stored {args.reference_csv}" if args.reference_csv else
              f"the O(h^2) extrapolation of the {args.reference} "
              f"{1000 * finest[0]['size']:g} and {1000 * finest[1]['size']:g} mm runs")
    fig.suptitle(f"wheel modes (hex8 formulations, consistent mass): error against {source}",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "wheel_convergence.png"), dpi=120)
    for r in runs:
        print(f"{r['element']:17s} {r['size']:.3f} m  {r['dofs']:8d} DOFs  {r['wall']:7.1f} s  "
              f"max {r['max']:.2f} %  mean {r['mean']:.2f} %")


if __name__ == "__main__":
    main()
