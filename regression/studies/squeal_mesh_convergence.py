#!/usr/bin/env python3
"""Speed against accuracy of the squeal scene's contact mesh (issue 16): case 1 on the demo's
time line (no lateral motion; torque ramped over 0.5 ms, 1.6 ms) with the contact zone meshed at
6, 4, 3 and 2 mm (rail zone, rail head, wheel tread and refined arc alike; the step mass-scaled
in proportion, 25 ns per mm, as the contact's own limit scales; from 2 mm the contact's critical
step is the smaller). Over the last 0.2 ms: the creep force, the contact area and the nodes in
contact; at 1.6 ms the peak pressure and the patch's semi-axes (pressure-weighted second
moments); the run's wall time (statics and explicit), the explicit step's CPU time and the peak
memory. Force, area and peak pressure are compared with the finest run. At 1 mm (106 k
elements) the statics preload does not converge (the contact iterations lose every node after
the first solve), so the study stops at 2 mm.

The creepage: each size also runs without the torque (free rolling: issue 15 measures creepage
against a free-rolling run of the same model, not against V/R). Two rim points at axle height,
ahead and behind (make_squeal_decks.py --kinematics), give the wheel's turning speed (their
vertical velocities' difference over their distance) and its centre's speed (their mean
horizontal velocity less the turning of their midpoint's offset from the centre; the axle box,
the half axle's far end, lags the wheel while the axle bends). xi = omega r0 / V - 1 is averaged
over the window; the driven run's creepage is its xi less the free run's (also over the 0.2 ms
before the window, and xi's spread over it: the demo's time line is not steady). The exact
steady-rolling solver (a "contact patch" step) then gives the longitudinal force at that
creepage for the run's normal force on an ellipse of the FE patch's semi-axes (the profiles'
curvatures give no usable Hertz patch: the first touch lies where the rail head's R300 crown
meets its R80 arc, and on the field side tread and crown nearly conform), and the creepage it
needs for the run's force.

Writes docs/data/squeal_mesh_convergence.csv and docs/img/squeal_mesh_convergence.png. Rows of
sizes not run this time are kept from the CSV, so sizes can be added one at a time; --reuse
reads runs already in --work; --exact recomputes the comparisons from the CSV alone:

    /usr/bin/python3 regression/studies/squeal_mesh_convergence.py [build/bin/railfe] \\
        [--sizes 2] [--no-free] [--reuse] [--exact] [--replot]
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE, os.path.join(ROOT, "regression", "scenes")]
from railfe_runs import csv_rows, run_deck, run_or_reuse, step_section, study_parser, typed_rows, write_rows  # noqa: E402
from squeal_simplifications import deck_text  # noqa: E402
from make_squeal_decks import ROLLING_RADIUS, SPEED  # noqa: E402

SIZES_MM = [6, 4, 3, 2]
WINDOW = (1.4e-3, 1.6e-3)  # s: the end of the run, where the traction has nearly settled
BEFORE = (1.2e-3, 1.4e-3)  # s: the 0.2 ms before it (how steady the creepage is)
MU = 0.45  # case 1: Coulomb
CSV = os.path.join(ROOT, "docs", "data", "squeal_mesh_convergence.csv")
COMPARED = ("creep_force_N", "contact_area_m2", "peak_pressure_Pa")
COLUMNS = [  # the first twelve as the study wrote them for 6, 4 and 3 mm
    "zone_element_size_mm", "elements", "steps", "explicit_cpu_s", "creep_force_N",
    "normal_force_N", "contact_area_m2", "active_nodes", "peak_pressure_Pa",
    "creep_force_vs_finest", "contact_area_vs_finest", "peak_pressure_vs_finest",
    # the run: wall times (statics, explicit), peak memory
    "wall_time_s", "preload_wall_s", "roll_wall_s", "peak_memory_MiB",
    # the patch: forces over the window, the change of Fx across it, the contact angle from the
    # force's direction, the semi-axes and centre at 1.6 ms
    "longitudinal_force_N", "lateral_force_N", "longitudinal_force_change_N",
    "contact_angle_rad", "patch_a_m", "patch_b_m", "patch_centre_y_m",
    # the creepage: the wheel's speed and turning, xi driven and free, their difference
    # (window means; the spread of xi over the window; the means over the 0.2 ms before it)
    "wheel_speed_m_per_s", "axle_box_speed_m_per_s", "omega_rad_per_s", "xi_driven",
    "xi_driven_spread", "xi_free", "free_longitudinal_force_N", "creepage", "xi_driven_before",
    "xi_free_before", "creepage_before",
    # the exact solver at that creepage, the run's N and an ellipse of the patch's a, b: Fx (and
    # at the creepage before the window; at the creepage less and plus its spread; and with the
    # contact angle's spin), its initial slope, the creepage it needs for the run's Fx
    "exact_longitudinal_force_N", "exact_area_m2", "exact_peak_pressure_Pa",
    "exact_adhesion_fraction", "longitudinal_force_vs_exact", "peak_pressure_vs_exact",
    "exact_longitudinal_force_before_N", "exact_longitudinal_force_low_N",
    "exact_longitudinal_force_high_N", "exact_initial_slope_N", "exact_creepage_for_fe_force",
    "creepage_vs_exact", "spin_per_m", "exact_longitudinal_force_spin_N",
    "exact_lateral_force_spin_N", "longitudinal_force_vs_exact_spin"]

EXACT_DECK = """<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="Exact solver at a squeal run's creepage and force"/>
  <ParameterList name="Steps">
    <ParameterList name="exact">
      <Parameter name="Module" type="string" value="contact patch"/>
{common}
      <Parameter name="Longitudinal creepage" type="Array(double)" value="{{{xi}}}"/>
      <Parameter name="Spin creepage" type="Array(double)" value="{{{phi}}}"/>
    </ParameterList>
    <ParameterList name="inverse">
      <Parameter name="Module" type="string" value="contact patch"/>
{common}
      <Parameter name="Prescribe" type="string" value="forces"/>
      <Parameter name="Longitudinal force" type="Array(double)" value="{{{Fx!r}}}"/>
      <Parameter name="Lateral force" type="Array(double)" value="{{0}}"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""
EXACT_COMMON = """      <Parameter name="Geometry" type="string" value="semi-axes"/>
      <Parameter name="a" type="double" value="{a!r}"/>
      <Parameter name="b" type="double" value="{b!r}"/>
      <Parameter name="Normal load" type="double" value="{N!r}"/>
      <Parameter name="Static friction" type="double" value="{mu!r}"/>
      <Parameter name="Rolling speed" type="double" value="{speed!r}"/>
      <Parameter name="Theories" type="Array(string)" value="{{exact}}"/>
      <Parameter name="Traction fields" type="bool" value="false"/>
      <Parameter name="Chart" type="bool" value="false"/>"""


def options(size_mm):
    h = size_mm / 1000
    return ["--zone-size", str(h), "--head-size", str(h), "--tread-size", str(h),
            "--arc-size", str(h), "--mass-scaling", f"{2.5e-5 * h:g}"]


def in_window(rows, window=WINDOW):
    return [r for r in rows if window[0] <= float(r["time_s"]) <= window[1]]


def window_mean(rows, column, window=WINDOW):
    values = [float(r[column]) for r in in_window(rows, window)]
    return sum(values) / len(values)


def column(rows, name):
    """The history column of the deck's history `name` (its header is name_quantity_...)."""
    keys = [k for k in rows[0] if k.startswith(name + "_")]
    if len(keys) != 1:
        raise KeyError(f"history {name!r}: {keys}")
    return [float(r[keys[0]]) for r in rows]


def creepage(results, window=WINDOW, before=BEFORE):
    """Means over `window` (and over `before`) of xi = omega r0 / V - 1 from the two rim points
    a (ahead) and b (behind) at axle height, and of the rim's omega, the wheel centre's V and the
    axle box's speed.

    At t = 0 every wheel node moves rigidly: v = V0 + omega0 x (x - c). So the points' distance
    along x and their midpoint's offset m from the centre c are known from their first velocities;
    later, x_a - x_b follows from their displacements, omega = -(vz_a - vz_b) / (x_a - x_b), m
    turns with the wheel (its angle the integral of omega), and V = (vx_a + vx_b) / 2 - omega m_z.
    The axle box is the far end of the half axle: it lags the wheel while the axle bends."""
    rows = csv_rows(os.path.join(results, "roll_histories.csv"))
    time = [float(r["time_s"]) for r in rows]
    vx_a, vz_a, ux_a = (column(rows, n) for n in ("rim vx", "rim vz", "rim ux"))
    vx_b, vz_b, ux_b = (column(rows, n) for n in ("rim behind vx", "rim behind vz",
                                                   "rim behind ux"))
    axle = column(rows, "axle vx")
    omega0, speed0 = column(rows, "axle spin")[0], axle[0]
    dx0 = -(vz_a[0] - vz_b[0]) / omega0
    mx0 = -(vz_a[0] + vz_b[0]) / 2 / omega0
    mz0 = ((vx_a[0] + vx_b[0]) / 2 - speed0) / omega0
    omega = [-(vz_a[k] - vz_b[k]) / (dx0 + ux_a[k] - ux_a[0] - ux_b[k] + ux_b[0])
             for k in range(len(rows))]
    angle = [0.0]
    for k in range(1, len(rows)):
        angle.append(angle[-1] + 0.5 * (omega[k] + omega[k - 1]) * (time[k] - time[k - 1]))
    speed = [(vx_a[k] + vx_b[k]) / 2 - omega[k] * (mz0 * math.cos(angle[k]) -
                                                   mx0 * math.sin(angle[k]))
             for k in range(len(rows))]
    xi = [w * ROLLING_RADIUS / v - 1 for w, v in zip(omega, speed)]

    def mean(values, span=window):
        chosen = [v for t, v in zip(time, values) if span[0] <= t <= span[1]]
        return sum(chosen) / len(chosen)

    return {"xi": mean(xi), "xi_before": mean(xi, before),
            "xi_spread": math.sqrt(mean([(x - mean(xi)) ** 2 for x in xi])),
            "omega": mean(omega), "speed": mean(speed), "axle_speed": mean(axle),
            "series": (time, xi), "omega_series": omega, "speed_series": speed}


def patch_shape(path):
    """Peak pressure, the pressure-weighted centre across (s2) and the semi-axes a = sqrt(5
    <s1^2>), b = sqrt(5 <s2^2>) of one patch file (what a Hertz ellipse meets exactly)."""
    patch = csv_rows(path)
    w = [float(r["pressure_Pa"]) * float(r["area_m2"]) for r in patch]
    total = sum(w)
    shape = {"peak_pressure_Pa": max(float(r["pressure_Pa"]) for r in patch)}
    for axis, key in (("s1_m", "patch_a_m"), ("s2_m", "patch_b_m")):
        s = [float(r[axis]) for r in patch]
        centre = sum(wi * si for wi, si in zip(w, s)) / total
        shape[key] = math.sqrt(5 * sum(wi * (si - centre) ** 2 for wi, si in zip(w, s)) / total)
    shape["patch_centre_y_m"] = sum(wi * float(r["y_m"]) for wi, r in zip(w, patch)) / total
    return shape


REUSE = False  # --reuse: read the runs already in --work instead of running them again


def one_run(railfe, work, size, torque, variant=(), reuse=None):
    """Case 1 at `size` mm (with the generator's `variant` options), driven or free; reuses
    the run in `work` if asked to (default: --reuse) and its deck is the same."""
    extra = ["--case", "1", "--kinematics"] + ([] if torque else ["--torque", "0"])
    name = f"zone_{size:g}mm" + ("" if torque else "_free")
    text = deck_text(options(size) + extra + list(variant))  # the last --case wins
    return run_or_reuse(railfe, text, work, name, REUSE if reuse is None else reuse)


def measure(railfe, work, size, free):
    results, summary = one_run(railfe, work, size, True)
    roll = step_section(summary, "roll")
    history = csv_rows(os.path.join(results, "roll_contact_wheel-rail.csv"))
    last_patch = max((f for f in os.listdir(results)
                      if f.startswith("roll_contact_wheel-rail_patch_") and f.endswith(".csv")),
                     key=lambda f: int(f.rsplit("_", 1)[1][:-4]))
    shape = patch_shape(os.path.join(results, last_patch))
    wall = summary["Wall time"]
    window = in_window(history)
    row = {
        "zone_element_size_mm": float(size),
        "elements": float(roll["elements"]),
        "steps": float(roll["steps"]),
        "explicit_cpu_s": float(roll["time: stepping, CPU of rank 0 [s]"]),
        "creep_force_N": math.hypot(window_mean(history, "tangential_1_N"),
                                    window_mean(history, "tangential_2_N")),
        "normal_force_N": window_mean(history, "normal_force_N"),
        "contact_area_m2": window_mean(history, "contact_area_m2"),
        "active_nodes": window_mean(history, "active_nodes"),
        "peak_pressure_Pa": shape["peak_pressure_Pa"],
        "wall_time_s": float(wall["total [s]"]),
        "preload_wall_s": float(wall["step preload [s]"]),
        "roll_wall_s": float(wall["step roll [s]"]),
        "peak_memory_MiB": float(summary["Memory"]["peak resident, largest rank [MiB]"]),
        "longitudinal_force_N": window_mean(history, "tangential_1_N"),
        "lateral_force_N": window_mean(history, "tangential_2_N"),
        # How far from steady: the longitudinal force's change over the window.
        "longitudinal_force_change_N": float(window[-1]["tangential_1_N"]) -
        float(window[0]["tangential_1_N"]),
        "contact_angle_rad": math.atan2(window_mean(history, "force_y_N"),
                                        window_mean(history, "force_z_N")),
        "patch_a_m": shape["patch_a_m"], "patch_b_m": shape["patch_b_m"],
        "patch_centre_y_m": shape["patch_centre_y_m"],
    }
    kinematics = creepage(results)
    row.update({"wheel_speed_m_per_s": kinematics["speed"],
                "axle_box_speed_m_per_s": kinematics["axle_speed"],
                "omega_rad_per_s": kinematics["omega"], "xi_driven": kinematics["xi"],
                "xi_driven_spread": kinematics["xi_spread"],
                "xi_driven_before": kinematics["xi_before"]})
    if free:
        results, _ = one_run(railfe, work, size, False)
        free_history = csv_rows(os.path.join(results, "roll_contact_wheel-rail.csv"))
        kinematics = creepage(results)
        row.update({"xi_free": kinematics["xi"], "xi_free_before": kinematics["xi_before"],
                    "free_longitudinal_force_N": window_mean(free_history, "tangential_1_N")})
        row["creepage"] = row["xi_driven"] - row["xi_free"]
        row["creepage_before"] = row["xi_driven_before"] - row["xi_free_before"]
    return row


def merge(new_rows):
    """The CSV's rows with those of the sizes run now replaced or added, finest last."""
    rows = {r["zone_element_size_mm"]: r for r in typed_rows(CSV, [])} if os.path.exists(
        CSV) else {}
    for row in new_rows:
        rows[row["zone_element_size_mm"]] = row
    return [rows[k] for k in sorted(rows, reverse=True)]


def exact(railfe, work, row):
    """The exact solver on an ellipse with the run's patch semi-axes and normal force: the
    longitudinal force at the run's creepage (and at the creepage of the 0.2 ms before the
    window; with the contact angle's spin sin(gamma) / r0; and at 1e-6, the initial slope), and
    the creepage that carries the run's longitudinal force (the inverse problem)."""
    phi = math.sin(row["contact_angle_rad"]) / ROLLING_RADIUS
    # Kalker's sign: a driving wheel's surface outruns its centre, xi < 0, Fx > 0 on the wheel.
    spread = row["xi_driven_spread"]
    cases = [(-row["creepage"], 0), (-row["creepage"], phi), (-row["creepage_before"], 0),
             (-1e-6, 0), (-row["creepage"] + spread, 0), (-row["creepage"] - spread, 0)]
    common = EXACT_COMMON.format(a=row["patch_a_m"], b=row["patch_b_m"],
                                 N=row["normal_force_N"], mu=MU, speed=SPEED)
    text = EXACT_DECK.format(common=common, xi=", ".join(repr(c[0]) for c in cases),
                             phi=", ".join(repr(c[1]) for c in cases),
                             Fx=row["longitudinal_force_N"])
    results, _ = run_deck(railfe, text, work, f"exact_{row['zone_element_size_mm']:g}mm")
    forward = [r for r in csv_rows(os.path.join(results, "exact_forces.csv"))
               if r["theory"] == "exact"]
    # (Only the run's own creepage: the spread's low end can cross zero on a steady run.)
    if float(forward[0]["Fx_N"]) < 0:
        raise RuntimeError("the exact solver's sign convention is not the one assumed")
    inverse = csv_rows(os.path.join(results, "inverse_inverse.csv"))[0]
    at, spin, before, slope, low, high = forward
    return {"exact_longitudinal_force_N": float(at["Fx_N"]),
            "exact_area_m2": math.pi * float(at["a_m"]) * float(at["b_m"]),
            "exact_peak_pressure_Pa": float(at["pmax_Pa"]),
            "exact_adhesion_fraction": float(at["adhesion_fraction"]),
            "exact_longitudinal_force_before_N": float(before["Fx_N"]),
            "exact_longitudinal_force_low_N": float(low["Fx_N"]),
            "exact_longitudinal_force_high_N": float(high["Fx_N"]),
            "exact_initial_slope_N": float(slope["Fx_N"]) / 1e-6,
            "exact_creepage_for_fe_force": -float(inverse["xi"]),
            "spin_per_m": phi,
            "exact_longitudinal_force_spin_N": float(spin["Fx_N"]),
            "exact_lateral_force_spin_N": float(spin["Fy_N"])}


def finish(rows, railfe, work, with_exact):
    finest = rows[-1]
    for row in rows:
        for key in COMPARED:
            row[key.rsplit("_", 1)[0] + "_vs_finest"] = row[key] / finest[key] - 1
        if with_exact and not any(math.isnan(row.get(k, float("nan")))
                                  for k in ("creepage", "creepage_before")):
            row.update(exact(railfe, work, row))
            row["longitudinal_force_vs_exact"] = (row["longitudinal_force_N"] /
                                                  row["exact_longitudinal_force_N"] - 1)
            row["creepage_vs_exact"] = row["creepage"] / row["exact_creepage_for_fe_force"] - 1
            row["longitudinal_force_vs_exact_spin"] = (
                row["longitudinal_force_N"] / row["exact_longitudinal_force_spin_N"] - 1)
            row["peak_pressure_vs_exact"] = (row["peak_pressure_Pa"] /
                                             row["exact_peak_pressure_Pa"] - 1)
    write_rows(CSV, [{k: float(row.get(k, float("nan"))) for k in COLUMNS} for row in rows])


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    rows = typed_rows(CSV, [])
    finest = rows[-1]["zone_element_size_mm"]
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    axis = axes[0]
    wall = [r["wall_time_s"] for r in rows]
    for key, label in (("creep_force_vs_finest", "creep force (mean, last 0.2 ms)"),
                       ("contact_area_vs_finest", "contact area (mean, last 0.2 ms)"),
                       ("peak_pressure_vs_finest", "peak pressure at 1.6 ms")):
        axis.plot(wall, [100 * r[key] for r in rows], marker="o", label=label)
    for r in rows:
        axis.annotate(f"{r['zone_element_size_mm']:g} mm\n{r['elements'] / 1e3:.0f} k el.",
                      (r["wall_time_s"], 0), textcoords="offset points", xytext=(0, 12),
                      ha="center", fontsize=8)
    axis.axhline(0, color="grey", linewidth=0.8)
    axis.set_xscale("log")
    axis.set_xlabel("wall time of the run, statics and explicit, one core (s)")
    axis.set_xlim(0.8 * min(wall), 1.25 * max(wall))
    axis.set_ylabel(f"difference from the {finest:g} mm run (%)")
    axis.set_title("against the finest mesh")
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    axis = axes[1]
    compared = [r for r in rows if not math.isnan(r.get("longitudinal_force_vs_exact",
                                                        float("nan")))]
    if not compared:  # --no-free: no creepage, so nothing to compare
        compared = [dict(r, longitudinal_force_vs_exact=float("nan")) for r in rows]
    wall = [r["wall_time_s"] for r in compared]
    mid = [100 * r["longitudinal_force_vs_exact"] for r in compared]
    low = [m - 100 * (r["longitudinal_force_N"] / r["exact_longitudinal_force_high_N"] - 1)
           for m, r in zip(mid, compared)]
    high = [100 * (r["longitudinal_force_N"] / r["exact_longitudinal_force_low_N"] - 1) - m
            for m, r in zip(mid, compared)]
    axis.errorbar(wall, mid, yerr=[low, high], marker="o", capsize=4,
                  label="at the creepage of the last 0.2 ms (bars: ± its spread over them)")
    axis.plot(wall, [100 * (r["longitudinal_force_N"] / r["exact_longitudinal_force_before_N"] - 1)
                     for r in compared], marker="s", linestyle="--",
              label="at the creepage of the 0.2 ms before")
    axis.plot(wall, [100 * r["longitudinal_force_vs_exact_spin"] for r in compared], marker="^",
              linestyle=":", label="at the creepage of the last 0.2 ms, with the contact angle's "
              "spin")
    for r, m in zip(compared, mid):
        axis.annotate(f"{r['zone_element_size_mm']:g} mm\nξ {1e3 * r['creepage']:.2f}e-3",
                      (r["wall_time_s"], m), textcoords="offset points", xytext=(14, 4),
                      fontsize=8)
    axis.axhspan(-4, 4, color="grey", alpha=0.15,
                 label="±4 %: issue 15's steady rolling at b/h ≥ 8 (Carter)")
    axis.axhline(0, color="grey", linewidth=0.8)
    axis.set_xscale("log")
    axis.set_xlabel("wall time of the run, statics and explicit, one core (s)")
    axis.set_ylabel("FE longitudinal creep force against the exact solver (%)")
    axis.set_title("against the exact steady-rolling solver (N and the patch's a, b)")
    axis.set_xlim(0.8 * min(wall), 1.8 * max(wall))  # room for the labels
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8, loc="upper left")
    for axis in axes:
        ticks = [t for t in (20, 30, 50, 100, 200, 300, 500, 1000, 2000, 5000)
                 if axis.get_xlim()[0] <= t <= axis.get_xlim()[1]]
        axis.set_xticks(ticks)
        axis.set_xticklabels([f"{t:g}" for t in ticks])
        axis.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    fig.suptitle("Squeal scene, case 1 on the demo's time line: contact mesh size")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "squeal_mesh_convergence.png"), dpi=110)


def main():
    parser = study_parser(__doc__.split("\n")[0], "squeal_mesh_convergence_work", ROOT)
    parser.add_argument("--sizes", type=float, nargs="+", default=SIZES_MM,
                        help="contact zone element sizes to run (mm); the CSV keeps the others")
    parser.add_argument("--no-free", action="store_true",
                        help="skip the free-rolling runs (no creepage, no exact comparison)")
    parser.add_argument("--reuse", action="store_true",
                        help="read the runs already in --work (same deck) instead of running "
                             "them again")
    parser.add_argument("--exact", action="store_true",
                        help="only recompute the comparisons (and the exact solver's) from the "
                             "CSV, then draw")
    args = parser.parse_args()
    global REUSE
    REUSE = args.reuse
    if not args.replot:
        rows = merge([] if args.exact else
                     [measure(args.railfe, args.work, s, not args.no_free) for s in args.sizes])
        finish(rows, args.railfe, args.work, True)
    plot()


if __name__ == "__main__":
    main()
