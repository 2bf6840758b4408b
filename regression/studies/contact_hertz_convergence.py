#!/usr/bin/env python3
"""Convergence of explicit penalty contact to Hertz's line contact (issue 15, "Verification:
Hertz"): the case inputs/verification/contact_hertz_cylinder (the lower half of a steel cylinder,
R = 0.1 m, pressed on a steel block with P' = 4e6 N/m in plane strain, one 1 mm layer of fully
integrated hex8; force ramped over 0.3 ms and held to 0.6 ms with Rayleigh mass damping) run
with the contact-zone elements h = 0.25, 0.125 (the case's) and 0.0625 mm (the structured bands
of inputs/meshes/hertz_cylinder.geo, regenerated with gmsh -setnumber h) and bulk-modulus
penalty factors f = 0.3, 1 (the case's) and 3. Each run is compared with Hertz (2-D, two equal
steels): b = sqrt(4 P' R / (pi E*)) = 2.10093 mm, p0 = 2 P' / (pi b) = 1212.07 MPa, with
1/E* = 2 (1 - nu^2)/E.

Measured from the patch written at the end (press_contact_hertz_patch_1.csv: one row per slave
node in contact, pressure = nodal normal force / tributary area):
  b_node   the outermost node in contact, the mean of both sides (what the case checks)
  b_area   contact_area_m2 / (2 t): whole tributary areas, (n + 1/2) h for n nodes in contact
           on one side of the centre
  p0_node  the largest nodal pressure (what the case checks)
  b_fit, p0_fit  least-squares fit of Hertz's ellipse p^2 = p0^2 (1 - (s - c)^2 / b^2) to every
           node in contact (free of the one-node resolution of b_node and b_area)
Errors are relative to the closed form at the applied P'; force_error is the contact force's
departure from P' t at the end (b and p0 go with its square root).

    /usr/bin/python3 regression/studies/contact_hertz_convergence.py [build/bin/railfe]
        [--work DIR] [--jobs N] [--replot]

Writes docs/data/contact_hertz_convergence.csv (units in the column names) and
docs/img/contact_hertz_convergence.png (error against element size and against wall time). Nine
runs, 12.5 min on 2 cores with --jobs 2 (the default: two runs at a time, so the wall times are
those of a shared machine; the finest mesh takes about 6 min per run, the case's 43 s alone).
--replot redraws the chart from the CSV file.
"""
import concurrent.futures
import math
import os
import re
import subprocess
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.lines  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import (csv_rows, run_deck, step_section, study_parser,  # noqa: E402
                         typed_rows, write_rows)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "contact_hertz_cylinder", "deck.xml")
GEO = os.path.join(ROOT, "inputs", "meshes", "hertz_cylinder.geo")
CSV = os.path.join(ROOT, "docs", "data", "contact_hertz_convergence.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_hertz_convergence.png")

SIZES_MM = [0.25, 0.125, 0.0625]
FACTORS = [0.3, 1.0, 3.0]

YOUNG, POISSON, RADIUS = 210e9, 0.3, 0.1
LOAD_PER_LENGTH = 4e6  # N/m
THICKNESS = 1e-3       # m, the slice along y
E_STAR = YOUNG / (2 * (1 - POISSON**2))
B_HERTZ = math.sqrt(4 * LOAD_PER_LENGTH * RADIUS / (math.pi * E_STAR))
P0_HERTZ = 2 * LOAD_PER_LENGTH / (math.pi * B_HERTZ)


def mesh_file(size_mm, work):
    """Generates the case's mesh with contact-zone elements of size_mm (Gmsh); returns its path."""
    path = os.path.join(work, f"hertz_cylinder_h{size_mm:g}mm.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h", repr(size_mm * 1e-3),
                        "-o", path, GEO], check=True, capture_output=True)
    return path


def deck_text(mesh, factor):
    """The case's deck on `mesh` (absolute path) with penalty factor `factor`."""
    text = open(DECK).read()
    text = re.sub(r"<!--.*?-->\s*", "", text, flags=re.S)
    text = text.replace('value="../../meshes/hertz_cylinder.msh"', f'value="{mesh}"')
    old = '<Parameter name="Penalty factor" type="double" value="1"/>'
    assert old in text
    return text.replace(old, f'<Parameter name="Penalty factor" type="double" value="{factor!r}"/>')


def ellipse_fit(s, p):
    """Least-squares fit of p^2 = A + B s + C s^2 (Hertz's ellipse about a free centre):
    returns (b, p0)."""
    matrix = np.vstack([np.ones_like(s), s, s * s]).T
    a, b, c = np.linalg.lstsq(matrix, p * p, rcond=None)[0]
    peak_squared = a - b * b / (4 * c)
    return math.sqrt(-peak_squared / c), math.sqrt(peak_squared)


def measure(size_mm, factor, work, railfe):
    """Runs one mesh size and penalty factor; returns the row of the study's table."""
    mesh = mesh_file(size_mm, work)
    name = f"hertz_h{size_mm:g}_f{factor:g}"
    results, summary = run_deck(railfe, deck_text(mesh, factor), work, name)
    step = step_section(summary, "press")
    patch = csv_rows(os.path.join(results, "press_contact_hertz_patch_1.csv"))
    s = np.array([float(row["s1_m"]) for row in patch])
    p = np.array([float(row["pressure_Pa"]) for row in patch])
    history = csv_rows(os.path.join(results, "press_contact_hertz.csv"))
    last = history[-1]
    energy = csv_rows(os.path.join(results, "press_energy.csv"))
    b_node = 0.5 * (s.max() - s.min())
    b_area = float(last["contact_area_m2"]) / (2 * THICKNESS)
    b_fit, p0_fit = ellipse_fit(s, p)
    force = float(last["normal_force_N"])
    row = {
        "element_size_mm": size_mm,
        "penalty_factor": factor,
        "elements": step["elements"],
        "steps": step["steps"],
        "time_step_s": float(last["time_s"]) / step["steps"],
        "contact_critical_step_s": step["contact critical step [s]"],
        "wall_time_s": summary["Wall time"]["total [s]"],
        "contact_nodes": len(patch),
        "contact_force_N": force,
        "force_error": force / (LOAD_PER_LENGTH * THICKNESS) - 1,
        "b_node_mm": b_node * 1e3,
        "b_node_error": b_node / B_HERTZ - 1,
        "b_area_mm": b_area * 1e3,
        "b_area_error": b_area / B_HERTZ - 1,
        "b_fit_mm": b_fit * 1e3,
        "b_fit_error": b_fit / B_HERTZ - 1,
        "p0_node_MPa": p.max() * 1e-6,
        "p0_node_error": p.max() / P0_HERTZ - 1,
        "p0_fit_MPa": p0_fit * 1e-6,
        "p0_fit_error": p0_fit / P0_HERTZ - 1,
        "max_penetration_um": float(last["max_penetration_m"]) * 1e6,
        "max_abs_energy_error": max(abs(float(r["energy_error"])) for r in energy),
    }
    print(f"h {size_mm:g} mm, f {factor:g}: b_node {row['b_node_error']:+.2%}, b_fit "
          f"{row['b_fit_error']:+.2%}, p0_node {row['p0_node_error']:+.2%}, p0_fit "
          f"{row['p0_fit_error']:+.2%}, force {row['force_error']:+.2%}, "
          f"{row['wall_time_s']:.1f} s", flush=True)
    return row


def plot(rows):
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharey="row")
    colours = {f: f"C{k}" for k, f in enumerate(FACTORS)}
    limits = {"b": (-7, 15), "p0": (-7, 7)}
    estimators = [("node", "o-", "none"), ("fit", "s--", "white"), ("area", "^:", None)]
    for r, (key, label) in enumerate([("b", "half-width b"), ("p0", "peak pressure p0")]):
        low, high = limits[key]
        for factor in FACTORS:
            runs = sorted((row for row in rows if row["penalty_factor"] == factor),
                          key=lambda row: row["element_size_mm"])
            for c, x_key in enumerate(["element_size_mm", "wall_time_s"]):
                ax = axes[r, c]
                x = [row[x_key] for row in runs]
                for estimator, style, face in estimators:
                    column = ("b_area_error" if estimator == "area" else
                              f"{key}_{estimator}_error")
                    if estimator == "area" and key != "b":
                        continue
                    y = [100 * row[column] for row in runs]
                    ax.plot(x, np.clip(y, low, high), style, color=colours[factor],
                            mfc=face if face != "none" else colours[factor], ms=6 if face else 4)
                    for xi, yi in zip(x, y):
                        if yi > high or yi < low:
                            ax.annotate(f"{yi:+.0f} %: the centre node pair chatters",
                                        (xi, np.clip(yi, low, high)),
                                        xytext=(-10 if c == 0 else 10, -14 if yi > high else 8),
                                        textcoords="offset points",
                                        ha="right" if c == 0 else "left", fontsize=7,
                                        color=colours[factor])
        for c in range(2):
            ax = axes[r, c]
            ax.axhline(0, color="k", lw=0.8)
            for bound in (-5, 5):
                ax.axhline(bound, color="0.6", lw=0.8, ls=":")
            ax.set_xscale("log")
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.grid(True, which="both", alpha=0.3)
            ax.set_ylim(low, high)
        axes[r, 0].set_ylabel(f"{label}: error against Hertz (%)")
        axes[r, 0].set_xticks(SIZES_MM)
    axes[1, 0].set_xlabel("contact-zone element size h (mm)")
    axes[1, 1].set_xlabel("wall time of the run (s; one rank, two runs at a time on 2 cores)")
    axes[0, 0].set_title("against element size (b / h = 8.4, 17, 34)")
    axes[0, 1].set_title("against wall time")
    handles = [matplotlib.lines.Line2D([], [], color=colours[f], lw=2, label=f"penalty factor "
                                       f"f = {f:g}") for f in FACTORS]
    handles += [
        matplotlib.lines.Line2D([], [], color="0.3", marker="o", ls="-",
                                label="node value: outermost node in contact (b), largest "
                                      "nodal pressure (p0): the case's checks"),
        matplotlib.lines.Line2D([], [], color="0.3", marker="s", mfc="white", ls="--",
                                label="least-squares fit of Hertz's ellipse to the nodal "
                                      "pressures"),
        matplotlib.lines.Line2D([], [], color="0.3", marker="^", ms=4, ls=":",
                                label="contact area / 2t (b only)"),
    ]
    fig.legend(handles=handles, loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle("Hertz line contact, steel cylinder R = 0.1 m on a block, P' = 4 MN/m: "
                 f"b = {B_HERTZ * 1e3:.3f} mm, p0 = {P0_HERTZ * 1e-6:.0f} MPa\n"
                 "explicit penalty node-to-segment contact, bulk-modulus penalty; dotted grey: "
                 "the case's 5 % tolerance", fontsize=10)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.subplots_adjust(wspace=0.06)
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_contact_hertz_convergence", ROOT)
    args = parser.parse_args()
    if args.replot:
        rows = typed_rows(CSV, ("elements", "steps", "contact_nodes"))
        plot(rows)
        print(f"wrote {PNG}")
        return
    os.makedirs(args.work, exist_ok=True)
    for size in SIZES_MM:
        mesh_file(size, args.work)
    cases = [(size, factor) for size in reversed(SIZES_MM) for factor in FACTORS]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {case: pool.submit(measure, *case, args.work, args.railfe) for case in cases}
        rows = [futures[case].result() for case in cases]
    rows.sort(key=lambda row: (row["penalty_factor"], -row["element_size_mm"]))
    write_rows(CSV, rows)
    plot(rows)
    print(f"wrote {CSV} and {PNG}")


if __name__ == "__main__":
    main()
