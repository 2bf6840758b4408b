#!/usr/bin/env python3
"""Do the creep forces damp the wheel's (0,0) axial mode out of the rolling wheel's rim response
(issue 16, Table 4: the full-scale records never show it)? A lateral pulse on the demo wheel
says no.

The hypothesis. Where the patch sticks, a vibration velocity u' of the tread at the contact
changes the creepage by u'/V, and Kalker's linear theory turns that into a force -f u'/V: a
dashpot c = f/V (f11 = G a b C11 along the rail, f22 = G a b C22 across it) to a rigid rail. A
mode phi of unit modal mass then has the damping ratio

    zeta = (c_x phi_x^2 + c_y phi_y^2) / (2 omega)

with phi_x, phi_y its tread displacement at the contact. A mode with n >= 1 nodal diameters has
a twin turned by 90 / n degrees: one member can have its nodal line through the contact,
undamped, the other carries the pair's whole zeta. A mode with n = 0 has no twin. This gives
the (0,0) mode zeta = 0.91 (full scale) and 0.92 (demo): critically damped, never ringing.

The check (--run): the demo-scale wheel in free rolling, the axle box given a lateral pulse (a
raised cosine of PULSE_AMPLITUDE over PULSE_DURATION from PULSE_START), twice: with the scene's
Coulomb friction and frictionless. One damped sine fitted by least squares to the rim point's
lateral velocity after the pulse gives the (0,0) mode's frequency and damping in the rolling FE
model (columns fitted_*); ESPRIT (charts/damped_sines.py, columns esprit_*) checks it where the
record holds enough periods: on the demo runs the two agree within 1.5 % in frequency and 0.002
in damping. The full-scale check (--full-deck, --full-results) is case 1 with the same pulse
after the torque ramp: two periods to 19 ms, too few for ESPRIT's stabilisation check. The FE's damping ratio is what decides; the rigid-rail figure is an upper
bound, and the column implied_series_stiffness_N_per_m is the lateral stiffness a spring in
series with the dashpot (the rail's head moving with the tread) would need to bring it down to
the FE's: c_eff = c / (1 + (c omega / k)^2).

    /usr/bin/python3 regression/studies/squeal_creep_damping.py [build/bin/railfe] \\
        --modes FULL_RUN_DIR --patch 6.14e-3 9.76e-3 [--run] [--replot]

--modes reads a full-scale run's modes.exo and modes_modes.csv (its patch's semi-axes from
--patch, m); --run takes about 10 min, the two runs side by side on two cores. Writes
docs/data/squeal_creep_damping_full.csv (the full-scale wheel's rigid-rail figures per mode),
docs/data/squeal_creep_damping_demo.csv (the demo wheel's, with the runs' fits),
docs/data/squeal_creep_damping_pulse.csv (the rim's lateral velocity in both runs) and
docs/img/squeal_creep_damping.png.
"""
import math
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from scipy.io import netcdf_file
from scipy.optimize import curve_fit

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE, os.path.join(ROOT, "regression", "charts"),
                os.path.join(ROOT, "regression", "scenes")]
import damped_sines  # noqa: E402
import squeal_mesh_convergence as convergence  # noqa: E402
from railfe_runs import csv_rows, run_or_reuse, study_parser, typed_rows, write_rows  # noqa: E402
from make_squeal_decks import SPEED  # noqa: E402
from wickens_critical_speed import kalker  # noqa: E402

DATA = os.path.join(ROOT, "docs", "data")
FULL_CSV = os.path.join(DATA, "squeal_creep_damping_full.csv")
DEMO_CSV = os.path.join(DATA, "squeal_creep_damping_demo.csv")
PULSE_CSV = os.path.join(DATA, "squeal_creep_damping_pulse.csv")
FULL_PULSE_CSV = os.path.join(DATA, "squeal_creep_damping_full_pulse.csv")
PNG = os.path.join(ROOT, "docs", "img", "squeal_creep_damping.png")
SHEAR_MODULUS = 210e9 / (2 * 1.3)  # Pa, the scene's steel
# The pulse is long enough to leave the modes above 1 kHz nearly alone (its spectrum falls as
# 1/f^3 beyond 2 / PULSE_DURATION) and short against the (0,0) mode's period; its largest
# lateral speed, pi A / duration = 79 mm/s, is a lateral creepage of 0.3 %, a third of what
# saturates the demo patch.
PULSE_START, PULSE_DURATION, PULSE_AMPLITUDE = 1e-3, 2e-3, 5e-5  # s, s, m
END_TIME = 0.016  # s: three periods of the (0,0) mode after the pulse
FIT_START = PULSE_START + PULSE_DURATION  # the free response only
FIT_BAND = (50.0, 3000.0)  # Hz
FIT_ORDER = 16
NEAR = 0.25  # a fitted sine names the (0,0) mode within this share of its frequency
DECK_OPTIONS = ["--case", "3", "--scale", "demo", "--torque", "0", "--modes", "--end-time",
                f"{END_TIME:g}", "--rail-length", "2.4", "--start-x", "0.9", "--zone-end", "0.47"]
RUNS = ("coulomb", "frictionless")
# The full-scale check (--full-deck, --full-results): case 3's deck with its lateral motion
# replaced by the pulse, which leaves case 1 (driving torque, Coulomb 0.45, 19 ms) and the pulse
# after the torque ramp, so that the (0,0) mode rings for two periods before the end.
FULL_OPTIONS = ["--case", "3"]
FULL_PULSE_START = 7e-3  # s


def contact_modes(exodus, table):
    """Each mode's row of the modal table with its mass-normalised displacement (phi_x, phi_y,
    phi_z) at the wheel's running-circle node lowest down: the contact point."""
    data = netcdf_file(exodus, "r", mmap=False)
    v = data.variables
    names = ["".join(c.decode() for c in row if c != b"").strip() for row in v["ns_names"][:]]
    nodes = np.array(v[f"node_ns{names.index('wheel.running_circle') + 1}"][:], dtype=int) - 1
    node = nodes[np.argmin(np.array(v["coordz"][:])[nodes])]
    rows = csv_rows(table)
    for k, row in enumerate(rows):
        row["phi"] = [float(v[f"vals_nod_var{c}"][k, node]) for c in (1, 2, 3)]
    data.close()
    return rows


def creep_damping(rows, a, b):
    """The rigid-rail damping ratio of each n = 0 mode and each pair's damped twin (module doc),
    and the dashpots' coefficients."""
    c11, c22 = kalker(a, b)
    cx, cy = (SHEAR_MODULUS * a * b * c / SPEED for c in (c11, c22))
    by_mode = {row["mode"]: row for row in rows}
    out = []
    for row in rows:
        omega = 2 * math.pi * float(row["frequency_hz"])

        def zeta(r):
            return (cx * r["phi"][0] ** 2 + cy * r["phi"][1] ** 2) / (2 * omega)
        partner = by_mode.get(row["partner"])
        if partner is not None and partner["partner"] != row["mode"]:
            partner = None  # a one-sided pairing is no twin
        if partner is not None and int(partner["mode"]) < int(row["mode"]):
            continue  # a pair is one row, under its first member
        total = zeta(row) + (zeta(partner) if partner is not None else 0.0)
        out.append({"mode": int(row["mode"]), "frequency_hz": float(row["frequency_hz"]),
                    "family": row["family"], "nodal_diameters": int(row["nodal_diameters"]),
                    "nodal_circles": int(row["nodal_circles"]),
                    "pair": float(partner is not None),
                    "contact_phi_x": row["phi"][0], "contact_phi_y": row["phi"][1],
                    "contact_phi_z": row["phi"][2],
                    "damping_ratio_rigid_rail": total,
                    "patch_a_m": a, "patch_b_m": b, "lateral_dashpot_N_s_per_m": cy,
                    "longitudinal_dashpot_N_s_per_m": cx})
    return out


def pulse_deck(friction, options=DECK_OPTIONS, start=PULSE_START, scene="demo wheel in free "
               "rolling", duration=PULSE_DURATION, amplitude=PULSE_AMPLITUDE):
    """The deck `options` make (the demo in free rolling unless given) with the axle box's
    lateral pulse (a raised cosine of `amplitude` over `duration`) from `start` instead of its
    lateral motion, with Coulomb friction or none."""
    command = [sys.executable, os.path.join(ROOT, "regression", "scenes", "make_squeal_decks.py")]
    text = subprocess.run(command + options, check=True, capture_output=True, text=True).stdout
    pulse = (f"t &lt; {start:g} ? 0 : (t &lt; {start + duration:g} ? "
             f"{amplitude / 2:g}*(1 - cos(2*_pi*(t - {start:g})/"
             f"{duration:g})) : 0)")
    text, count = re.subn(r'(name="Motion y" type="string" value=")[^"]*"',
                          lambda m: m.group(1) + pulse + '"', text)
    assert count == 1, "the deck's lateral motion was not found"
    text = re.sub(r'(name="Title" type="string" value=")[^"]*"',
                  lambda m: m.group(1) + f'Squeal {scene}, a lateral pulse on the axle box, '
                  f'friction {friction}"', text, count=1)
    if friction == "frictionless":
        text, count = re.subn(r'<Parameter name="Friction" type="string" value="coulomb"/>\s*'
                              r'<Parameter name="Friction coefficient" type="double" '
                              r'value="[^"]*"/>',
                              '<Parameter name="Friction" type="string" value="none"/>', text)
        assert count == 1, "the deck's friction was not found"
    return text


def run_pair(railfe, work):
    """Both pulse runs side by side: {name: results dir}. A run already in `work` from the same
    deck is read, not run again."""
    def one(name):
        return run_or_reuse(railfe, pulse_deck(name), work, f"pulse_{name}")[0]
    with ThreadPoolExecutor(max_workers=2) as pool:
        return dict(zip(RUNS, pool.map(one, RUNS)))


def rim_lateral_velocity(results):
    """Time (s) and the rim point's lateral velocity (m/s) from the run's histories."""
    rows = csv_rows(os.path.join(results, "roll_histories.csv"))
    return (np.array([float(r["time_s"]) for r in rows]),
            np.array([float(r["rim vy_velocity_y_m_per_s"]) for r in rows]))


def single_sine(t, v, frequency, start):
    """Least squares of one damped sine, a constant and a trend to the record from `start`,
    started near `frequency`: {frequency_hz, damping_ratio, rms}. ESPRIT (fitted_mode) needs
    more periods than the full-scale record holds; on the demo runs the two agree (module doc)."""
    keep = t >= start
    s, y = t[keep] - start, v[keep]

    def model(s, amplitude, zeta, f, phase, offset, trend):
        return (amplitude * np.exp(-zeta * 2 * np.pi * f * s) * np.cos(2 * np.pi * f * s + phase)
                + offset + trend * s)
    best = None
    for phase in (0.0, 1.5, 3.0, 4.5):
        try:
            p, _ = curve_fit(model, s, y, p0=[1.4 * np.std(y), 0.02, frequency, phase,
                                              np.mean(y), 0.0], maxfev=20000)
        except RuntimeError:
            continue
        misfit = np.std(y - model(s, *p))
        if best is None or misfit < best[0]:
            best = (misfit, p)
    if best is None or abs(best[1][2] / frequency - 1) > NEAR:
        return None
    amplitude, zeta, f = best[1][:3]
    return {"frequency_hz": f, "damping_ratio": zeta, "rms": abs(amplitude) / math.sqrt(2)}


def fitted_mode(t, v, frequency, start=FIT_START):
    """The damped sine nearest `frequency` (within NEAR of it) in the free response after the
    pulse (from `start`); None where there is none: a mode damped past ringing leaves no sine."""
    keep = t >= start
    sines = damped_sines.stable_poles(v[keep], t[1] - t[0], FIT_BAND, order=FIT_ORDER,
                                      floor=0.0)
    near = [s for s in sines if abs(s["frequency_hz"] / frequency - 1) <= NEAR]
    return min(near, key=lambda s: abs(s["frequency_hz"] - frequency), default=None)


def patch_semi_axes(results):
    """The mean semi-axes (m) over the run's patch files before the pulse."""
    shapes = [convergence.patch_shape(os.path.join(results, f)) for f in os.listdir(results)
              if re.match(r"roll_contact_wheel-rail_patch_\d+\.csv$", f)]
    return (sum(s["patch_a_m"] for s in shapes) / len(shapes),
            sum(s["patch_b_m"] for s in shapes) / len(shapes))


def zero_zero(rows):
    """The (0,0) axial mode: the lowest axial mode without nodal diameters."""
    return min((r for r in rows if r["family"] == "axial" and r["nodal_diameters"] == 0),
               key=lambda r: r["frequency_hz"])


def check_runs(railfe, work):
    """The two pulse runs: the demo wheel's rigid-rail rows with the (0,0) mode's fits, and the
    rim's lateral velocity in both runs."""
    results = run_pair(railfe, work)
    coulomb = results["coulomb"]
    a, b = patch_semi_axes(coulomb)
    rows = creep_damping(contact_modes(os.path.join(coulomb, "modes.exo"),
                                       os.path.join(coulomb, "modes_modes.csv")), a, b)
    mode = zero_zero(rows)
    pulse = {}
    for name, path in results.items():
        t, v = rim_lateral_velocity(path)
        pulse["time_s"], pulse[f"rim_lateral_velocity_{name}_m_per_s"] = t, v
        for method, sine in (("fitted", single_sine(t, v, mode["frequency_hz"], FIT_START)),
                             ("esprit", fitted_mode(t, v, mode["frequency_hz"]))):
            for key in ("frequency_hz", "damping_ratio", "rms"):
                mode[f"{method}_{name}_{key}"] = sine[key] if sine else float("nan")
    ratio = mode["damping_ratio_rigid_rail"] / mode["fitted_coulomb_damping_ratio"]
    c_omega = mode["lateral_dashpot_N_s_per_m"] * 2 * math.pi * mode["frequency_hz"]
    mode["implied_series_stiffness_N_per_m"] = (c_omega / math.sqrt(ratio - 1) if ratio > 1
                                                else float("nan"))
    for row in rows:
        for key in mode:
            row.setdefault(key, float("nan"))
    return rows, pulse


def full_check(results):
    """The full-scale pulse run in `results` (--full-deck, run by hand): the wheel's rigid-rail
    rows from its own modal step and patches, the (0,0) mode's fit, and the rim's lateral
    velocity from the torque ramp's end (every 4th sample)."""
    rows = creep_damping(contact_modes(os.path.join(results, "modes.exo"),
                                       os.path.join(results, "modes_modes.csv")),
                         *patch_semi_axes(results))
    mode = zero_zero(rows)
    t, v = rim_lateral_velocity(results)
    start = FULL_PULSE_START + PULSE_DURATION
    for method, sine in (("fitted", single_sine(t, v, mode["frequency_hz"], start)),
                         ("esprit", fitted_mode(t, v, mode["frequency_hz"], start))):
        for key in ("frequency_hz", "damping_ratio", "rms"):
            mode[f"{method}_coulomb_{key}"] = sine[key] if sine else float("nan")
    for row in rows:
        for key in mode:
            row.setdefault(key, float("nan"))
    keep = np.nonzero(t >= 0.006)[0][::4]
    return rows, [{"time_s": t[k], "rim_lateral_velocity_m_per_s": v[k]} for k in keep]


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    full = os.path.exists(FULL_PULSE_CSV)  # the full-scale pulse run, where it was run
    fig, axes = plt.subplots(1, 3 if full else 2, figsize=(22 if full else 15, 5.2))
    if full:
        full_pulse(axes[1])
    chart = axes[-1]
    pulse = typed_rows(PULSE_CSV, [])
    demo = typed_rows(DEMO_CSV, ["family"])
    mode = zero_zero(demo)
    t = np.array([r["time_s"] for r in pulse]) * 1e3
    for name, colour in zip(RUNS, ("C0", "C3")):
        fit = (f"fit: {mode[f'fitted_{name}_frequency_hz']:.0f} Hz, "
               f"zeta {mode[f'fitted_{name}_damping_ratio']:.3f}")
        axes[0].plot(t, [1e3 * r[f"rim_lateral_velocity_{name}_m_per_s"] for r in pulse],
                     color=colour, lw=0.8, label=f"{name} ({fit})")
    axes[0].axvspan(1e3 * PULSE_START, 1e3 * (PULSE_START + PULSE_DURATION), color="grey",
                    alpha=0.2, label=f"axle box pulse, {PULSE_AMPLITUDE * 1e6:g} um")
    axes[0].set_xlabel("time (ms)")
    axes[0].set_ylabel("rim point's lateral velocity (mm/s)")
    axes[0].set_title(f"demo wheel in free rolling, a lateral pulse on the axle box: the (0,0) "
                      f"mode ({mode['frequency_hz']:.0f} Hz clamped)\nrings in both runs; a "
                      f"creep dashpot to a rigid rail would give zeta "
                      f"{mode['damping_ratio_rigid_rail']:.2f}", fontsize=10)
    axes[0].legend(fontsize=8)
    for path, label, marker in ((FULL_CSV, "full-scale wheel", "o"), (DEMO_CSV, "demo wheel", "s")):
        rows = typed_rows(path, ["family"])
        for single, fill in ((True, "full"), (False, "none")):
            picked = [r for r in rows if (r["nodal_diameters"] == 0) == single]
            chart.plot([r["frequency_hz"] for r in picked],
                         [max(r["damping_ratio_rigid_rail"], 1e-4) for r in picked], marker,
                         fillstyle=fill, linestyle="none", color="C0" if single else "C1",
                         alpha=1 if path == FULL_CSV else 0.5,
                         label=f"{label}: " + ("n = 0 mode" if single else
                                               "pair's damped twin (the other: none)"))
        zz = zero_zero(rows)
        chart.annotate(f"(0,0) {zz['frequency_hz']:.0f} Hz",
                         (zz["frequency_hz"], zz["damping_ratio_rigid_rail"]),
                         textcoords="offset points", fontsize=8,
                         xytext=(-75, 8) if path == FULL_CSV else (8, -12))
    for name, colour in zip(RUNS, ("C0", "C3")):
        chart.plot([mode[f"fitted_{name}_frequency_hz"]],
                     [max(mode[f"fitted_{name}_damping_ratio"], 1e-4)], "*", markersize=14,
                     color=colour, label=f"demo FE, {name}: the fitted (0,0) sine "
                     "(zeta <= 0 drawn at 1e-4)")
    if full:
        zz = zero_zero(typed_rows(FULL_CSV, ["family"]))
        chart.plot([zz["fitted_coulomb_frequency_hz"]],
                   [max(zz["fitted_coulomb_damping_ratio"], 1e-4)], "P", markersize=12,
                   color="C0", label="full-scale FE, coulomb: the fitted (0,0) sine")
    chart.axhline(1 / math.sqrt(2), color="k", lw=0.8, linestyle="--")
    chart.annotate("zeta = 0.71: no resonance peak", (60, 0.75), fontsize=8)
    chart.set_xscale("log")
    chart.set_yscale("log")
    chart.set_ylim(1e-4, 10)
    chart.set_xlabel("mode frequency (Hz)")
    chart.set_ylabel("damping ratio")
    chart.set_title("creep dashpots to a rigid rail (Kalker's linear theory; open and filled "
                      "marks)\nagainst the rolling FE's (0,0) mode (stars): the rail is no "
                      "rigid wall", fontsize=10)
    chart.grid(alpha=0.3, which="both")
    chart.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=100)
    print(PNG)


def full_pulse(axis):
    """The full-scale pulse run's rim velocity, with its (0,0) fit in the title."""
    pulse = typed_rows(FULL_PULSE_CSV, [])
    mode = zero_zero(typed_rows(FULL_CSV, ["family"]))
    axis.plot([1e3 * r["time_s"] for r in pulse],
              [1e3 * r["rim_lateral_velocity_m_per_s"] for r in pulse], color="C0", lw=0.8,
              label=f"coulomb (fit: {mode['fitted_coulomb_frequency_hz']:.0f} Hz, zeta "
                    f"{mode['fitted_coulomb_damping_ratio']:.3f})")
    axis.axvspan(1e3 * FULL_PULSE_START, 1e3 * (FULL_PULSE_START + PULSE_DURATION),
                 color="grey", alpha=0.2, label=f"axle box pulse, {PULSE_AMPLITUDE * 1e6:g} um")
    axis.set_xlabel("time (ms)")
    axis.set_ylabel("rim point's lateral velocity (mm/s)")
    axis.set_title(f"full scale, case 1 with the pulse after the torque ramp: the (0,0) mode "
                   f"({mode['frequency_hz']:.0f} Hz clamped)", fontsize=10)
    axis.legend(fontsize=8)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_squeal_creep_damping", ROOT)
    parser.add_argument("--modes", help="a run's results directory with modes.exo and "
                                        "modes_modes.csv: the full-scale prediction")
    parser.add_argument("--patch", type=float, nargs=2, metavar=("A", "B"),
                        help="that run's patch semi-axes along and across the rail (m)")
    parser.add_argument("--run", action="store_true", help="the demo-scale pulse runs")
    parser.add_argument("--full-deck", metavar="PATH",
                        help="write the full-scale pulse deck (case 1, 19 ms; about 1.7 h on "
                             "two ranks: mpirun -np 2 railfe PATH --output DIR)")
    parser.add_argument("--full-results", metavar="DIR",
                        help="that run's results: the full-scale wheel's rows and the fit")
    args = parser.parse_args()
    if args.full_deck:
        with open(args.full_deck, "w") as deck:
            deck.write(pulse_deck("coulomb", FULL_OPTIONS, FULL_PULSE_START,
                                  "rolling scene, case 1 at full scale"))
    if not args.replot:
        if args.full_results:
            rows, pulse = full_check(args.full_results)
            write_rows(FULL_CSV, rows)
            write_rows(FULL_PULSE_CSV, pulse)
        if args.modes:
            if not args.patch:
                parser.error("--modes needs --patch A B")
            write_rows(FULL_CSV, creep_damping(contact_modes(
                os.path.join(args.modes, "modes.exo"),
                os.path.join(args.modes, "modes_modes.csv")), *args.patch))
        if args.run:
            rows, pulse = check_runs(args.railfe, args.work)
            write_rows(DEMO_CSV, rows)
            write_rows(PULSE_CSV, [dict(zip(pulse, values)) for values in zip(*pulse.values())])
    plot()


if __name__ == "__main__":
    main()
