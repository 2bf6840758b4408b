#!/usr/bin/env python3
"""Stability where the method fails (issue 16): case 5 of the squeal scene (falling friction
mu = 0.32 + 0.18 exp(-6 s/m |v_slip|), otherwise case 3, the axle moved sideways) at demo scale,
at two time steps (the demo's automatic step, 0.9 x 95.17 ns = 85.66 ns, and half of it, both
fixed) and two penalty factors (the decks' 1 and a quarter of it, in the preload and the rolling
step alike, so that each run starts in balance), with case 3 (Coulomb mu 0.45) as the demo ships
it (automatic step, penalty 1) as the constant-friction reference. All runs write their contact
history every step (no aliasing of step-level chatter) and the patch every 20 us over the last
0.4 ms.

Over the last 0.4 ms (1.2-1.6 ms; the torque is ramped by 0.5 ms, the lateral speed constant from
0.7 ms): the mean and spread of the normal, longitudinal and lateral contact forces, also about
a quadratic trend (the oscillation); the spectrum of the detrended longitudinal creep force (Hann
window, 2.5 kHz resolution; the strongest line between 5 and 20 kHz, where the demo mesh's
passing frequency V / h = 27.8 m/s / 4 mm = 6.9 kHz lies, and above 20 kHz, with each band's
RMS); the nodes in contact, stick and slip (the contact history every step, the patch files at
21 instants, the last at 1.6 ms), where in the patch the slip lies (the leading and trailing
rows), the slip speed of the slipping nodes and the friction coefficient the patch uses
(friction bound / normal force); and wall time.

Writes docs/data/squeal_case5_stability.csv and docs/img/squeal_case5_stability.png (the force
histories overlaid, the creep force's spectrum, the slip along the patch and the longitudinal
traction along the patch centre line at 1.6 ms). About 6 minutes on one core, one run at a time.

    /usr/bin/python3 regression/studies/squeal_case5_stability.py [build/bin/railfe] [--replot]
"""
import os
import re
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "regression", "charts"))
from railfe_runs import csv_rows, run_deck, step_section, study_parser, typed_rows, write_rows  # noqa: E402
from squeal_simplifications import deck_text  # noqa: E402

DEMO_STEP = 0.9 * 9.51742e-8  # s: the demo deck's automatic step (safety 0.9 x the solids' limit)
# (name, case, penalty factor, fixed time step or None for automatic)
RUNS = [
    ("f1_dt", 5, 1.0, DEMO_STEP),
    ("f1_dt2", 5, 1.0, DEMO_STEP / 2),
    ("f0.25_dt", 5, 0.25, DEMO_STEP),
    ("f0.25_dt2", 5, 0.25, DEMO_STEP / 2),
    ("case3_ref", 3, 1.0, None),
]
WINDOW = (1.2e-3, 1.6e-3)  # s
PATCH_TIMES = [1.2e-3 + 2e-5 * k for k in range(21)]  # s
BANDS = ((5e3, 2e4), (2e4, np.inf))  # Hz: the mesh-passing and structural band, above it
SPECTRUM_BANDS = 4.2e3 * 2.0 ** (np.arange(21) / 2)  # Hz: half octaves to 4.3 MHz (chart; each
# holds at least one line of the 2.5 kHz resolution)
CSV = os.path.join(ROOT, "docs", "data", "squeal_case5_stability.csv")
PNG = os.path.join(ROOT, "docs", "img", "squeal_case5_stability.png")
FORCES = {"normal": "normal_force_N", "longitudinal": "tangential_1_N",
          "lateral": "tangential_2_N"}


def replace_once(text, old, new, count=1):
    """text with `old` replaced by `new`, refusing a deck that holds `old` not `count` times (the
    generator changed: this study must change with it)."""
    found = text.count(old)
    if found != count:
        raise SystemExit(f"expected {count} x {old!r} in the generated deck, found {found}")
    return text.replace(old, new)


def study_deck(case, penalty, step):
    """The demo-scale deck of `case` with the penalty factor (preload and roll), the fixed step
    (None: automatic), the contact history every step and the patch at PATCH_TIMES (no charts)."""
    text = deck_text(["--case", str(case)])  # the last --case wins over squeal_simplifications' 3
    text = replace_once(text, '<Parameter name="Penalty factor" type="double" value="1"/>',
                        f'<Parameter name="Penalty factor" type="double" value="{penalty:g}"/>',
                        count=2)
    if step is not None:
        old = '<Parameter name="End time" type="double" value="0.0016"/>'
        text = replace_once(text, old, old + f'\n<Parameter name="Time step" type="double" '
                                               f'value="{step:.10g}"/>')
    text = re.sub(r'<Parameter name="Patch times" type="Array\(double\)" value="[^"]*"/>',
                  '<Parameter name="Patch times" type="Array(double)" value="{%s}"/>\n'
                  '<Parameter name="Patch charts" type="bool" value="false"/>'
                  % ", ".join(f"{t:.6g}" for t in PATCH_TIMES), text)
    return replace_once(text, '<Parameter name="History interval" type="int" value="10"/>',
                        '<Parameter name="History interval" type="int" value="1"/>')


def history(results):
    """The contact history as arrays: time, forces, nodes, friction bound."""
    rows = csv_rows(os.path.join(results, "roll_contact_wheel-rail.csv"))
    columns = ("time_s", "normal_force_N", "tangential_1_N", "tangential_2_N", "active_nodes",
               "slipping_nodes", "friction_bound_N", "max_penetration_m", "frictional_work_J")
    return {c: np.array([float(r[c]) for r in rows]) for c in columns}


def in_window(h):
    t = h["time_s"]
    return (t >= WINDOW[0] - 1e-12) & (t <= WINDOW[1] + 1e-12)


def detrended(t, y):
    """y on a uniform grid (the median step; the automatic step varies by 1e-5) minus its
    quadratic trend: (grid step, residual)."""
    dt = float(np.median(np.diff(t)))
    grid = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    yy = np.interp(grid, t, y)
    x = grid - grid.mean()
    return dt, yy - np.polyval(np.polyfit(x, yy, 2), x)


def spectrum(t, y):
    """Single-sided amplitude spectrum (N per line, Hann window, zero-padded 8x) of the detrended
    y, and the residual itself: (frequencies Hz, amplitudes N, residual, dt)."""
    dt, res = detrended(t, y)
    w = np.hanning(len(res))
    n = 8 * len(res)
    amplitude = 2 * np.abs(np.fft.rfft(res * w, n)) / w.sum()
    return np.fft.rfftfreq(n, dt), amplitude, res, dt


def band_rms(res, dt, lo, hi):
    """RMS of the part of `res` between lo and hi Hz (FFT mask, no window)."""
    f = np.fft.rfftfreq(len(res), dt)
    spec = np.fft.rfft(res)
    spec[(f < lo) | (f >= hi)] = 0
    return float(np.sqrt(np.mean(np.fft.irfft(spec, len(res)) ** 2)))


def peak(f, a, lo, hi):
    band = (f >= lo) & (f < hi)
    k = np.argmax(np.where(band, a, -1.0))
    return float(f[k]), float(a[k])


def patches(results):
    """The patch files' arrays, by time (read_patch of the centre-line chart)."""
    from patch_centre_line import read_patch
    names = sorted((f for f in os.listdir(results)
                    if f.startswith("roll_contact_wheel-rail_patch_") and f.endswith(".csv")),
                   key=lambda f: int(f.rsplit("_", 1)[1].split(".")[0]))
    return [read_patch(os.path.join(results, f)) for f in names]


def patch_measures(ps, row_depth=0.5 * 0.004):
    """Stick and slip over the patch instants: counts at the last, means over all, the share of
    node-instants slipping in the leading row (largest s1, the rolling direction) and the trailing
    row (the nodes within `row_depth` of the patch's end: half the demo's 4 mm contact elements by
    default), the s1 of the stick and of the slip node-instants, and the slip speed of the
    slipping."""
    stick, slip, lead, trail, s1_stick, s1_slip, speeds = [], [], [], [], [], [], []
    spacing = row_depth
    for p in ps:
        s1, slipping = p["s1_m"], p["slipping"] > 0.5
        stick.append(int((~slipping).sum()))
        slip.append(int(slipping.sum()))
        lead += list(slipping[s1 >= s1.max() - spacing])
        trail += list(slipping[s1 <= s1.min() + spacing])
        s1_stick += list(s1[~slipping])
        s1_slip += list(s1[slipping])
        speeds += list(np.hypot(p["slip_velocity_1_m/s"], p["slip_velocity_2_m/s"])[slipping])
    last = ps[-1]
    return {
        "patch_last_time_s": float(last["time_s"][0]),
        "patch_last_nodes": float(len(last["s1_m"])),
        "patch_last_stick_nodes": float(stick[-1]),
        "patch_last_slip_nodes": float(slip[-1]),
        "patch_instants": float(len(ps)),
        "patch_mean_stick_nodes": float(np.mean(stick)),
        "patch_mean_slip_nodes": float(np.mean(slip)),
        "patch_slip_fraction": float(np.sum(slip) / (np.sum(slip) + np.sum(stick))),
        "leading_row_slip_fraction": float(np.mean(lead)),
        "trailing_row_slip_fraction": float(np.mean(trail)),
        "stick_mean_s1_mm": 1e3 * float(np.mean(s1_stick)) if s1_stick else float("nan"),
        "slip_mean_s1_mm": 1e3 * float(np.mean(s1_slip)) if s1_slip else float("nan"),
        "slip_speed_median_m_per_s": float(np.median(speeds)) if speeds else float("nan"),
        "slip_speed_max_m_per_s": float(np.max(speeds)) if speeds else float("nan"),
    }


def measures(name, case, penalty, step, results, summary):
    roll = step_section(summary, "roll")
    h = history(results)
    m = in_window(h)
    row = {"run": name, "case": float(case), "penalty_factor": penalty,
           "time_step_s": float(np.median(np.diff(h["time_s"]))),
           "step": "automatic" if step is None else "fixed",
           "steps": float(roll["steps"]),
           "contact_critical_step_s": float(roll["contact critical step [s]"]),
           "wall_time_s": float(summary["Wall time"]["total [s]"]),
           "roll_stepping_s": float(roll["time: stepping [s]"]),
           "energy_error_at_end": float(roll["energy error at end"])}
    for key, column in FORCES.items():
        y = h[column][m]
        _, res = detrended(h["time_s"][m], y)
        row[f"{key}_mean_N"] = float(y.mean())
        row[f"{key}_std_N"] = float(y.std())
        row[f"{key}_detrended_std_N"] = float(res.std())
    f, a, res, dt = spectrum(h["time_s"][m], h["tangential_1_N"][m])
    for (lo, hi), label in zip(BANDS, ("5_20kHz", "above_20kHz")):
        row[f"creep_peak_{label}_Hz"], row[f"creep_peak_{label}_amplitude_N"] = peak(f, a, lo, hi)
        row[f"creep_rms_{label}_N"] = band_rms(res, dt, lo, hi)
    f, a, res, dt = spectrum(h["time_s"][m], h["normal_force_N"][m])
    row["normal_peak_5_20kHz_Hz"], row["normal_peak_5_20kHz_amplitude_N"] = peak(f, a, *BANDS[0])
    row["normal_rms_above_20kHz_N"] = band_rms(res, dt, *BANDS[1])
    row["active_nodes_mean"] = float(h["active_nodes"][m].mean())
    row["active_nodes_min"] = float(h["active_nodes"][m].min())
    row["active_nodes_max"] = float(h["active_nodes"][m].max())
    row["slipping_nodes_mean"] = float(h["slipping_nodes"][m].mean())
    row["slip_fraction_history"] = float((h["slipping_nodes"][m] / h["active_nodes"][m]).mean())
    row["friction_coefficient_in_use_mean"] = float(
        (h["friction_bound_N"][m] / h["normal_force_N"][m]).mean())
    row["traction_coefficient_mean"] = float(
        np.hypot(h["tangential_1_N"][m], h["tangential_2_N"][m]).mean() /
        h["normal_force_N"][m].mean())
    row["max_penetration_mean_m"] = float(h["max_penetration_m"][m].mean())
    row["frictional_work_at_end_J"] = float(h["frictional_work_J"][-1])
    row.update(patch_measures(patches(results)))
    return row


def run(railfe, work):
    rows = []
    for name, case, penalty, step in RUNS:
        results, summary = run_deck(railfe, study_deck(case, penalty, step), work, name)
        rows.append(measures(name, case, penalty, step, results, summary))
        print(f"{name}: {rows[-1]['wall_time_s']:.0f} s", flush=True)
    write_rows(CSV, rows)


STYLE = {"f1_dt": dict(color="C0", linestyle="-"), "f1_dt2": dict(color="C0", linestyle=":"),
         "f0.25_dt": dict(color="C3", linestyle="-"), "f0.25_dt2": dict(color="C3", linestyle=":"),
         "case3_ref": dict(color="0.45", linestyle="--")}


def label(r):
    if r["run"] == "case3_ref":
        return "case 3 (Coulomb 0.45), f 1, auto step"
    return f"case 5, f {r['penalty_factor']:g}, dt {1e9 * r['time_step_s']:.1f} ns"


def plot(work):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from patch_centre_line import centre_line
    rows = typed_rows(CSV, ["run", "step"])
    fig, axes = plt.subplots(4, 2, figsize=(13, 15.5))
    (fx, zoom), (fy, fn), (sp, slipax), (cl, nodes) = axes
    for r in rows:
        name, style = r["run"], STYLE[r["run"]]
        results = os.path.join(work, name + "_results")
        h = history(results)
        t = 1e3 * h["time_s"]
        lw = 1.6 if style["linestyle"] == ":" else 1.0  # the half step's dots over its line
        for axis, column in ((fx, "tangential_1_N"), (fy, "tangential_2_N"),
                             (fn, "normal_force_N")):
            axis.plot(t, 1e-3 * h[column], label=label(r), linewidth=lw, **style)
        late = h["time_s"] >= 1.5e-3
        zoom.plot(t[late], 1e-3 * h["tangential_1_N"][late], linewidth=lw, **style)
        m = in_window(h)
        dt, res = detrended(h["time_s"][m], h["tangential_1_N"][m])
        levels = [band_rms(res, dt, lo, hi) for lo, hi in zip(SPECTRUM_BANDS[:-1],
                                                               SPECTRUM_BANDS[1:])]
        sp.loglog(1e-3 * np.sqrt(SPECTRUM_BANDS[:-1] * SPECTRUM_BANDS[1:]), levels,
                  marker="o", markersize=3, linewidth=lw, **style)
        ps = patches(results)
        s1 = np.concatenate([p["s1_m"] for p in ps])
        slipping = np.concatenate([p["slipping"] for p in ps]) > 0.5
        edges = np.arange(-10, 12.01, 2.0)
        centres, share = [], []
        for lo, hi in zip(edges[:-1], edges[1:]):
            inside = (1e3 * s1 >= lo) & (1e3 * s1 < hi)
            if inside.sum() >= 5:
                centres.append(0.5 * (lo + hi))
                share.append(100 * slipping[inside].mean())
        slipax.plot(centres, share, marker="o", markersize=4, linewidth=1.2, **style)
        last = ps[-1]
        line = centre_line(last)
        x = 1e3 * last["s1_m"][line]
        q = 1e-6 * last["shear_1_Pa"][line]
        cl.plot(x, q, linewidth=1.2, **style)
        slip_line = last["slipping"][line] > 0.5
        cl.plot(x[~slip_line], q[~slip_line], "o", color=style["color"], markersize=6)
        cl.plot(x[slip_line], q[slip_line], "o", markerfacecolor="white",
                markeredgecolor=style["color"], markersize=6)
        width = max(1, int(round(2e-5 / np.median(np.diff(h["time_s"])))))  # 20 us
        running = np.convolve(h["slipping_nodes"], np.ones(width) / width, mode="valid")
        nodes.plot(t[width - 1:], running, linewidth=lw, **style)
    for axis in (fx, fy, fn, nodes):
        axis.axvspan(1e3 * WINDOW[0], 1e3 * WINDOW[1], color="0.9", zorder=0)
    fx.set_ylabel("longitudinal creep force (kN)")
    fx.legend(fontsize=8, loc="lower right")
    zoom.set_ylabel("longitudinal creep force (kN)")
    zoom.set_title("the last 0.1 ms", fontsize=10)
    fy.set_ylabel("lateral creep force (kN)")
    fn.set_ylabel("normal force (kN)")
    for axis in (fx, zoom, fy, fn, nodes):
        axis.set_xlabel("time (ms)")
    sp.set_xlabel("frequency (kHz)")
    sp.set_ylabel("RMS in the band (N)")
    sp.axvspan(5, 20, color="0.9", zorder=0)
    sp.set_title("detrended longitudinal creep force, 1.2-1.6 ms: RMS per half-octave band\n"
                 "(shaded: 5-20 kHz)", fontsize=10)
    slipax.set_xlabel("s1 along the rolling direction (mm; + = leading edge)")
    slipax.set_ylabel("node-instants slipping (%)")
    slipax.set_title("slip across the patch, 21 instants 1.2-1.6 ms (2 mm bins)", fontsize=10)
    cl.set_xlabel("s1 along the rolling direction (mm; + = leading edge)")
    cl.set_ylabel("longitudinal shear traction (MPa)")
    cl.set_title("centre line at 1.6 ms (filled: stick, open: slip)", fontsize=10)
    nodes.set_ylabel("slipping nodes (20 us running mean)")
    nodes.set_title("slipping nodes", fontsize=10)
    finish_chart(fig, sp, "Squeal scene, case 5 (falling friction) at demo scale: two steps, two "
                 "penalty factors\n(shaded: the 1.2-1.6 ms window of the measures)", PNG)


def finish_chart(fig, spectrum_axis, title, png):
    """Grids (minor ones on the log-log spectrum too), the title, and the PNG written."""
    for axis in fig.axes:
        axis.grid(alpha=0.3, which="both" if axis is spectrum_axis else "major")
    fig.suptitle(title, fontsize=12)
    fig.tight_layout()
    os.makedirs(os.path.dirname(png), exist_ok=True)
    fig.savefig(png, dpi=100)


def main():
    parser = study_parser(__doc__.split("\n")[0],
                          os.path.join(tempfile.gettempdir(), "squeal_case5_stability_work"), ROOT)
    args = parser.parse_args()
    if not args.replot:
        run(args.railfe, args.work)
    plot(args.work)


if __name__ == "__main__":
    main()
