#!/usr/bin/env python3
"""A finite-element contact patch beside the exact steady-rolling solver's patch for the same
forces (the squeal scene's Table 3 and Figs. 6-7): sums FN, Fx, Fy of one patch file
<step>_contact_<pair>_patch_<k>.csv (pressure and shear times each node's area_m2), runs railfe's
"contact patch" step with Prescribe forces (the exact solver finds the creepages that carry Fx,
Fy) on a Hertz patch of the same normal load, and writes

- a Table-3 row (FN, Fx, Fy, the semi-axes used, the creepages found, adhesion shares) appended
  to --table (header when new);
- a PNG: the FE patch (pressure with shear arrows; stick and slip nodes with micro-slip) above
  the exact solver's (the same, its slip times --speed).

The Hertz patch's semi-axes come from --geometry: "moments" (default) a = sqrt(5 <s1^2>),
b = sqrt(5 <s2^2>), the pressure-weighted second moments about the centre, which a Hertz
ellipse meets exactly and a coarse mesh's few nodes do not bias as their extent does; "extent":
half the nodes' extent plus half a node spacing; or "curvatures A B" (1/m): Hertz from the
relative curvatures of the profiles. Or no ellipse: "separation" gives the exact solver the
undeformed separation A x^2 + s(y) of the real profiles (--separation, a CSV of y, s and
optionally the rolling radius R(y), as the contact patch step's Separation file takes it; --A
the longitudinal curvature), as CONTACT takes profiles; a and b are then the exact patch's
moments. Its y must be the FE's s2 direction. Forces are the FE's on the slave body (the wheel) in the
patch's frame (s1 along the rolling direction, s2 = n x s1): the exact solver takes them as body
1's, with x = s1 and y = s2; spin from --spin (default 0: the patch file does not hold it).

    /usr/bin/python3 regression/charts/patch_vs_exact.py --railfe build/bin/railfe --mu 0.45 \\
        --table table3.csv --png patch_vs_exact.png --work /tmp/pve roll_contact_wheel-rail_patch_1.csv
"""
import argparse
import csv
import math
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "studies")]
from contact_patch_map import (pressure_shear_panel, shear_angle_panel, shear_angles,  # noqa: E402
                               slip_panel)
from patch_centre_line import node_spacing, read_patch  # noqa: E402
from railfe_runs import csv_rows, run_deck  # noqa: E402

DECK = """<!-- Written by regression/charts/patch_vs_exact.py for {patch} -->
<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="Exact solver's patch for the forces of an FE patch"/>
  <ParameterList name="Steps">
    <ParameterList name="exact">
      <Parameter name="Module" type="string" value="contact patch"/>
{geometry}
      <Parameter name="Normal load" type="double" value="{FN!r}"/>
      <Parameter name="Young's modulus" type="double" value="{E!r}"/>
      <Parameter name="Poisson's ratio" type="double" value="{nu!r}"/>
      <Parameter name="Prescribe" type="string" value="forces"/>
      <Parameter name="Longitudinal force" type="Array(double)" value="{{{Fx!r}}}"/>
      <Parameter name="Lateral force" type="Array(double)" value="{{{Fy!r}}}"/>
      <Parameter name="Spin creepage" type="Array(double)" value="{{{spin!r}}}"/>
      <Parameter name="Static friction" type="double" value="{mu!r}"/>
      <Parameter name="Rolling speed" type="double" value="{speed!r}"/>
      <Parameter name="Exact grid" type="int" value="{grid}"/>
      <Parameter name="Theories" type="Array(string)" value="{{exact}}"/>
      <Parameter name="Chart" type="bool" value="false"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""
PARAMETER = '      <Parameter name="{}" type="double" value="{!r}"/>'
TABLE = ["patch", "time_s", "FN_N", "Fx_N", "Fy_N", "Ft_over_muN", "geometry", "a_m", "b_m",
         "xi", "eta", "phi_per_m", "fe_adhesion_share", "exact_adhesion_share",
         "fe_tilt_deg", "exact_tilt_deg", "force_angle_deg"]


def patch_forces(patch):
    """FN, Fx, Fy (N) and the area share of the nodes that do not slip."""
    if "area_m2" not in patch:
        raise SystemExit("the patch file has no area_m2 column: write it with a railfe that does")
    area = patch["area_m2"]
    stick = np.sum(area[patch["slipping"] < 0.5]) / np.sum(area)
    return [float(np.sum(patch[k] * area)) for k in ("pressure_Pa", "shear_1_Pa", "shear_2_Pa")
            ] + [float(stick)]


def semi_axes(patch, how):
    """a, b (m) of the patch by second moments or extent."""
    w = patch["pressure_Pa"] * patch["area_m2"]
    s1, s2 = patch["s1_m"], patch["s2_m"]
    if how == "extent":
        half = 0.5 * node_spacing(patch)
        return 0.5 * np.ptp(s1) + half, 0.5 * np.ptp(s2) + half
    moment = [np.sum(w * (s - np.sum(w * s) / np.sum(w)) ** 2) / np.sum(w) for s in (s1, s2)]
    return float(np.sqrt(5 * moment[0])), float(np.sqrt(5 * moment[1]))


def orientation(s1, s2, weight):
    """Tilt (deg, -90 to 90) of the patch's long axis from s2 (across the rail), positive from s2
    towards -s1: the principal axis of the larger weighted second moment about the weighted
    centre. 0 for a patch long across the rail and symmetric about s1."""
    c1, c2 = (np.sum(weight * s) / np.sum(weight) for s in (s1, s2))
    m11, m22, m12 = (np.sum(weight * u * v) / np.sum(weight)
                     for u, v in ((s1 - c1, s1 - c1), (s2 - c2, s2 - c2), (s1 - c1, s2 - c2)))
    from_s1 = np.degrees(0.5 * np.arctan2(2 * m12, m11 - m22))  # the long axis, from s1
    return float(from_s1 % 180 - 90)


def solve_exact(args, patch_path, FN, Fx, Fy):
    """Runs the contact patch step; returns the inverse row, the exact tractions and a, b."""
    if args.geometry == "separation":
        geometry = "\n".join([
            '      <Parameter name="Geometry" type="string" value="separation"/>',
            '      <Parameter name="Separation file" type="string" value="{}"/>'.format(
                os.path.abspath(args.separation)), PARAMETER.format("A", args.A)])
        a = b = float("nan")
    elif args.geometry == "curvatures":
        geometry = "\n".join(['      <Parameter name="Geometry" type="string" value="curvatures"/>',
                              PARAMETER.format("A", args.A), PARAMETER.format("B", args.B)])
        a = b = float("nan")
    else:
        a, b = semi_axes(read_patch(patch_path), args.geometry)
        geometry = "\n".join(['      <Parameter name="Geometry" type="string" value="semi-axes"/>',
                              PARAMETER.format("a", a), PARAMETER.format("b", b)])
    text = DECK.format(patch=patch_path, geometry=geometry, FN=FN, Fx=Fx, Fy=Fy, spin=args.spin,
                       mu=args.mu, speed=args.speed, grid=args.grid, E=args.E, nu=args.nu)
    try:
        output, _ = run_deck(args.railfe, text, args.work, "patch_vs_exact")
    except RuntimeError as error:
        raise SystemExit(str(error))
    inverse = csv_rows(os.path.join(output, "exact_inverse.csv"))[0]
    forces = csv_rows(os.path.join(output, "exact_forces.csv"))[0]
    tractions = [r for r in csv_rows(os.path.join(output, "exact_tractions.csv"))
                 if r["theory"] == "exact"]
    return inverse, tractions, float(forces["a_m"]), float(forces["b_m"])


def chart(png, patch, tractions, speed, title, across_shift=0.0):
    """The FE patch (top) above the exact solver's (bottom), on the same axes; the exact solver's
    y less `across_shift` (m)."""
    fig, axes = plt.subplots(2, 3, figsize=(17, 9.5), sharex=True, sharey=True)
    s1, s2 = 1e3 * patch["s1_m"], 1e3 * patch["s2_m"]
    pressure_shear_panel(fig, axes[0, 0], s1, s2, 1e-6 * patch["pressure_Pa"],
                         patch["shear_1_Pa"], patch["shear_2_Pa"])
    slip_panel(axes[0, 1], s1, s2, patch["slip_velocity_1_m/s"], patch["slip_velocity_2_m/s"],
               patch["slipping"] > 0.5)
    # One colour scale for both rows: 5 degrees beyond the largest turn of either, at least 10.
    column_q = [(patch["shear_1_Pa"], patch["shear_2_Pa"]),
                ([float(r["qx_Pa"]) for r in tractions if float(r["p_Pa"]) > 0],
                 [float(r["qy_Pa"]) for r in tractions if float(r["p_Pa"]) > 0])]
    largest = max(abs(a) for q1, q2 in column_q for a in shear_angles(q1, q2))
    limit = min(180.0, max(10.0, 5 * math.ceil(largest / 5 + 1)))
    shear_angle_panel(fig, axes[0, 2], s1, s2, patch["shear_1_Pa"], patch["shear_2_Pa"], limit)
    column = {k: np.array([float(r[k]) for r in tractions])
              for k in ("x_m", "y_m", "p_Pa", "qx_Pa", "qy_Pa", "slip_x", "slip_y")}
    x, y = 1e3 * column["x_m"], 1e3 * (column["y_m"] - across_shift)
    # Arrows on every third element each way, so that the grid's arrows stay readable.
    step = [np.min(np.diff(np.unique(np.round(v, 9)))) for v in (x, y)]
    arrows = [i for i in range(len(x))
              if round(x[i] / step[0]) % 3 == 0 and round(y[i] / step[1]) % 3 == 0]
    pressure_shear_panel(fig, axes[1, 0], x, y, 1e-6 * column["p_Pa"], column["qx_Pa"],
                         column["qy_Pa"], marker_size=12, arrows=arrows)
    slip_panel(axes[1, 1], x, y, speed * column["slip_x"], speed * column["slip_y"],
               [r["state"] == "slip" for r in tractions], marker_size=10)
    loaded = column["p_Pa"] > 0
    shear_angle_panel(fig, axes[1, 2], x[loaded], y[loaded], column["qx_Pa"][loaded],
                      column["qy_Pa"][loaded], limit, marker_size=12)
    for ax, label in zip(axes[:, 0], ("finite elements", "exact steady rolling")):
        ax.set_ylabel(f"{label}\ns2 across (mm)")
    for ax in axes.flat:
        ax.set_aspect("equal", adjustable="box")
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("s1 along the rolling direction (mm)")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("patch", help="a patch file <step>_contact_<pair>_patch_<k>.csv")
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--mu", type=float, required=True, help="Coulomb friction coefficient")
    parser.add_argument("--geometry", choices=("moments", "extent", "curvatures", "separation"),
                        default="moments")
    parser.add_argument("--A", type=float,
                        help="relative curvature along (1/m): curvatures, separation")
    parser.add_argument("--B", type=float, help="relative curvature across (1/m), curvatures")
    parser.add_argument("--separation", help="separation CSV (y, s[, R]), for separation")
    parser.add_argument("--spin", type=float, default=0.0, help="spin creepage (1/m)")
    parser.add_argument("--speed", type=float, default=100 / 3.6, help="rolling speed (m/s)")
    parser.add_argument("--E", type=float, default=210e9)
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--grid", type=int, default=40, help="exact solver's elements a side")
    parser.add_argument("--table", required=True, help="Table-3 CSV, a row appended")
    parser.add_argument("--png", required=True)
    parser.add_argument("--work", required=True, help="directory for the deck and its results")
    args = parser.parse_args()
    if args.geometry == "curvatures" and (args.A is None or args.B is None):
        parser.error("--geometry curvatures needs --A and --B")
    if args.geometry == "separation" and (args.A is None or not args.separation):
        parser.error("--geometry separation needs --A and --separation")
    if args.A is not None and args.geometry not in ("curvatures", "separation"):
        parser.error("--A is read only with --geometry curvatures or separation")
    if args.B is not None and args.geometry != "curvatures":
        parser.error("--B is read only with --geometry curvatures")
    if args.geometry != "separation" and args.separation:
        parser.error("--separation is read only with --geometry separation")
    patch = read_patch(args.patch)
    FN, Fx, Fy, fe_stick = patch_forces(patch)
    inverse, tractions, a, b = solve_exact(args, args.patch, FN, Fx, Fy)
    # The creepages found must carry the FE forces (the step's Inverse tolerance, 1e-6 mu N).
    mu_n = args.mu * FN
    miss = np.hypot(float(inverse["Fx_found_N"]) - Fx, float(inverse["Fy_found_N"]) - Fy)
    if not miss <= 1e-5 * mu_n:
        raise SystemExit(f"the exact solver's forces miss the FE ones by {miss:g} N")
    time = float(patch["time_s"][0])
    row = [os.path.basename(args.patch), time, FN, Fx, Fy, np.hypot(Fx, Fy) / mu_n,
           args.geometry, a, b, float(inverse["xi"]), float(inverse["eta"]), args.spin,
           fe_stick, float(inverse["adhesion_fraction"]),
           orientation(patch["s1_m"], patch["s2_m"], patch["pressure_Pa"] * patch["area_m2"]),
           orientation(np.array([float(r["x_m"]) for r in tractions]),
                       np.array([float(r["y_m"]) for r in tractions]),
                       np.array([float(r["p_Pa"]) for r in tractions])),
           float(np.degrees(np.arctan2(Fy, Fx)))]
    new = not os.path.exists(args.table)
    with open(args.table, "a", newline="") as f:
        out = csv.writer(f)
        if new:
            out.writerow(TABLE)
        out.writerow(row)
    # The separation's y is the track's, the FE's s2 is about the patch's centre: both drawn
    # about the FE centre's track y, so that the chart shows where each patch lies.
    weight = patch["pressure_Pa"] * patch["area_m2"]
    shift = (float(np.sum(weight * patch["y_m"]) / np.sum(weight))
             if args.geometry == "separation" else 0.0)
    chart(args.png, patch, tractions, args.speed,
          f"t = {1e3 * time:.4f} ms: FN {FN / 1e3:.2f} kN, Fx {Fx / 1e3:.3f} kN, Fy "
          f"{Fy / 1e3:.3f} kN; exact solver (a {1e3 * a:.2f}, b {1e3 * b:.2f} mm, "
          f"{args.geometry}): ξ {row[9]:.4g}, η {row[10]:.4g}", shift)
    print(",".join(TABLE))
    print(",".join(str(v) for v in row))


if __name__ == "__main__":
    main()
