#!/usr/bin/env python3
"""Steady rolling against Carter, speed against accuracy (issue 15, "Verification: Steady rolling"
and "Speed against accuracy"): the case inputs/verification/contact_rolling_carter (a plane-strain
steel cylinder, R = 0.1 m, on a steel block, the block driven at V = 20 m/s and the cylinder's hub
turned 1.85e-3 faster than V / R, Coulomb mu = 0.3, bulk-modulus penalty) run for 1.2 ms with
contact-zone elements h = 0.25 (the case's), 0.1667 and 0.125 mm (inputs/meshes/
rolling_cylinder.geo with gmsh -setnumber h) and penalty factors f = 0.3, 1 (the case's) and 3,
plus the creep curve at the case's mesh (hub creepages 0.9e-3, 1.85e-3, 2.8e-3 and 3.5e-3 of
V / R) and one free-rolling run per mesh (the hub a rigid body with no torque: its mean angular
speed omega_free is the reference of the creepage, xi = omega / omega_free - 1).

Measured over the window 0.6-1.2 ms (after the 0.4 ms ramp of the hub's extra speed): the mean
creep force Q (tangential_1_N) and normal force P of the contact history, the hub's angular
speed from its end nodes' histories; at the patch written at 1.2 ms: the largest nodal
pressure, the half-width (outermost nodes in contact), the adhesion zone (nodes that stick) and
the RMS departure of the nodal shear traction from Carter's, relative to mu p0. Carter
(regression/studies/carter_rolling.py) at the measured P: the creep force at the measured
creepage, Q/(mu P) = 1 - (1 - xi R / (mu b))^2, and the patch at the measured Q.

    /usr/bin/python3 regression/studies/contact_rolling_speed_accuracy.py [build/bin/railfe]
        [--work DIR] [--jobs N] [--replot]

Writes docs/data/contact_rolling_speed_accuracy.csv (units in the column names) and
docs/img/contact_rolling_speed_accuracy.png (creep-force and peak-pressure error against wall
time, the creep curve, and the patch of the 0.125 mm, f = 1 run against Carter's shear, whose
nodes go to docs/data/contact_rolling_patch.csv). 13 runs (3 free, 10 driven), 36 min with
--jobs 2 on a 2-core machine shared with other work (about half that idle); run it with nice.
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
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import carter_rolling  # noqa: E402
from railfe_runs import (csv_rows, run_deck, step_section, study_parser,  # noqa: E402
                         typed_rows, write_rows)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "contact_rolling_carter", "deck.xml")
GEO = os.path.join(ROOT, "inputs", "meshes", "rolling_cylinder.geo")
CSV = os.path.join(ROOT, "docs", "data", "contact_rolling_speed_accuracy.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_rolling_speed_accuracy.png")
PATCH_CSV = os.path.join(ROOT, "docs", "data", "contact_rolling_patch.csv")
PATCH_RUN = (0.125, 1.0)  # the run whose patch is drawn against Carter's

SIZES_MM = [0.25, 0.1667, 0.125]
FACTORS = [0.3, 1.0, 3.0]
CURVE_CREEPAGES = [0.9e-3, 2.8e-3, 3.5e-3]  # the case's is 1.85e-3 (hub speed over V / R)
CASE_CREEPAGE = 1.85e-3
MU, SPEED = 0.3, 20.0
OMEGA_NOMINAL = SPEED / carter_rolling.RADIUS
END_TIME = 1.2e-3
WINDOW = (0.6e-3, 1.2e-3)
FREE_WINDOW = (0.2e-3, 1.2e-3)
PREWIND_PER_NEWTON = 2e-4 / 650.0  # rad/N: the case's pre-wind over its creep force


# --coarse: below issue 15's table (b/h = 8.5), towards the squeal demo's a/h = 2.2, so that its
# steady check has a tolerance for its mesh. The geometry script wants even element counts in its
# bands, so the bands' lengths are nudged to whole even numbers of elements. At 1 mm (b/h 2.1)
# the squeeze's CG + MueLu breaks down: not run.
COARSE_SIZES_MM = [0.5, 0.75]
COARSE_BANDS = {0.75: ["-setnumber", "xr", "27e-3", "-setnumber", "ds", "1.5e-3"]}
COARSE_CSV = os.path.join(ROOT, "docs", "data", "contact_rolling_coarse.csv")


def mesh_file(size_mm, work):
    """Generates the case's mesh with contact-zone elements of size_mm (Gmsh); returns its path."""
    path = os.path.join(work, f"rolling_cylinder_h{size_mm:g}mm.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h", repr(size_mm * 1e-3)]
                       + COARSE_BANDS.get(size_mm, []) + ["-o", path, GEO], check=True,
                       capture_output=True)
    return path


def hub_angle(creepage, prewind):
    """The hub's angle theta(t) (muParser, XML-escaped), as in the case's deck."""
    ramp = 4e-4
    step = f"(t &lt; {ramp:g} ? (t/{ramp:g})^3*(10 - 15*t/{ramp:g} + 6*(t/{ramp:g})^2) : 1)"
    integral = (f"(t &lt; {ramp:g} ? {ramp:g}*(t/{ramp:g})^4*(2.5 - 3*t/{ramp:g} + "
                f"(t/{ramp:g})^2) : t - {ramp / 2:g})")
    return f"({OMEGA_NOMINAL:g}*t + {OMEGA_NOMINAL * creepage!r}*{integral} + {prewind!r}*{step})"


def deck_text(mesh, factor, creepage=CASE_CREEPAGE, free=False):
    """The case's deck on `mesh` with penalty factor `factor`, the hub turning `creepage` faster
    than V / R (pre-wound in proportion to Carter's creep force there), run to END_TIME; with
    `free`, the hub is a rigid body with no torque instead (free rolling)."""
    text = open(DECK).read()
    text = re.sub(r"<!--.*?-->\s*", "", text, flags=re.S)
    text = text.replace('value="../../meshes/rolling_cylinder.msh"', f'value="{mesh}"')
    old = '<Parameter name="Penalty factor" type="double" value="1"/>'
    assert text.count(old) == 2
    text = text.replace(old, f'<Parameter name="Penalty factor" type="double" value="{factor!r}"/>')
    if mesh.endswith("h0.75mm.msh"):
        # On these facets the squeeze's linearisation stalls at 5.2e-4 of the force, just above
        # the case's 5e-4 (the limit its message names): 2e-3 accepts it.
        old_tolerance = '<Parameter name="Contact tolerance" type="double" value="5e-4"/>'
        assert text.count(old_tolerance) == 1
        text = text.replace(old_tolerance, old_tolerance.replace("5e-4", "2e-3"))
    text = text.replace('<Parameter name="End time" type="double" value="8e-4"/>',
                        f'<Parameter name="End time" type="double" value="{END_TIME!r}"/>')
    text = text.replace('value="{6e-4, 8e-4}"', f'value="{{{END_TIME!r}}}"')
    theta = re.search(r'value="x\*\(cos\((.*)\) - 1\)"', text).group(1)
    if not free:
        ratio = carter_rolling.carter_force_ratio(4.1e6, creepage, MU)
        prewind = PREWIND_PER_NEWTON * ratio * MU * 4100.0
        return text.replace(theta, hub_angle(creepage, prewind))
    # Only the explicit step changes: its hub becomes a rigid body turning freely.
    head, roll = text.split('<ParameterList name="roll">')
    start = roll.index('<ParameterList name="hub x">')
    end = roll.index('<ParameterList name="plane strain">', start)
    roll = roll[:start] + roll[end:]
    held = '<Parameter name="Node set" type="string" value="all"/>'
    assert roll.count(held) == 1
    roll = roll.replace(held, held.replace('"all"', '"below hub"'))
    sets = '      <ParameterList name="hub right">'
    head = head.replace(sets, '''      <ParameterList name="below hub">
        <Parameter name="Box" type="Array(double)" value="{-1, 1, -1, 1, -1, 0.09999}"/>
      </ParameterList>
''' + sets, 1)
    hub = '''      <ParameterList name="Discrete parts">
        <ParameterList name="Rigid bodies">
          <ParameterList name="hub">
            <Parameter name="Node set" type="string" value="roller_top"/>
            <Parameter name="Reference point" type="Array(double)" value="{0, 0.0005, 0.1000001}"/>
            <Parameter name="Angular velocity" type="Array(double)" value="{0, 200, 0}"/>
            <Parameter name="Fixed translations" type="string" value="xyz"/>
            <Parameter name="Fixed rotations" type="string" value="xz"/>
          </ParameterList>
        </ParameterList>
      </ParameterList>
'''
    pairs = '      <ParameterList name="Contact pairs">'
    return head + '<ParameterList name="roll">' + roll.replace(pairs, hub + pairs, 1)


def free_rolling(size_mm, work, railfe):
    """Runs the free-rolling variant at size_mm (f = 1); returns (omega_free, wall time)."""
    mesh = mesh_file(size_mm, work)
    results, summary = run_deck(railfe, deck_text(mesh, 1.0, free=True), work,
                                f"free_h{size_mm:g}")
    t, theta = carter_rolling.hub_angle(csv_rows(os.path.join(results, "roll_histories.csv")))
    omega = carter_rolling.mean_rate(t, theta, FREE_WINDOW)
    print(f"free rolling h {size_mm:g} mm: omega_free {omega:.6f} rad/s "
          f"(V/R {OMEGA_NOMINAL:g}), {summary['Wall time']['total [s]']:.0f} s", flush=True)
    return omega, summary["Wall time"]["total [s]"]


def measure(size_mm, factor, creepage, omega_free, work, railfe):
    """Runs one driven case; returns the row of the study's table."""
    mesh = mesh_file(size_mm, work)
    name = f"roll_h{size_mm:g}_f{factor:g}_xi{creepage:g}"
    results, summary = run_deck(railfe, deck_text(mesh, factor, creepage), work, name)
    step = step_section(summary, "roll")
    row = {"element_size_mm": size_mm, "penalty_factor": factor,
           "hub_creepage_over_V/R": creepage, "elements": step["elements"],
           "steps": step["steps"], "wall_time_s": summary["Wall time"]["total [s]"],
           "omega_free_rad/s": omega_free}
    measured = carter_rolling.measure(results, "roll", "rolling", MU, WINDOW, 1, omega_free)
    contact = csv_rows(os.path.join(results, "roll_contact_rolling.csv"))
    window = [r for r in contact if WINDOW[0] <= float(r["time_s"]) <= WINDOW[1]]
    measured["creep_force_std_N"] = float(np.std([float(r["tangential_1_N"]) for r in window]))
    measured["normal_force_std_N"] = float(np.std([float(r["normal_force_N"]) for r in window]))
    energy = csv_rows(os.path.join(results, "roll_energy.csv"))
    measured["max_abs_energy_error"] = max(abs(float(r["energy_error"])) for r in energy)
    row.update(measured)
    print(f"h {size_mm:g} mm, f {factor:g}, hub creepage {creepage:g}: xi {row['creepage']:.4e}, "
          f"Q/muP {row['traction_ratio']:.4f} (Carter "
          f"{row['carter_force_ratio_at_creepage']:.4f}, "
          f"{row['creep_force_error']:+.2%}), p0 {row['p0_error']:+.2%}, b {row['b_error']:+.2%}, "
          f"adhesion {row['adhesion_error']:+.2%}, shear rms {row['shear_rms_error']:.3f}, "
          f"{row['wall_time_s']:.0f} s", flush=True)
    return row


def write_patch(row, work):
    """Writes the patch of the PATCH_RUN case with Hertz's pressure and Carter's shear at its
    measured P and Q (PATCH_CSV: one row per slave node in contact)."""
    size, factor = PATCH_RUN
    results = os.path.join(work, f"roll_h{size:g}_f{factor:g}_xi{CASE_CREEPAGE:g}_results")
    patch = csv_rows(os.path.join(results, "roll_contact_rolling_patch_1.csv"))
    load = row["normal_force_N"] / carter_rolling.THICKNESS
    reference = carter_rolling.carter(load, row["traction_ratio"], MU)
    with open(PATCH_CSV, "w") as out:
        out.write("s1_mm,pressure_MPa,shear_MPa,slipping,hertz_pressure_MPa,carter_shear_MPa\n")
        for r in sorted(patch, key=lambda r: float(r["s1_m"])):
            s = float(r["s1_m"])
            hertz = reference["p0"] * math.sqrt(max(0.0, 1 - (s / reference["b"]) ** 2))
            out.write(f"{s * 1e3!r},{float(r['pressure_Pa']) * 1e-6!r},"
                      f"{float(r['shear_1_Pa']) * 1e-6!r},{int(float(r['slipping']))},"
                      f"{hertz * 1e-6!r},{float(reference['shear'](s)) * 1e-6!r}\n")


def plot(rows):
    fig, grid = plt.subplots(2, 2, figsize=(13, 10))
    axes = grid.ravel()
    markers = {0.25: "o", 0.1667: "s", 0.125: "^"}
    colours = {f: f"C{k}" for k, f in enumerate(FACTORS)}
    case_rows = [r for r in rows if abs(r["hub_creepage_over_V/R"] - CASE_CREEPAGE) < 1e-9]
    for ax, key, label in [(axes[0], "creep_force_error", "creep force Q at the measured creepage"),
                           (axes[1], "p0_error", "peak pressure p0 (largest nodal pressure)")]:
        for row in case_rows:
            ax.plot(row["wall_time_s"], 100 * row[key], markers[row["element_size_mm"]],
                    color=colours[row["penalty_factor"]], ms=8)
            if key == "creep_force_error":
                ax.errorbar(row["wall_time_s"], 100 * row[key],
                            yerr=100 * row["creep_force_std_N"] / row["creep_force_N"],
                            color=colours[row["penalty_factor"]], capsize=3, lw=0.8)
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xscale("log")
        ax.set_xticks([60, 100, 200, 400, 800])
        ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("wall time of the run (s; one rank, two runs at a time on 2 cores)")
        ax.set_ylabel("error against Carter / Hertz (%)")
        ax.set_title(label, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    for size, marker in markers.items():
        axes[0].plot([], [], marker, color="0.4", label=f"h = {size:g} mm (b/h = "
                     f"{2.13 / size:.1f})")
    for factor, colour in colours.items():
        axes[0].plot([], [], "-", color=colour, lw=3, label=f"penalty factor f = {factor:g}")
    axes[0].legend(fontsize=8)
    ax = axes[2]
    xi = np.linspace(0, 4.5e-3, 200)
    curve = [r for r in rows if r["element_size_mm"] == 0.25 and r["penalty_factor"] == 1.0]
    load = np.mean([r["normal_force_N"] for r in curve]) / carter_rolling.THICKNESS
    ax.plot(1e3 * xi, [carter_rolling.carter_force_ratio(load, x, MU) for x in xi], "k-",
            label=f"Carter, P' = {load * 1e-6:.2f} MN/m")
    for r in sorted(curve, key=lambda r: r["creepage"]):
        ax.errorbar(1e3 * r["creepage"], r["traction_ratio"],
                    yerr=r["creep_force_std_N"] / (MU * r["normal_force_N"]), fmt="o",
                    color="C1", capsize=3)
    ax.plot([], [], "o", color="C1", label="railfe, h = 0.25 mm, f = 1 (bars: std over the "
            "window)")
    ax.set_xlabel("creepage xi = omega / omega_free - 1 (1e-3)")
    ax.set_ylabel("creep force Q / (mu P)")
    ax.set_title("creep curve", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    if os.path.exists(PATCH_CSV):
        patch = csv_rows(PATCH_CSV)
        ax = axes[3]
        run = next(r for r in rows if (r["element_size_mm"], r["penalty_factor"]) == PATCH_RUN
                   and abs(r["hub_creepage_over_V/R"] - CASE_CREEPAGE) < 1e-9)
        reference = carter_rolling.carter(run["normal_force_N"] / carter_rolling.THICKNESS,
                                          run["traction_ratio"], MU)
        x = np.linspace(-reference["b"], reference["b"], 801)
        ax.plot(1e3 * x, 1e-6 * MU * reference["p0"] * np.sqrt(1 - (x / reference["b"]) ** 2),
                "k:", lw=1, label="mu p, Hertz")
        ax.plot(1e3 * x, 1e-6 * reference["shear"](x), "k-", lw=1.5,
                label=f"q, Carter at the measured Q/(mu P) = {run['traction_ratio']:.3f}")
        for slip, marker, name in [(1, "x", "slipping"), (0, "o", "sticking")]:
            pick = [r for r in patch if int(r["slipping"]) == slip]
            ax.plot([float(r["s1_mm"]) for r in pick], [float(r["shear_MPa"]) for r in pick],
                    marker, color="C3", mfc="none", label=f"railfe nodal shear, {name}")
        ax.set_xlabel("s1 (mm; the contact moves towards +s1: leading edge on the right)")
        ax.set_ylabel("shear traction (MPa)")
        ax.set_title(f"patch at 1.2 ms, h = {PATCH_RUN[0]:g} mm, f = {PATCH_RUN[1]:g}",
                     fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Steady rolling in plane strain against Carter: steel cylinder R = 0.1 m on a "
                 "block, V = 20 m/s, mu = 0.3, P' ~ 4.1 MN/m (b ~ 2.13 mm); means over "
                 "0.6-1.2 ms", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_contact_rolling_speed_accuracy",
                          ROOT)
    parser.add_argument("--coarse", action="store_true",
                        help="only the coarse meshes (h = 0.5, 0.75 mm; f = 1, hub creepages "
                             "0.9e-3 and the case's), written to "
                             "docs/data/contact_rolling_coarse.csv")
    args = parser.parse_args()
    if args.coarse:
        os.makedirs(args.work, exist_ok=True)
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            free = {size: pool.submit(free_rolling, size, args.work, args.railfe)
                    for size in COARSE_SIZES_MM}
            rows = [pool.submit(measure, size, 1.0, creepage, free[size].result()[0],
                                args.work, args.railfe)
                    for size in COARSE_SIZES_MM for creepage in (0.9e-3, CASE_CREEPAGE)]
            rows = [row.result() for row in rows]
        write_rows(COARSE_CSV, rows)
        print(f"wrote {COARSE_CSV}")
        return
    if args.replot:
        rows = typed_rows(CSV, ("elements", "steps"))
        plot(rows)
        print(f"wrote {PNG}")
        return
    os.makedirs(args.work, exist_ok=True)
    for size in SIZES_MM:
        mesh_file(size, args.work)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        free = {size: pool.submit(free_rolling, size, args.work, args.railfe)
                for size in SIZES_MM}
        omega_free = {size: free[size].result()[0] for size in SIZES_MM}
        cases = [(0.25, f, CASE_CREEPAGE) for f in FACTORS]
        cases += [(0.25, 1.0, xi) for xi in CURVE_CREEPAGES]
        cases += [(0.1667, 1.0, CASE_CREEPAGE)]
        cases += [(0.125, f, CASE_CREEPAGE) for f in FACTORS]
        futures = {case: pool.submit(measure, *case, omega_free[case[0]], args.work, args.railfe)
                   for case in reversed(cases)}
        rows = [futures[case].result() for case in cases]
    write_rows(CSV, rows)
    write_patch(next(r for r in rows if (r["element_size_mm"], r["penalty_factor"]) == PATCH_RUN
                     and r["hub_creepage_over_V/R"] == CASE_CREEPAGE), args.work)
    plot(rows)
    print(f"wrote {CSV}, {PATCH_CSV} and {PNG}")


if __name__ == "__main__":
    main()
