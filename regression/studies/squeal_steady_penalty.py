#!/usr/bin/env python3
"""Why the held steady case 1 misses the exact solver, and what it costs to close the gap: the
held run (squeal_steady_creepage.py --hold) at several penalty factors (issue 16).

The penalty springs also act tangentially (docs/theory.md, penalty contact): a stuck slave node
moves A/k against the rail per unit shear traction. That flexibility is in series with the
bodies' own, which Kalker's simplified theory puts at L = 8a / (3 C11 G) for a patch of rolling
semi-axis a, and C11 G = (initial slope of the exact creep curve) / (a b). Where the patch sticks
the creep force at creepage xi is then that of the exact solver at about xi / (1 + r),
r = (A/k) / L. With the bulk-modulus penalty k = f K A^2 / V, A/k = h / (f K) on cubes of size
h: on the demo's 3 mm contact mesh r is about 0.3 / f.

For each --penalties f the held run is measured as squeal_steady_creepage.py does (the creepage
from the rim points less that of the free twin, which runs once, at f = 1; means over --window;
the patch's semi-axes from six patches in the window), and gets:
- the exact solver's Fx at the measured creepage, without and with the contact angle's spin;
- r from the run's patches (force-weighted A / (f K h)) and from the run's summary, where railfe
  reports it (the same ratio, with Kalker's C11);
- the exact solver's Fx at (xi, phi) / (1 + r): what the penalty layer alone predicts (the layer
  in series scales every creepage alike; phi = sin(contact angle) / r0 is the spin the held
  wheel's contact angle gives, which the FE run has and the comparison must have too).

Writes docs/data/squeal_steady_penalty.csv (a row per factor), docs/data/
squeal_steady_penalty_histories.csv (0.3 ms running means of Fx) and docs/img/
squeal_steady_penalty.png: the histories, the error against f with the prediction, and the error
against the steps it took (speed against accuracy: one mesh, so steps are the cost). The runs at
f = 1, 3, 10, 30 and 10 with the softer side took 9, 13, 35, 58 and 11 min on one core of a
machine that was running two of them at once:

    /usr/bin/python3 regression/studies/squeal_steady_penalty.py [build/bin/railfe] \\
        [--penalties 1 3 10 30] [--softer 10] [--size 3] [--reuse] [--replot]

Another mesh or window is another run set, with its own files (--name): the 2 mm mesh, softer
side at f = 10, held to 4 ms with the window 3-4 ms, as
    ... --penalties --softer 10 --size 2 --end-time 4e-3 --window 3e-3 4e-3 --name 2mm_4ms
and the same with its free twin at the held run's penalty settings (--free-like-held: the free
twin's own r is then railfe's report, not an estimate scaled from 3 mm):
    ... --name 2mm_4ms_matched --free-like-held
The bodies below the contact meshed finer than the demo's 20 mm (rail section) and 60 mm (wheel)
(--depth SECTION WHEEL, mm; both runs of the pair get it and their names _depthS-W):
    ... --size 3 --end-time 4e-3 --window 3e-3 4e-3 --free-like-held --depth 8 15 \\
        --name 3mm_4ms_depth8-15
The hub held inside a smaller radius than the generator's 0.385 m (--hub R, m; names _hubR):
    ... --size 3 --end-time 4e-3 --window 3e-3 4e-3 --free-like-held --hub 0.25 \\
        --name 3mm_4ms_hub0.25
The control, a cylindrical tread on the rail upright (--cylinder; names _cylinder; no chart
here: its free twin carries 8 kN at the nominal radius, so the comparisons need the twin's
offset, which squeal_steady_nonhertzian.py applies and draws):
    ... --size 3 --end-time 4e-3 --window 3e-3 4e-3 --free-like-held --cylinder \\
        --name 3mm_4ms_cylinder     (then --hold 0.0004 and 0.0016 with --reuse, as below)
A held creepage other than 0.8e-3 (--hold; the free twin is the same run, reused with --reuse
from a --work that holds it): the creep curve's points, as
    ... --size 3 --end-time 4e-3 --window 3e-3 4e-3 --free-like-held --hold 0.0004 \\
        --name 3mm_4ms_xi0.0004 --work DIR_OF_THE_0.8e-3_PAIR --reuse
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE, os.path.join(ROOT, "regression", "scenes")]
import squeal_mesh_convergence as convergence  # noqa: E402
import squeal_steady_creepage as steady  # noqa: E402
from railfe_runs import csv_rows, study_parser, typed_rows, write_rows  # noqa: E402

PENALTIES = [1, 3, 10, 30]
SOFTER = [10]  # also run with the softer side's cap
HOLD = 0.8e-3  # the held creepage
END_TIME = 2.5e-3  # s
WINDOW = (1.5e-3, 2.5e-3)  # s
YOUNG, POISSON = 210e9, 0.3  # the scene's steel (make_squeal_decks.py)
BULK = YOUNG / (3 * (1 - 2 * POISSON))
SUMMARY_KEY = "contact wheel-rail: penalty tangential flexibility / patch's"

def outputs(name):
    """The study's CSV, histories CSV and PNG for run set `name` ("" for the 3 mm set)."""
    suffix = f"_{name}" if name else ""
    return (os.path.join(ROOT, "docs", "data", f"squeal_steady_penalty{suffix}.csv"),
            os.path.join(ROOT, "docs", "data", f"squeal_steady_penalty{suffix}_histories.csv"),
            os.path.join(ROOT, "docs", "img", f"squeal_steady_penalty{suffix}.png"))


CSV, HISTORIES, PNG = outputs("")


def penalty_flexibility(results, size_mm, penalty):
    """Force-weighted mean over the run's patches of the slave nodes' A / k (m/Pa), with the
    bulk-modulus penalty k = f K A^2 / V = f K h on the master's h-sized cubes."""
    total = weighted = 0.0
    for path in steady.patches(results):
        for r in csv_rows(path):
            area = float(r["area_m2"])
            force = float(r["pressure_Pa"]) * area
            total += force
            weighted += force * area / (penalty * BULK * size_mm / 1000)
    return weighted / total


def summary_ratio(work, name):
    """The flexibility ratio railfe's summary reports for the run, NaN where it does not."""
    with open(os.path.join(work, name + "_results", "summary.json")) as summary:
        roll = json.load(summary)["Step roll (explicit)"]
    return float(roll.get(SUMMARY_KEY, "nan"))


def one_factor(railfe, work, size, penalty, softer, timeline, reuse):
    """The held run at `penalty` (with the softer side's cap if `softer`): its row and its Fx
    history (0.3 ms running means)."""
    steady.PENALTY, steady.SOFTER_SIDE = penalty, softer
    row, history = steady.measure(railfe, work, size, timeline, reuse)
    row = steady.compare(railfe, work, row)
    a, b = row["patch_a_m"], row["patch_b_m"]
    name = steady.held_name(size)
    row["flexibility_ratio_railfe"] = summary_ratio(work, name)
    row["free_like_held"] = float(steady.FREE_LIKE_HELD)
    row["free_flexibility_ratio_railfe"] = summary_ratio(work, steady.free_name(size))
    row["patch_flexibility_m_per_Pa"] = 8 * a * a * b / (3 * row["exact_initial_slope_N"])
    if softer:  # the caps are railfe's to know: its own ratio, on the same patch
        row["penalty_flexibility_m_per_Pa"] = (row["flexibility_ratio_railfe"] *
                                               row["patch_flexibility_m_per_Pa"])
    else:
        row["penalty_flexibility_m_per_Pa"] = penalty_flexibility(
            os.path.join(work, name + "_results"), size, penalty)
    ratio = row["penalty_flexibility_m_per_Pa"] / row["patch_flexibility_m_per_Pa"]
    row["flexibility_ratio"] = ratio
    # The layer in series scales every creepage alike, the spin sin(angle) / r0 too.
    angle = math.asin(math.sin(row["contact_angle_rad"]) / (1 + ratio))
    predicted = convergence.exact(railfe, work, dict(
        row, creepage=row["creepage"] / (1 + ratio), creepage_before=row["creepage_half1"],
        contact_angle_rad=angle))
    for spin in ("", "_spin"):
        fx = predicted[f"exact_longitudinal_force{spin}_N"]
        row[f"predicted_longitudinal_force{spin}_N"] = fx
        row[f"predicted_vs_exact{spin}"] = fx / row[f"exact_longitudinal_force{spin}_N"] - 1
        row[f"longitudinal_force_vs_predicted{spin}"] = row["longitudinal_force_N"] / fx - 1
    return row, [(t, v) for t, v in history[f"fx_{size:g}mm_N"]]


def column(row):
    """The history column of a row's run."""
    return f"fx_f{row['penalty_factor']:g}" + ("_softer" if row["softer_side"] else "") + "_N"


def label(row):
    return f"f = {row['penalty_factor']:g}" + (", softer side" if row["softer_side"] else "")


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = typed_rows(CSV, [])
    histories = typed_rows(HISTORIES, [])
    size = rows[0]["zone_element_size_mm"]
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.6))
    time = [1e3 * r["time_s"] for r in histories]
    for row in rows:
        values = [(t, 1e-3 * r[column(row)]) for t, r in zip(time, histories)
                  if not math.isnan(r[column(row)])]
        line = axes[0].plot([t for t, _ in values], [v for _, v in values], label=label(row),
                            linestyle="--" if row["softer_side"] else "-")[0]
        window = (1e3 * row["window_start_s"], 1e3 * row["window_end_s"])
        axes[0].plot(window, [1e-3 * row["longitudinal_force_N"]] * 2, color=line.get_color(),
                     linewidth=3, alpha=0.5)
        axes[0].plot(window, [1e-3 * row["exact_longitudinal_force_spin_N"]] * 2,
                     color=line.get_color(), linestyle=":", linewidth=2)
    window = (1e3 * rows[0]["window_start_s"], 1e3 * rows[0]["window_end_s"])
    axes[0].plot([], [], color="black", linestyle=":", linewidth=2,
                 label="exact solver at the run's creepage, patch and spin")
    axes[0].axvspan(*window, color="grey", alpha=0.12)
    axes[0].set_xlabel("time (ms; shaded: the window, thick: its mean)")
    axes[0].set_ylabel("creep force Fx (kN; 0.3 ms running mean)")
    hold = f"{rows[0]['hold_creepage']:.2g}"
    axes[0].set_title(f"held at ξ = {hold}: the creep force at each penalty factor")
    axes[0].legend(fontsize=8, loc="lower right")

    softer = [r for r in rows if r["softer_side"]]
    rows = [r for r in rows if not r["softer_side"]]
    factors = [r["penalty_factor"] for r in rows]
    for r in softer:
        axes[1].plot([r["penalty_factor"]], [100 * r["longitudinal_force_vs_exact_spin"]], "D",
                     color="C2", markersize=8, label=f"{label(r)}: FE against exact (spin)")
        axes[1].plot([r["penalty_factor"]], [100 * r["predicted_vs_exact_spin"]], "+",
                     color="C2", markersize=12, label=f"{label(r)}: the penalty layer alone")
    axes[1].plot(factors, [100 * r["longitudinal_force_vs_exact_spin"] for r in rows], "s-",
                 color="C0", label="FE against the exact solver (with the contact angle's spin)")
    axes[1].plot(factors, [100 * r["predicted_vs_exact_spin"] for r in rows], "--", marker="x",
                 color="C0", label="the penalty layer alone: exact at (ξ, φ) / (1 + r)")
    axes[1].plot(factors, [100 * r["longitudinal_force_vs_exact"] for r in rows], "o-",
                 color="C1", alpha=0.6, label="the same without spin: FE against exact")
    axes[1].plot(factors, [100 * r["predicted_vs_exact"] for r in rows], "--", marker="x",
                 color="C1", alpha=0.6, label="without spin: the penalty layer alone")
    for f, r in zip(factors, rows):
        axes[1].annotate(f"r = {r['flexibility_ratio']:.3f}",
                         (f, 100 * r["predicted_vs_exact_spin"]), textcoords="offset points",
                         xytext=(4, 6), fontsize=7)
    axes[1].axhspan(-4, 4, color="green", alpha=0.1, label="±4 %: issue 15's band")
    lowest = min(100 * r[key] for r in rows + softer
                 for key in ("longitudinal_force_vs_exact_spin", "longitudinal_force_vs_exact"))
    axes[1].set_ylim(bottom=min(-4.0, lowest) - 1.5)
    axes[1].set_xscale("log")
    axes[1].set_xlabel("penalty factor f")
    axes[1].set_ylabel("creep force error (%)")
    axes[1].set_title("error against f, and what the penalty's flexibility predicts")
    axes[1].legend(fontsize=7, loc="best")

    for r in softer:
        axes[2].plot([r["steps"] / 1e3], [100 * abs(r["longitudinal_force_vs_exact_spin"])],
                     "D", color="C2", markersize=8, label=f"{label(r)} (with spin)")
        axes[2].annotate(f"{label(r)}, {r['roll_wall_s'] / 60:.0f} min",
                         (r["steps"] / 1e3, 100 * abs(r["longitudinal_force_vs_exact_spin"])),
                         textcoords="offset points", xytext=(4, -12), fontsize=7)
    walls = [r["steps"] / 1e3 for r in rows]  # the cost: one mesh, so steps (wall times shared a
    # busy machine)
    axes[2].plot(walls, [100 * abs(r["longitudinal_force_vs_exact_spin"]) for r in rows], "s-",
                 color="C0", label="with the contact angle's spin")
    axes[2].plot(walls, [100 * abs(r["longitudinal_force_vs_exact"]) for r in rows], "o-",
                 color="C1", alpha=0.6, label="no spin")
    for w, r in zip(walls, rows):
        axes[2].annotate(f"f = {r['penalty_factor']:g}, {r['roll_wall_s'] / 60:.0f} min",
                         (w, 100 * abs(r["longitudinal_force_vs_exact_spin"])),
                         textcoords="offset points", xytext=(4, 4), fontsize=7)
    first = (rows + softer)[0]
    axes[2].set_xlabel(f"steps to {1e3 * first['end_time_s']:g} ms (thousands; "
                       f"{first['elements']:,.0f} elements; labels: wall time on a shared core)")
    axes[2].set_ylabel("|creep force error| (%)")
    axes[2].set_title("speed against accuracy")
    axes[2].set_ylim(bottom=0)
    axes[2].legend(fontsize=8)
    for axis in axes:
        axis.grid(alpha=0.3, which="both")
    fig.suptitle(f"Squeal scene, case 1 held at ξ = {hold}, {size:g} mm contact mesh: the "
                 "penalty layer's tangential flexibility is the missing creep force")
    fig.tight_layout()
    fig.savefig(PNG, dpi=100)


def main():
    parser = study_parser(__doc__.split("\n")[0], "squeal_steady_penalty_work", ROOT)
    parser.add_argument("--penalties", type=float, nargs="*", default=PENALTIES)
    parser.add_argument("--softer", type=float, nargs="*", default=SOFTER,
                        help="factors run with Penalty stiffness 'bulk modulus, softer side'")
    parser.add_argument("--size", type=float, default=3, help="contact zone element size (mm)")
    steady.add_run_arguments(parser, END_TIME, WINDOW)
    parser.add_argument("--name", default="",
                        help="a run set other than the 3 mm one: its files get _NAME (e.g. "
                             "2mm_4ms: squeal_steady_penalty_2mm_4ms.csv)")
    parser.add_argument("--free-like-held", action="store_true",
                        help="run each free twin at its held run's penalty settings instead of "
                             "at f = 1 on the plain bulk modulus")
    parser.add_argument("--hold", type=float, default=HOLD,
                        help="the held run's creepage (the free twin's is 0 whatever it is)")
    parser.add_argument("--depth", type=float, nargs=2, metavar=("SECTION", "WHEEL"),
                        help="the rail section's and the wheel's element sizes away from the "
                             "running surfaces (mm; the demo's: 20 60), both runs of the pair")
    parser.add_argument("--hub", type=float,
                        help="the held hub's radius (m; the generator's 0.385), both runs")
    parser.add_argument("--cylinder", action="store_true",
                        help="the control: a cylindrical tread on the rail upright (Hertz's "
                             "contact, no spin), both runs")
    args = parser.parse_args()
    global CSV, HISTORIES, PNG
    CSV, HISTORIES, PNG = outputs(args.name)
    if not args.replot:
        steady.HOLD, steady.FREE_LIKE_HELD = args.hold, args.free_like_held
        steady.DEPTH, steady.HUB, steady.CYLINDER = args.depth, args.hub, args.cylinder
        timeline = steady.Timeline(args.end_time, args.window)
        rows, columns = [], {}
        runs = [(f, False) for f in args.penalties] + [(f, True) for f in args.softer]
        for penalty, softer in runs:
            row, history = one_factor(args.railfe, args.work, args.size, penalty, softer,
                                      timeline, args.reuse)
            rows.append(row)
            columns[column(row)] = history
        write_rows(CSV, rows)
        write_rows(HISTORIES, steady.table(HISTORIES, "time_s", columns))
    if args.cylinder:  # its free twin carries 8 kN: only references with its offset mean much
        print("the control's chart: regression/studies/squeal_steady_nonhertzian.py")
        return
    plot()


if __name__ == "__main__":
    main()
