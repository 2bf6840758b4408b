#!/usr/bin/env python3
"""Cattaneo-Mindlin partial slip of explicit penalty contact with Coulomb friction (issue 15,
"Verification: Cattaneo-Mindlin"): the case inputs/verification/contact_cattaneo_mindlin (the
Hertz cylinder, R = 0.1 m on a block, plane strain, P' = 4e6 N/m, mu = 0.3, pushed sideways by a
rigid, non-rotating top face) loaded tangentially in three equal steps, Q'/(mu P') = 0.25, 0.5,
0.75 (each ramped over 0.3 ms and held 0.3 ms), at contact-zone elements h = 0.25, 0.125 (the
case's) and 0.0625 mm (inputs/meshes/hertz_cylinder.geo with gmsh -setnumber h) and bulk-modulus
penalty factors f = 0.3, 1 (the case's) and 3. Every run uses the safety factor 0.6 (the case
runs at 0.9; the Hertz study's 0.25 mm mesh grows without bound at 0.9).

Closed form (Johnson, Contact Mechanics, 1985, ch. 4 and section 7.2; two equal steels, so the
normal and tangential problems do not couple): 1/E* = 2 (1 - nu^2)/E,
b = sqrt(4 P' R / (pi E*)), p0 = 2 P' / (pi b), s = Q'/(mu P'),
  stick zone |x| < c = b sqrt(1 - s), slip zones c < |x| < b with |q| = mu p,
  q(x) = mu p0 sqrt(1 - x^2/b^2) - mu p0 (c/b) sqrt(1 - x^2/c^2) in the stick zone.
Tangential compliance in 2-D (derived in docs/theory.md#cattaneo-mindlin-line-contact from the
half-plane's surface displacement, Johnson ch. 2, with the stick correction above): the
relative tangential displacement of two points, one in each body, is
  delta(Q') = delta_0 + L Q' + (2 / (pi E*)) (mu P' - Q') ln sqrt(1 - s),
where L depends on where the points are (the 2-D displacement is defined only up to such a
term). The study fits delta_0, L and the factor A of (mu P' - Q') ln sqrt(1 - s) to the
displacement of the cylinder's axis 12 mm above the contact relative to the block's 12 mm below,
against the contact's own tangential force, over the whole tangential loading, and compares A
with 2 / (pi E*).

Measured at the end of each hold (patch CSV: one row per slave node in contact):
  c_node   the outermost sticking node (slipping = 0), the mean of both sides (the case's check)
  c_fit    least-squares fit of the stick correction mu p - q = mu p0 (c/b) sqrt(1 - x^2/c^2)
           (an ellipse, as in the Hertz study) to the sticking nodes, with the nodal pressure p
  q0       the shear at the nodes within h/2 of the centre, against mu p0 (1 - c/b)
  q_error  the largest |q - q(x)| over the nodes in contact, as a fraction of mu p0 (max, rms),
           and over the stick zone less its outermost node (stick_max: |x| < c - h)
References use the applied s; s_contact = Q'/(mu N) from the contact's own forces at the same
time is written too (it differs by the ramp's lag, 0.3-0.5 %).

    /usr/bin/python3 regression/studies/contact_cattaneo_mindlin.py [build/bin/railfe]
        [--work DIR] [--jobs N] [--replot]

Writes docs/data/contact_cattaneo_mindlin.csv (one row per run and load level) and
docs/img/contact_cattaneo_mindlin.png. Seven runs, two at a time (the finest mesh takes most of
the time); --replot redraws the chart from the CSV file and the kept results in --work, --reuse
measures the kept results again without running railfe.
"""
import concurrent.futures
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import (csv_rows, run_deck, step_section, study_parser,  # noqa: E402
                         typed_rows, write_rows)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "contact_cattaneo_mindlin", "deck.xml")
GEO = os.path.join(ROOT, "inputs", "meshes", "hertz_cylinder.geo")
CSV = os.path.join(ROOT, "docs", "data", "contact_cattaneo_mindlin.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_cattaneo_mindlin.png")

RUNS = [(0.25, 1.0), (0.125, 1.0), (0.0625, 1.0), (0.25, 0.3), (0.125, 0.3), (0.25, 3.0),
        (0.125, 3.0)]
LEVELS = [0.25, 0.5, 0.75]  # Q' / (mu P') at the end of each hold
RAMP, HOLD, PRESS = 3e-4, 3e-4, 6e-4  # s
SAFETY = 0.6

YOUNG, POISSON, RADIUS, MU = 210e9, 0.3, 0.1, 0.3
LOAD_PER_LENGTH = 4e6  # N/m
THICKNESS = 1e-3       # m
NORMAL = LOAD_PER_LENGTH * THICKNESS
E_STAR = YOUNG / (2 * (1 - POISSON**2))
B = math.sqrt(4 * LOAD_PER_LENGTH * RADIUS / (math.pi * E_STAR))
P0 = 2 * LOAD_PER_LENGTH / (math.pi * B)
COMPLIANCE = 2 / (math.pi * E_STAR)  # m^2/N: factor of (mu P' - Q') ln sqrt(1 - s)


def stick_radius(s):
    return B * math.sqrt(1 - s)


def shear(x, s):
    """Cattaneo-Mindlin's shear traction q(x) (Pa) at load level s, on the block along +x."""
    c = stick_radius(s)
    x = np.asarray(x, dtype=float)
    full = MU * P0 * np.sqrt(np.clip(1 - x * x / B**2, 0, None))
    correction = MU * P0 * (c / B) * np.sqrt(np.clip(1 - x * x / c**2, 0, None))
    return full - correction


def hold_end(k):
    """End of the hold after the k-th tangential step (k = 1, 2, 3); 0 = after the normal load."""
    return PRESS + k * (RAMP + HOLD)


def mesh_file(size_mm, work):
    path = os.path.join(work, f"hertz_cylinder_h{size_mm:g}mm.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h", repr(size_mm * 1e-3),
                        "-o", path, GEO], check=True, capture_output=True)
    return path


def smoothstep(start):
    u = f"min(max((t - {start!r})/{RAMP!r}, 0), 1)"
    return f"{u}^2*(3 - 2*{u})"


def deck_text(mesh, factor):
    """The case's deck on `mesh` with penalty factor `factor`, loaded in three tangential steps."""
    text = re.sub(r"<!--.*?-->\s*", "", open(DECK).read(), flags=re.S)
    replacements = {
        'value="../../meshes/hertz_cylinder.msh"': f'value="{mesh}"',
        '<Parameter name="Penalty factor" type="double" value="1"/>':
            f'<Parameter name="Penalty factor" type="double" value="{factor!r}"/>',
        '<Parameter name="Safety factor" type="double" value="0.9"/>':
            f'<Parameter name="Safety factor" type="double" value="{SAFETY!r}"/>',
        '<Parameter name="End time" type="double" value="1.3e-3"/>':
            f'<Parameter name="End time" type="double" value="{hold_end(3)!r}"/>',
        'value="{6e-4, 1.3e-3}"': "value=\"{" + ", ".join(repr(hold_end(k)) for k in range(4))
                                  + "}\"",
        'value="{600, 0, 0}"': f'value="{{{MU * NORMAL * LEVELS[0]!r}, 0, 0}}"',
    }
    for old, new in replacements.items():
        assert old in text, old
        text = text.replace(old, new)
    function = " + ".join(smoothstep(PRESS + k * (RAMP + HOLD)) for k in range(3))
    text, n = re.subn(r'(<ParameterList name="tangential">.*?name="Function" type="string" '
                      r'value=")[^"]*"', lambda m: m.group(1) + function + '"', text, flags=re.S)
    assert n == 1
    return text


def ellipse_fit(x, y):
    """Fit of y^2 = A + B x + C x^2: returns (half-width, peak)."""
    matrix = np.vstack([np.ones_like(x), x, x * x]).T
    a, b, c = np.linalg.lstsq(matrix, y * y, rcond=None)[0]
    peak_squared = a - b * b / (4 * c)
    return math.sqrt(-peak_squared / c), math.sqrt(peak_squared)


def nearest(rows, time):
    return min(rows, key=lambda row: abs(float(row["time_s"]) - time))


def compliance_fit(results):
    """Fits delta = delta_0 + L Q + A (mu N - Q) ln sqrt(1 - Q/(mu N)) over the tangential loading;
    returns (A, L, samples)."""
    contact = csv_rows(os.path.join(results, "load_contact_mindlin.csv"))
    histories = csv_rows(os.path.join(results, "load_histories.csv"))
    by_time = {row["time_s"]: row for row in contact}
    q, n, delta = [], [], []
    for row in histories:
        if float(row["time_s"]) < PRESS or row["time_s"] not in by_time:
            continue
        q.append(-float(by_time[row["time_s"]]["tangential_1_N"]))
        n.append(float(by_time[row["time_s"]]["normal_force_N"]))
        delta.append(float(row["cylinder 12 mm above_displacement_x_m"]) -
                     float(row["block 12 mm below_displacement_x_m"]))
    q, n, delta = np.array(q) / THICKNESS, np.array(n) / THICKNESS, np.array(delta)
    s = q / (MU * n)
    shape = (MU * n - q) * np.log(np.sqrt(1 - s))
    matrix = np.vstack([np.ones_like(q), q, shape]).T
    delta_0, slope, factor = np.linalg.lstsq(matrix, delta, rcond=None)[0]
    return factor, slope, (s, delta - delta_0 - slope * q)


def measure(size_mm, factor, work, railfe, reuse=False):
    """Runs one mesh size and penalty factor (or reads the kept results with `reuse`); returns
    one row per load level."""
    mesh = mesh_file(size_mm, work)
    name = f"mindlin_h{size_mm:g}_f{factor:g}"
    results = os.path.join(work, name + "_results")
    if reuse and os.path.exists(os.path.join(results, "summary.json")):
        with open(os.path.join(results, "summary.json")) as kept:
            summary = json.load(kept)
    else:
        results, summary = run_deck(railfe, deck_text(mesh, factor), work, name)
    step = step_section(summary, "load")
    contact = csv_rows(os.path.join(results, "load_contact_mindlin.csv"))
    energy = csv_rows(os.path.join(results, "load_energy.csv"))
    factor_a, slope, _ = compliance_fit(results)
    start = csv_rows(os.path.join(results, "load_contact_mindlin_patch_1.csv"))
    rows = []
    for k, level in enumerate(LEVELS, start=1):
        patch = csv_rows(os.path.join(results, f"load_contact_mindlin_patch_{k + 1}.csv"))
        x = np.array([float(r["s1_m"]) for r in patch])
        p = np.array([float(r["pressure_Pa"]) for r in patch])
        q = -np.array([float(r["shear_1_Pa"]) for r in patch])
        stick = np.array([float(r["slipping"]) == 0 for r in patch])
        last = nearest(contact, hold_end(k))
        c = stick_radius(level)
        c_node = 0.5 * (x[stick].max() - x[stick].min())
        c_fit, _ = ellipse_fit(x[stick], MU * p[stick] - q[stick])
        centre = np.abs(x) <= 0.5e-3 * size_mm
        q0 = q[centre].mean()
        q0_exact = MU * P0 * (1 - c / B)
        ratio = np.abs(q[~stick]) / (MU * p[~stick])
        rows.append({
            "element_size_mm": size_mm,
            "penalty_factor": factor,
            "level": level,
            "s_contact": -float(last["tangential_1_N"]) / (MU * float(last["normal_force_N"])),
            "elements": step["elements"],
            "steps": step["steps"],
            "wall_time_s": summary["Wall time"]["total [s]"],
            "normal_force_error": float(last["normal_force_N"]) / NORMAL - 1,
            "slipping_after_normal_load": int(sum(float(r["slipping"]) for r in start)),
            "c_exact_mm": c * 1e3,
            "c_node_mm": c_node * 1e3,
            "c_node_error": c_node / c - 1,
            "c_fit_mm": c_fit * 1e3,
            "c_fit_error": c_fit / c - 1,
            "q0_exact_MPa": q0_exact * 1e-6,
            "q0_MPa": q0 * 1e-6,
            "q0_error": q0 / q0_exact - 1,
            "q_error_max": float(np.max(np.abs(q - shear(x, level)))) / (MU * P0),
            "q_error_stick_max": float(np.max(np.abs(q - shear(x, level))[
                stick & (np.abs(x) < c - 1e-3 * size_mm)])) / (MU * P0),
            "q_error_rms": float(np.sqrt(np.mean((q - shear(x, level))**2))) / (MU * P0),
            "slip_ratio_max_deviation": float(np.max(np.abs(ratio - 1))) if ratio.size else 0.0,
            "compliance_factor_m2_per_N": factor_a,
            "compliance_error": factor_a / COMPLIANCE - 1,
            "linear_compliance_m2_per_N": slope,
            "max_abs_energy_error": max(abs(float(r["energy_error"])) for r in energy),
        })
        r = rows[-1]
        print(f"h {size_mm:g} mm, f {factor:g}, s {level}: c_node {r['c_node_error']:+.2%}, "
              f"c_fit {r['c_fit_error']:+.2%}, q0 {r['q0_error']:+.2%}, q max err "
              f"{r['q_error_max']:.3f} mu p0 (stick zone {r['q_error_stick_max']:.3f}), "
              f"compliance {r['compliance_error']:+.2%}, "
              f"{r['wall_time_s']:.0f} s", flush=True)
    return rows


def plot(rows, work):
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    # (a) tractions of the case's mesh and penalty against the closed form
    ax = axes[0, 0]
    results = os.path.join(work, "mindlin_h0.125_f1_results")
    xs = np.linspace(-B, B, 801)
    for k, level in enumerate(LEVELS, start=1):
        colour = f"C{k - 1}"
        ax.plot(xs / B, shear(xs, level) / (MU * P0), color=colour, lw=1.2,
                label=f"Q'/(\u03bcP') = {level:g}: closed form, c/b = {math.sqrt(1 - level):.3f}")
        patch = csv_rows(os.path.join(results, f"load_contact_mindlin_patch_{k + 1}.csv"))
        x = np.array([float(r["s1_m"]) for r in patch])
        q = -np.array([float(r["shear_1_Pa"]) for r in patch])
        stick = np.array([float(r["slipping"]) == 0 for r in patch])
        ax.plot(x[stick] / B, q[stick] / (MU * P0), "o", color=colour, ms=4)
        ax.plot(x[~stick] / B, q[~stick] / (MU * P0), "o", color=colour, mfc="white", ms=4)
        c = math.sqrt(1 - level)
        ax.plot([-c, c], [-0.04 - 0.03 * k] * 2, color=colour, lw=3, solid_capstyle="butt")
    ax.plot(xs / B, np.sqrt(1 - xs**2 / B**2), "k--", lw=0.8, label="\u03bcp(x): the slip limit")
    ax.set_xlabel("x / b (about the force centre)")
    ax.set_ylabel("shear traction q / (\u03bc p0)")
    ax.set_title("h = 0.125 mm, f = 1: filled = stick, open = slip;\nbars: closed-form stick zones",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper center", ncol=2)
    ax.set_ylim(-0.16, 1.3)
    ax.grid(alpha=0.3)
    # (b) stick-zone error against load
    ax = axes[0, 1]
    styles = {0.25: ":", 0.125: "-", 0.0625: "--"}
    colours = {0.3: "C0", 1.0: "C1", 3.0: "C2"}
    for size, factor in RUNS:
        runs = [r for r in rows if r["element_size_mm"] == size and r["penalty_factor"] == factor]
        if not runs:
            continue
        levels = [r["level"] for r in runs]
        ax.plot(levels, np.clip([100 * r["c_node_error"] for r in runs], -7, 12),
                "o" + styles[size], color=colours[factor], mfc="none",
                label=f"h {size:g} mm, f {factor:g}")
        if factor == 1.0:
            ax.plot(levels, np.clip([100 * r["c_fit_error"] for r in runs], -7, 12),
                    "s" + styles[size], color="k", ms=4, lw=0.8,
                    label=f"h {size:g} mm, f 1: ellipse fit")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_ylim(-7, 12)
    ax.set_xticks(LEVELS)
    ax.set_xlabel("Q' / (\u03bc P')")
    ax.set_ylabel("stick half-width c: error against b \u221a(1 \u2212 Q'/\u03bcP') (%)")
    ax.set_title("open circles: outermost sticking node (the case's check, resolution h);\n"
                 "black squares: ellipse fit of \u03bcp \u2212 q over the sticking nodes",
                 fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    # (c) errors against element size at Q'/(mu P') = 0.5
    ax = axes[1, 0]
    for factor, colour in zip([0.3, 1.0, 3.0], ["C0", "C1", "C2"]):
        runs = sorted((r for r in rows if r["penalty_factor"] == factor and r["level"] == 0.5),
                      key=lambda r: r["element_size_mm"])
        h = [r["element_size_mm"] for r in runs]
        for key, style, label in [("c_node_error", "o-", "c: node"), ("c_fit_error", "s--",
                                  "c: fit"), ("q0_error", "^:", "q(0)")]:
            ax.plot(h, np.clip([100 * r[key] for r in runs], -4, 10), style, color=colour,
                    mfc="none",
                    label=f"f {factor:g}, {label}")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_ylim(-4, 10)
    ax.set_xscale("log")
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xticks([0.0625, 0.125, 0.25])
    ax.set_xticklabels(["0.0625", "0.125", "0.25"])
    ax.set_xlabel("contact-zone element size h (mm)")
    ax.set_ylabel("error against the closed form at Q'/(\u03bcP') = 0.5 (%)")
    ax.legend(fontsize=7, ncol=3)
    ax.grid(alpha=0.3)
    # (d) the nonlinear part of the compliance
    ax = axes[1, 1]
    s = np.linspace(0, 0.76, 100)
    ax.plot(s, 1e6 * COMPLIANCE * MU * LOAD_PER_LENGTH * (1 - s) * np.log(np.sqrt(1 - s)), "k-",
            lw=2, label="closed form (2/\u03c0E*)(\u03bcP' \u2212 Q') ln \u221a(1 \u2212 s)")
    for size, factor in RUNS:
        results = os.path.join(work, f"mindlin_h{size:g}_f{factor:g}_results")
        if not os.path.exists(os.path.join(results, "summary.json")):
            continue
        factor_a, slope, (s_run, nonlinear) = compliance_fit(results)
        ax.plot(s_run, 1e6 * nonlinear, styles[size], color=colours[factor], lw=0.9,
                label=f"h {size:g} mm, f {factor:g}: A/(2/\u03c0E*) \u2212 1 = "
                      f"{factor_a / COMPLIANCE - 1:+.1%}")
    ax.set_xlabel("Q' / (\u03bc P') of the contact's force along the loading")
    ax.set_ylabel("nonlinear part of the relative displacement (\u00b5m)")
    ax.set_title("axis points 12 mm above and below the contact; offset and linear part fitted",
                 fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.suptitle("Cattaneo\u2013Mindlin line contact: steel cylinder R = 0.1 m on a block, "
                 f"P' = 4 MN/m, \u03bc = 0.3; b = {B * 1e3:.3f} mm, \u03bcp0 = "
                 f"{MU * P0 * 1e-6:.1f} MPa\nexplicit penalty contact with Coulomb friction, "
                 "bulk-modulus penalty factor f, safety factor 0.6", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_contact_cattaneo_mindlin", ROOT)
    parser.add_argument("--reuse", action="store_true",
                        help="measure the kept results in --work instead of running railfe")
    args = parser.parse_args()
    if args.replot:
        rows = typed_rows(CSV, ("elements", "steps", "slipping_after_normal_load"))
        plot(rows, args.work)
        print(f"wrote {PNG}")
        return
    os.makedirs(args.work, exist_ok=True)
    for size in sorted({size for size, _ in RUNS}):
        mesh_file(size, args.work)
    # The longest first, so that two processes stay busy.
    order = sorted(RUNS, key=lambda run: (run[0], -run[1]))
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {run: pool.submit(measure, *run, args.work, args.railfe, args.reuse)
                   for run in order}
        rows = [row for run in RUNS for row in futures[run].result()]
    write_rows(CSV, rows)
    plot(rows, args.work)
    print(f"wrote {CSV} and {PNG}")


if __name__ == "__main__":
    main()
