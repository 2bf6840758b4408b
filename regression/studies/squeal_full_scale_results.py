#!/usr/bin/env python3
"""The squeal scene's full-scale results (issue 16), from the results directories of the shipped
decks' runs (inputs/scenes/squeal_case<k>.xml): the seed's Figs. 4-7, 9-10 and Tables 3-4.

For each case given (--case K DIR):
- Fig. 4: the contact forces, every 10th row, to docs/data/squeal_case<K>_full_forces.csv; all
  cases in one chart, docs/img/squeal_full_forces.png;
- Table 3 and Figs. 6-7: the FE patch at --time beside the exact steady-rolling solver's patch
  for the same FN, Fx, Fy (regression/charts/patch_vs_exact.py). The exact solver takes the
  real profiles' separation (as CONTACT does; the S1002 wheel on the 54E1 rail is too conformal
  for an ellipse, docs/verification.md), built by squeal_placement.separation_rows at the
  patch's contact angle (a plane fitted to its nodes) with the wheel moved sideways by the axle
  box's lateral displacement at that instant, and the wheel's rolling radii; the spin is
  sin(angle) / r0. A second row gives the ellipse of the FE patch's moments, the reference of
  earlier sessions, for contrast. Rows to docs/data/squeal_full_table3.csv, the profiles' chart
  to docs/img/squeal_full_patch_case<K>.png;
- Fig. 5: shear traction and mu p along the patch's centre line at the eight instants 18.1-18.8
  ms (one period of the creep force's 1.25 kHz oscillation; runs of decks from 2026-11-29 on),
  docs/img/squeal_full_centre_line_case<K>.png and its CSV in docs/data;
- Table 4 and Figs. 9-10: the rim point's velocity from 2 ms, its Welch PSD (3 segments, 118 Hz)
  and the peaks matched to the modes of the run's own modal step (regression/charts/
  rim_vibration.py): docs/data/squeal_full_rim_peaks.csv (a case column added), the PSD and
  wavelet charts to docs/img/squeal_full_rim_{psd,wavelet}_case<K>.png; the damped sines fitted
  to the same record (ESPRIT, regression/charts/damped_sines.py), each beside its nearest mode,
  to docs/data/squeal_full_rim_poles.csv;
- case 5 beside case 3 (slipping nodes, forces and bound), docs/img/
  squeal_full_case5_vs_case3.png, from the runs given or else from their forces in docs/data;
- a summary row (window means over --window of the forces and the patch, the axle box's lateral
  displacement at --time) to docs/data/squeal_full_cases.csv.
The tables of all cases keep the rows of cases not given (their runs may be gone) and replace
those of the cases given; the forces chart draws the others from their CSV in docs/data.

    /usr/bin/python3 regression/studies/squeal_full_scale_results.py --case 1 /tmp/case1/out \\
        --case 3 /tmp/case3/out [--railfe build/bin/railfe] [--time 0.019] [--work /tmp/sq]

A few minutes (the exact solver twice per case, the spectra); the runs themselves are hours
(docs/verification.md).
"""
import argparse
import csv
import functools
import glob
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
CHARTS = os.path.join(ROOT, "regression", "charts")
sys.path[:0] = [CHARTS, os.path.join(ROOT, "regression", "scenes")]
import squeal_placement as placement  # noqa: E402
from railfe_runs import kept_rows  # noqa: E402
from make_squeal_decks import LATERAL_CREEPAGE as NOMINAL_LATERAL_CREEPAGE  # noqa: E402
from make_squeal_decks import COULOMB_FRICTION as MU, falling_friction  # noqa: E402
import patch_wave_speed  # noqa: E402
from patch_centre_line import read_patch  # noqa: E402

DATA = os.path.join(ROOT, "docs", "data")
IMG = os.path.join(ROOT, "docs", "img")
PAIR = "roll_contact_wheel-rail"
SPEED = 100 / 3.6
ROLLING_RADIUS = 0.46038  # m, the decks' r0 (omega = V / r0)
AXLE_CENTRE = (0.7, 0.0, 0.459916265)  # m, the wheel part's Translation in the full decks
CENTRE_LINE_TIMES = [0.0181 + 0.0001 * k for k in range(8)]
WAVE_TIMES = [0.01855 + 2.5e-7 * k for k in range(32)]  # the decks' burst of patch files
RIM_START = 0.002  # s: the rim records leave out the first 2 ms (the roll's start)
RIM_POLE_ORDER = 24  # ESPRIT model order: 12 damped sines per component (at three orders)


def run(command):
    """Runs a helper script; its output is shown only when it fails."""
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{done.stdout}{done.stderr}")
    return done.stdout


@functools.lru_cache(maxsize=None)
def patch_instants(results):
    """(instant, path) of every patch file of `results`, each file's first row read once."""
    instants = []
    for path in glob.glob(os.path.join(results, f"{PAIR}_patch_*.csv")):
        with open(path) as f:
            row = next(csv.DictReader(f), None)
        if row is not None:
            instants.append((float(row["time_s"]), path))
    return instants


def patch_at(results, time):
    """The patch file of `results` whose instant is within 1 us of `time` (s), and that
    instant; (None, None) if there is none."""
    best = min(patch_instants(results), key=lambda item: abs(item[0] - time), default=None)
    if best is None or abs(best[0] - time) > 1e-6:
        return None, None
    return best[1], best[0]


@functools.lru_cache(maxsize=None)
def roll_histories(results):
    """The run's roll_histories.csv, read once."""
    return np.genfromtxt(os.path.join(results, "roll_histories.csv"), delimiter=",", names=True)


def history_value(results, column, time):
    """A column of roll_histories.csv at the row nearest `time`."""
    rows = roll_histories(results)
    return float(rows[column][np.argmin(np.abs(rows["time_s"] - time))])


def contact_angle(patch):
    """Angle (rad) of the contact plane across the track: a plane z = c + m y fitted to the
    patch's nodes, weighted by their normal forces; positive when the normal leans to +y."""
    weight = patch["pressure_Pa"] * patch["area_m2"]
    slope = np.polyfit(patch["y_m"], patch["z_m"], 1, w=np.sqrt(weight))[0]
    return math.atan(-slope)


def table3_rows(case, results, time, railfe, work):
    """The case's two Table-3 rows (profiles, ellipse), and its chart to docs/img. Case 5 has
    none: falling friction has no counterpart in the exact steady solver's Coulomb law, so its
    chart is the run's own patch map at that instant (the seed's Fig. 7)."""
    path, instant = patch_at(results, time)
    if path is None:
        raise SystemExit(f"{results}: no patch file at t = {time} s")
    if falling_friction(case):
        shutil.copy(os.path.splitext(path)[0] + ".png",
                    os.path.join(IMG, f"squeal_full_patch_case{case}.png"))
        return []
    patch = read_patch(path)
    angle = contact_angle(patch)
    shift = history_value(results, "axle_y_displacement_y_m", instant)
    separation = os.path.join(work, f"separation_case{case}.csv")
    with open(separation, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["y_m", "separation_m", "rolling_radius_m"])
        out.writerows(placement.separation_rows(angle, wheel_shift=shift))
    spin = math.sin(angle) / ROLLING_RADIUS
    table = os.path.join(work, f"table3_case{case}.csv")
    if os.path.exists(table):
        os.remove(table)
    common = [sys.executable, os.path.join(CHARTS, "patch_vs_exact.py"), "--railfe", railfe,
              "--mu", str(MU), "--spin", repr(spin), "--table", table, path]
    run(common + ["--geometry", "separation", "--separation", separation,
                  "--A", repr(1 / (2 * ROLLING_RADIUS)),
                  "--png", os.path.join(IMG, f"squeal_full_patch_case{case}.png"),
                  "--work", os.path.join(work, f"exact_case{case}_profiles")])
    run(common + ["--png", os.path.join(work, f"patch_case{case}_ellipse.png"),
                  "--work", os.path.join(work, f"exact_case{case}_ellipse")])
    with open(table) as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        row.update({"case": case, "contact_angle_rad": angle, "axle_lateral_m": shift,
                    "nominal_lateral_creepage": NOMINAL_LATERAL_CREEPAGE[case]})
    return rows


def forces(results):
    """The contact history as a dict of numpy columns."""
    rows = np.genfromtxt(os.path.join(results, f"{PAIR}.csv"), delimiter=",", names=True)
    return {name: rows[name] for name in rows.dtype.names}


def summary_row(case, history, window, results, time):
    """Window means of the forces and the patch, for the cases' table."""
    inside = (history["time_s"] >= window[0]) & (history["time_s"] <= window[1])
    mean = lambda name: float(np.mean(history[name][inside]))  # noqa: E731
    creep = np.hypot(history["tangential_1_N"], history["tangential_2_N"])[inside]
    return {"case": case, "window_start_s": window[0], "window_end_s": window[1],
            "normal_force_N": mean("normal_force_N"), "longitudinal_force_N": mean("tangential_1_N"),
            "lateral_force_N": mean("tangential_2_N"),
            "lateral_force_std_N": float(np.std(history["tangential_2_N"][inside])),
            "creep_force_N": float(np.mean(creep)),
            "creep_force_over_mu_N": float(np.mean(creep / history["friction_bound_N"][inside])),
            "contact_area_m2": mean("contact_area_m2"), "active_nodes": mean("active_nodes"),
            "slipping_nodes": mean("slipping_nodes"),
            "axle_lateral_at_time_m": history_value(results, "axle_y_displacement_y_m", time),
            "nominal_lateral_creepage": NOMINAL_LATERAL_CREEPAGE[case]}


def forces_chart(histories, png):
    """Fig. 4 for every case: normal, longitudinal and lateral force against time (kN)."""
    fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
    for case, h in sorted(histories.items()):
        t = 1e3 * h["time_s"]
        for ax, name in zip(axes, ("normal_force_N", "tangential_1_N", "tangential_2_N")):
            ax.plot(t, 1e-3 * h[name], linewidth=0.7, label=f"case {case}")
    first = min(histories)
    axes[1].plot(1e3 * histories[first]["time_s"], 1e-3 * histories[first]["friction_bound_N"],
                 color="red", linestyle="--", linewidth=0.7,
                 label=f"traction bound mu N (case {first})")
    for ax, label in zip(axes, ("normal force (kN)", "longitudinal force (kN)",
                                "lateral force (kN)")):
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    axes[-1].set_xlabel("time (ms)")
    fig.suptitle("Squeal scene at full scale: contact forces on the wheel (lateral axle motion "
                 "from 16 ms in cases 2-5)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def falling_against_coulomb(histories, png):
    """Case 5 beside case 3 from 15.5 ms (the same lateral motion, falling friction against
    Coulomb): slipping nodes, longitudinal force with its bound mu N, lateral force."""
    fig, axes = plt.subplots(3, 1, figsize=(10, 8), sharex=True)
    # Both at the coarser sampling (a case from docs/data has every 10th row), so that the
    # flicker of the slipping nodes is drawn alike.
    spacing = {case: float(np.median(np.diff(histories[case]["time_s"]))) for case in (3, 5)}
    for case, colour in ((3, "tab:blue"), (5, "tab:red")):
        stride = max(1, int(round(max(spacing.values()) / spacing[case])))
        h = {name: values[::stride] for name, values in histories[case].items()}
        late = h["time_s"] >= 0.0155
        t = 1e3 * h["time_s"][late]
        axes[0].plot(t, h["slipping_nodes"][late], color=colour, lw=0.6, label=f"case {case}")
        axes[1].plot(t, h["tangential_1_N"][late] / 1e3, color=colour, lw=0.6,
                     label=f"case {case}: Fx")
        axes[1].plot(t, h["friction_bound_N"][late] / 1e3, "--", color=colour, lw=0.6,
                     label=f"case {case}: bound μN")
        axes[2].plot(t, h["tangential_2_N"][late] / 1e3, color=colour, lw=0.6,
                     label=f"case {case}")
    axes[0].set_ylabel("slipping nodes")
    axes[1].set_ylabel("longitudinal force (kN)")
    axes[2].set_ylabel("lateral force (kN)")
    axes[2].set_xlabel("time (ms)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, ncol=2)
    fig.suptitle("Case 5 (falling friction) against case 3 (Coulomb 0.45), full scale")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def centre_line(case, results):
    """Fig. 5 from the eight instants, if the run wrote them."""
    paths = [patch_at(results, t)[0] for t in CENTRE_LINE_TIMES]
    if any(p is None for p in paths):
        print(f"case {case}: no patch files at 18.1-18.8 ms (an older deck); no centre line")
        return
    falling = falling_friction(case)
    law = ["--falling", *map(str, falling)] if falling else ["--mu", str(MU)]
    run([sys.executable, os.path.join(CHARTS, "patch_centre_line.py"), *law,
         "--png", os.path.join(IMG, f"squeal_full_centre_line_case{case}.png"),
         "--csv", os.path.join(DATA, f"squeal_full_centre_line_case{case}.csv")] + paths)


def wave_speed(case, results, png):
    """The waves seen in the patch over the decks' burst of patch files (patch_wave_speed.py):
    rows of the fitted speed per signal; none if the run has no burst."""
    paths = [patch_at(results, t)[0] for t in WAVE_TIMES]
    if any(p is None for p in paths):
        print(f"case {case}: no burst of patch files at 18.55 ms (an older deck); no wave speed")
        return []
    rows, patches, where = patch_wave_speed.fit([read_patch(p) for p in paths])
    patch_wave_speed.chart(png, patches, where, rows, f"case {case}")
    return [dict(row, case=case) for row in rows]


def rim_peaks(case, results, work):
    """Table 4 rows of the case: its PSD peaks and its fitted damped sines (ESPRIT, far finer
    than the 118 Hz of the PSD), each against its own modes."""
    prefix = os.path.join(work, f"rim_case{case}")
    run([sys.executable, os.path.join(CHARTS, "rim_vibration.py"),
         os.path.join(results, "roll_histories.csv"), os.path.join(results, "modes_modes.csv"),
         prefix, "--history", "rim", "--quantity", "velocity",
         "--exodus", os.path.join(results, "modes.exo"), "--rim-set", "wheel.rim point",
         "--centre", *[repr(c) for c in AXLE_CENTRE], "--speed", repr(SPEED),
         "--spin-history", "axle spin", "--start", repr(RIM_START), "--segments", "3",
         "--max-hz", "2600", "--prominence", "0.5", "--poles", str(RIM_POLE_ORDER)])
    for kind in ("psd", "wavelet"):
        shutil.copy(f"{prefix}_{kind}.png", os.path.join(IMG, f"squeal_full_rim_{kind}_case{case}.png"))
    record = {"record_start_s": RIM_START,
              "record_end_s": float(roll_histories(results)["time_s"][-1])}
    tables = []
    for kind in ("peaks", "poles"):
        with open(f"{prefix}_{kind}.csv") as f:
            tables.append([dict(row, case=case, **(record if kind == "poles" else {}))
                           for row in csv.DictReader(f)])
    return tables


def write(path, rows):
    columns = list(rows[0].keys())
    for row in rows:
        columns += [k for k in row if k not in columns]
    with open(path, "w", newline="") as f:
        out = csv.DictWriter(f, columns)
        out.writeheader()
        out.writerows(rows)


def write_cases(path, rows, cases):
    """Writes the given cases' rows into a table of all cases: rows of other cases already in
    `path` are kept (a run of one case must not drop the others' results, whose runs may be
    gone), and the given cases' old rows are replaced. Rows are ordered by case, stably."""
    merged = sorted(kept_rows(path, "case", cases) + rows, key=lambda row: int(row["case"]))
    if merged:
        write(path, merged)


def shipped_histories(exclude):
    """The other cases' forces as the docs hold them (every 10th row), for the charts of all
    cases when only some were given."""
    histories = {}
    for path in glob.glob(os.path.join(DATA, "squeal_case*_full_forces.csv")):
        case = int(os.path.basename(path)[len("squeal_case"):].split("_")[0])
        if case not in exclude:
            rows = np.genfromtxt(path, delimiter=",", names=True)
            histories[case] = {name: rows[name] for name in rows.dtype.names}
    return histories


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--case", nargs=2, action="append", required=True,
                        metavar=("K", "DIR"), help="case number and its results directory")
    parser.add_argument("--railfe", default=os.path.join(ROOT, "build", "bin", "railfe"))
    parser.add_argument("--time", type=float, default=0.019, help="Table 3's instant (s)")
    parser.add_argument("--window", type=float, nargs=2, default=(0.0165, 0.019),
                        help="the summary's window (s)")
    parser.add_argument("--work", default="/tmp/squeal_full_results")
    args = parser.parse_args()
    cases = {}
    for number, directory in args.case:
        if number not in {"1", "2", "3", "4", "5"}:
            parser.error(f"--case {number}: the scene's cases are 1 to 5")
        if not os.path.isfile(os.path.join(directory, "summary.json")):
            parser.error(f"--case {number} {directory}: no summary.json (not a finished run)")
        cases[int(number)] = directory
    os.makedirs(args.work, exist_ok=True)
    table3, summaries, peaks, poles, waves, histories = [], [], [], [], [], {}
    for case, results in sorted(cases.items()):
        print(f"case {case}: {results}")
        history = forces(results)
        histories[case] = history
        write(os.path.join(DATA, f"squeal_case{case}_full_forces.csv"),
              [{k: f"{v[i]:.6g}" for k, v in history.items()}
               for i in range(0, len(history["time_s"]), 10)])
        summaries.append(summary_row(case, history, args.window, results, args.time))
        table3 += table3_rows(case, results, args.time, args.railfe, args.work)
        centre_line(case, results)
        case_peaks, case_poles = rim_peaks(case, results, args.work)
        peaks += case_peaks
        poles += case_poles
        waves += wave_speed(case, results,
                            os.path.join(IMG, f"squeal_full_patch_waves_case{case}.png"))
    given = set(cases)
    histories.update(shipped_histories(exclude=given))
    forces_chart(histories, os.path.join(IMG, "squeal_full_forces.png"))
    if 3 in histories and 5 in histories:
        falling_against_coulomb(histories, os.path.join(IMG, "squeal_full_case5_vs_case3.png"))
    for name, rows in (("table3", table3), ("cases", summaries), ("rim_peaks", peaks),
                       ("rim_poles", poles), ("wave_speeds", waves)):
        write_cases(os.path.join(DATA, f"squeal_full_{name}.csv"), rows, given)
    for row in table3:
        print(f"case {row['case']} {row['geometry']:10s} FN {float(row['FN_N']) / 1e3:7.2f} kN "
              f"Fx {float(row['Fx_N']) / 1e3:6.2f} Fy {float(row['Fy_N']) / 1e3:6.2f} kN "
              f"xi {float(row['xi']):.3e} eta {float(row['eta']):.3e} adhesion FE "
              f"{float(row['fe_adhesion_share']):.2f} exact {float(row['exact_adhesion_share']):.2f}")


if __name__ == "__main__":
    main()
