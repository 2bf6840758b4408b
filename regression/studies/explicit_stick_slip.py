#!/usr/bin/env python3
"""Stability of penalty contact with falling friction in the explicit module (issue 15): the
stick-slip case inputs/verification/contact_stick_slip (a steel block on springs dragged by a belt
at 0.1 m/s, mu = 0.32 + 0.18 exp(-6 |v_slip|), N = 100 N) run with fixed steps r = 0.9, 0.5, 0.25
and 0.1 times the stable step (the smaller of the solids' limit and the contact's critical step,
both read from a short automatic run) and with penalty factors f = 0.01, 0.1 (default), 1 and 10
(Penalty stiffness 'bulk modulus'), for 0.11 s: two slip phases and two re-sticks. Every run
writes its histories and contact forces every step. Measured against the exact limit cycle of
regression/studies/stick_slip_reference.py (same ODE, SciPy):

  period, x_max, x_min    limit-cycle error (period from 'block x' in drag_measurements.csv,
                          extremes of the block's mean x, written every step)
  ring_rms_N, ring_peak_N the penalty spring's ringing in the stick phases: F - (k x + P), which
                          the exact solution holds at zero (F the friction force, tangential_1_N)
  slip_law_rms_N          the friction force's departure from mu(v - x') N during slip, x' and N
                          the run's own, 0.2 ms away from the transitions: high-frequency slip
                          oscillation shows here
  slip_velocity_hf_rms    the block velocity minus its 0.2 ms moving average, during slip
  switches_per_cycle      changes of the 'some slave node slips' state per cycle (2 = one slip
                          phase, clean), and of the 'all nine slip' (gross slip) state
  normal_rms_N            the normal force's departure from N = 100 N (contact chatter)

A control runs each penalty factor at r = 0.9 and 0.25 with Decay 0 (mu = mu_s = 0.5 at every
speed: stuck until 30 ms, then steady sliding, 0.05 s): whatever oscillates there does not come
from the falling law (its switch count is per run, one slip phase).

    /usr/bin/python3 regression/studies/explicit_stick_slip.py [build/bin/railfe] [--work DIR]

Writes docs/data/explicit_stick_slip.csv (units in the column names; errors relative to the
exact period, to the exact swing x_max - x_min, to the largest relative speed) and
docs/img/explicit_stick_slip.png (about 4 min on one core; the per-step CSV files, up to 180 MB for one run, are deleted after reading).
"""
import argparse
import csv
import math
import os
import re
import shutil
import sys
import time

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import run_deck, step_section  # noqa: E402
from stick_slip_reference import CASE, limit_cycle  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "contact_stick_slip", "deck.xml")
CSV = os.path.join(ROOT, "docs", "data", "explicit_stick_slip.csv")
PNG = os.path.join(ROOT, "docs", "img", "explicit_stick_slip.png")

END_TIME = 0.11
FACTORS = [0.01, 0.1, 1.0, 10.0]
FRACTIONS = [0.9, 0.5, 0.25, 0.1]
SKIP = {(10.0, 0.1)}  # 1.9 M steps: the trend is clear without it
TRACE = [(0.1, 0.9), (10.0, 0.9), (1.0, 0.9), (10.0, 0.25)]  # runs whose force is drawn
CONTROL_FRACTIONS = [0.9, 0.25]  # constant mu = mu_s (Decay 0): is the falling law the cause?
CONTROL_END_TIME = 0.05


def deck_text(factor, time_step, end_time, history_interval, constant=False):
    """The case's deck with penalty factor `factor`, a fixed step (0 = automatic), an End time
    and a History interval; `constant` sets Decay 0 (mu = mu_s at every slip speed)."""
    text = open(DECK).read()
    text = re.sub(r"<!--.*?-->\s*", "", text, flags=re.S)
    text = text.replace('<Parameter name="End time" type="double" value="0.2"/>',
                        f'<Parameter name="End time" type="double" value="{end_time!r}"/>'
                        + (f'\n      <Parameter name="Time step" type="double" '
                           f'value="{time_step!r}"/>' if time_step else ""))
    text = text.replace('<Parameter name="Decay" type="double" value="6"/>',
                        '<Parameter name="Decay" type="double" value="6"/>\n'
                        f'          <Parameter name="Penalty factor" type="double" '
                        f'value="{factor!r}"/>')
    text = text.replace('<Parameter name="History interval" type="int" value="10"/>',
                        f'<Parameter name="History interval" type="int" value="{history_interval}"/>')
    text = text.replace('<Parameter name="Energy interval" type="int" value="100"/>',
                        '<Parameter name="Energy interval" type="int" value="1000"/>')
    if constant:
        text = text.replace('<Parameter name="Decay" type="double" value="6"/>',
                            '<Parameter name="Decay" type="double" value="0"/>')
    assert text.count("Penalty factor") == 1 and ("Time step" in text) == bool(time_step)
    return text


def load(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def moving_average(values, width):
    if width < 2:
        return values.copy()
    kernel = np.ones(width) / width
    return np.convolve(values, kernel, mode="same")


def measure(results, reference, p, time_step, constant=False):
    h = load(os.path.join(results, "drag_histories.csv"))
    c = load(os.path.join(results, "drag_contact_belt.csv"))
    with open(os.path.join(results, "drag_measurements.csv")) as f:
        rows = {r["history"]: r for r in csv.DictReader(f)}
    t, x, v = h["time_s"], h["block x_displacement_x_m"], h["block vx_velocity_x_m_per_s"]
    force, normal, slipping = c["tangential_1_N"], c["normal_force_N"], c["slipping_nodes"]
    k, P, belt = p["stiffness"], p["preload"], p["belt"]
    end_time = t[-1]
    if constant:
        # mu = mu_s: stuck until k x + P = mu_s N (30 ms), then steady sliding at x = 3 mm.
        onsets, resticks = [reference["onsets"][0]], [end_time + 1]
    else:
        onsets = [o for o in reference["onsets"] if o < end_time]
        resticks = [o + reference["slip_time"] for o in onsets]
    stick = np.zeros(t.size, bool)
    slip = np.zeros(t.size, bool)
    for onset, restick in zip(onsets, resticks):
        slip |= (t > onset + 2e-4) & (t < restick - 2e-4)
    starts = [0.005] + resticks
    ends = onsets + [end_time]
    for start, end in zip(starts, ends):
        stick |= (t >= start) & (t < end - 5e-4)
    ring = force - (k * x + P)
    decay = 0.0 if constant else p["decay"]
    law = (p["mu_d"] + (p["mu_s"] - p["mu_d"]) * np.exp(-decay * np.abs(belt - v))) * normal
    hf = v - moving_average(v, max(1, int(round(2e-4 / time_step))))
    after = t > 0.005
    some = (slipping > 0).astype(int)[after]
    gross = (slipping >= slipping.max()).astype(int)[after]
    cycles = len(onsets)
    amplitude = reference["x_max"] - reference["x_min"]
    period = float(rows["block x"]["period_s"]) if not constant else math.nan
    nan = math.nan
    if constant:
        return dict(period_s=nan, period_error=nan, x_max_m=nan, x_max_error=nan, x_min_m=nan,
                    x_min_error=nan, v_min_m_per_s=nan, v_min_error=nan,
                    ring_rms_N=float(np.sqrt(np.mean(ring[stick] ** 2))),
                    ring_peak_N=float(np.max(np.abs(ring[stick]))),
                    slip_law_rms_N=float(np.sqrt(np.mean((force[slip] - law[slip]) ** 2))),
                    slip_velocity_hf_rms_m_per_s=float(np.sqrt(np.mean(hf[slip] ** 2))),
                    switches_per_cycle=float(np.count_nonzero(np.diff(some))),
                    gross_switches_per_cycle=float(np.count_nonzero(np.diff(gross))),
                    normal_rms_N=float(np.sqrt(np.mean((normal[after] - p["normal"]) ** 2))),
                    friction_max_N=float(force.max()), trace=(t, force, x, v))
    return dict(
        period_s=period,
        period_error=period / reference["period"] - 1,
        x_max_m=float(x.max()), x_max_error=(x.max() - reference["x_max"]) / amplitude,
        x_min_m=float(x.min()), x_min_error=(x.min() - reference["x_min"]) / amplitude,
        v_min_m_per_s=float(v.min()),
        v_min_error=(v.min() - (belt - reference["largest_relative_speed"]))
        / reference["largest_relative_speed"],
        ring_rms_N=float(np.sqrt(np.mean(ring[stick] ** 2))),
        ring_peak_N=float(np.max(np.abs(ring[stick]))),
        slip_law_rms_N=float(np.sqrt(np.mean((force[slip] - law[slip]) ** 2))),
        slip_velocity_hf_rms_m_per_s=float(np.sqrt(np.mean(hf[slip] ** 2))),
        switches_per_cycle=float(np.count_nonzero(np.diff(some))) / cycles,
        gross_switches_per_cycle=float(np.count_nonzero(np.diff(gross))) / cycles,
        normal_rms_N=float(np.sqrt(np.mean((normal[after] - p["normal"]) ** 2))),
        friction_max_N=float(force.max()),
        trace=(t, force, x, v))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("railfe", nargs="?", default=os.path.join(ROOT, "build", "bin", "railfe"))
    parser.add_argument("--work", default="/tmp/railfe_explicit_stick_slip")
    args = parser.parse_args()
    p = CASE
    grid = np.linspace(0, END_TIME, 22001)
    reference = limit_cycle(p, cycles=3, samples=grid)
    _, xs, us = reference["samples"]
    onsets = reference["onsets"]
    stuck = np.ones(grid.size, bool)
    for onset in onsets:
        stuck &= ~((grid > onset) & (grid < onset + reference["slip_time"]))
    reference_force = np.where(
        stuck, p["stiffness"] * xs + p["preload"],
        (p["mu_d"] + (p["mu_s"] - p["mu_d"]) * np.exp(-p["decay"] * np.abs(p["belt"] - us)))
        * p["normal"])
    print(f"reference: period {reference['period']:.9f} s, x {reference['x_min']:.7e} .. "
          f"{reference['x_max']:.7e} m", flush=True)

    rows, traces = [], {}
    for factor in FACTORS:
        _, summary = run_deck(args.railfe, deck_text(factor, 0.0, 2e-5, 1), args.work,
                              f"probe_f{factor:g}")
        section = step_section(summary, "drag")
        solid = section["stable step at start [s]"]
        contact = section["contact critical step [s]"]
        stable = min(solid, contact)
        runs = [(fraction, False) for fraction in FRACTIONS if (factor, fraction) not in SKIP]
        runs += [(fraction, True) for fraction in CONTROL_FRACTIONS]
        for fraction, constant in runs:
            dt = fraction * stable
            name = f"f{factor:g}_r{fraction:g}" + ("_constant" if constant else "")
            started = time.time()
            end_time = CONTROL_END_TIME if constant else END_TIME
            results, summary = run_deck(args.railfe, deck_text(factor, dt, end_time, 1, constant),
                                        args.work, name)
            wall = time.time() - started
            m = measure(results, reference, p, dt, constant)
            if (factor, fraction) in TRACE and not constant:
                traces[(factor, fraction)] = m["trace"]
            del m["trace"]
            row = dict(law="constant mu_s" if constant else "falling", penalty_factor=factor,
                       step_fraction=fraction, time_step_s=dt, solid_stable_step_s=solid,
                       contact_critical_step_s=contact,
                       steps=step_section(summary, "drag")["steps"], end_time_s=end_time,
                       wall_s=round(wall, 2))
            row.update(m)
            rows.append(row)
            shutil.rmtree(results)
            print(f"{row['law']:13s} f {factor:5g} r {fraction:4g} dt {dt:.3e} s: period "
                  f"{m['period_error']:+.2e} x_max {m['x_max_error']:+.1e} x_min "
                  f"{m['x_min_error']:+.1e} ring {m['ring_rms_N']:.3f}/{m['ring_peak_N']:.2f} N "
                  f"slip law {m['slip_law_rms_N']:.4f} N v_hf "
                  f"{m['slip_velocity_hf_rms_m_per_s']:.1e} normal {m['normal_rms_N']:.3f} N "
                  f"switches {m['switches_per_cycle']:.1f}/{m['gross_switches_per_cycle']:.1f}"
                  f" F_max {m['friction_max_N']:.3f} ({wall:.1f} s)", flush=True)

    # Units in the column names; errors: period relative to the exact period, x_max and x_min
    # relative to the exact swing x_max - x_min, v_min relative to the largest relative speed.
    names = dict(period_error="period_rel_error", x_max_error="x_max_error_of_swing",
                 x_min_error="x_min_error_of_swing", v_min_error="v_min_rel_error")
    rows = [{names.get(k, k): v for k, v in row.items()} for row in rows]
    with open(CSV, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v:.7g}" if isinstance(v, float) else v)
                             for k, v in row.items()})
    print("wrote", CSV)
    plot(rows, traces, grid, reference_force, reference)


def plot(rows, traces, grid, reference_force, reference):
    fig, axes = plt.subplots(2, 4, figsize=(20, 9))
    colours = {0.01: "tab:blue", 0.1: "tab:green", 1.0: "tab:orange", 10.0: "tab:red"}
    falling = [r for r in rows if r["law"] == "falling"]
    control = [r for r in rows if r["law"] != "falling"]
    for ax, keys, title in [(axes[0, 0], [(1.0, 0.9), (0.1, 0.9)],
                             "Friction force, f = 0.1 (default) and 1"),
                            (axes[0, 1], [(10.0, 0.9), (10.0, 0.25)],
                             "Friction force, stiff penalty f = 10")]:
        ax.plot(grid * 1e3, reference_force, color="black", lw=3, alpha=0.3, label="exact (ODE)")
        for key, style in zip(keys, ["-", "-"]):
            if key not in traces:
                continue
            t, force, _, _ = traces[key]
            ax.plot(t * 1e3, force, style, color=colours[key[0]] if key[1] == 0.9 else "purple",
                    lw=0.5 if key[0] > 0.1 else 1.2, alpha=0.8, label=f"railfe f = {key[0]:g}, r = {key[1]:g}")
        ax.set_xlim(25, END_TIME * 1e3)
        ax.set_xlabel("t (ms)")
        ax.set_ylabel("friction force on the block (N)")
        ax.set_title(title)
        ax.legend(fontsize=7, loc="upper right")
        ax.grid(alpha=0.3)
    ax = axes[0, 2]
    restick = reference["onsets"][1] + reference["slip_time"]
    ax.plot((grid - restick) * 1e3, reference_force, color="black", lw=3, alpha=0.3,
            label="exact")
    for key in [(1.0, 0.9), (0.1, 0.9)]:
        if key in traces:
            t, force, _, _ = traces[key]
            window = (t > restick - 0.5e-3) & (t < restick + 1.5e-3)
            ax.plot((t[window] - restick) * 1e3, force[window], color=colours[key[0]], lw=0.8,
                    label=f"f = {key[0]:g}, r = {key[1]:g}")
    ax.axhline(CASE["mu_s"] * CASE["normal"], color="grey", ls=":", lw=1, label="mu_s N")
    ax.set_xlim(-0.5, 1.5)
    ax.set_xlabel("t - second re-stick (ms)")
    ax.set_ylabel("friction force (N)")
    ax.set_title("At re-stick the tangential penalty spring rings")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    metrics = [
        (axes[0, 3], lambda r: abs(r["period_rel_error"]), "|period error| (relative)",
         "Limit-cycle period", False),
        (axes[1, 0], lambda r: max(abs(r["x_max_error_of_swing"]), abs(r["x_min_error_of_swing"])),
         "largest |x_max or x_min error| / (x_max - x_min)", "Limit-cycle amplitude", False),
        (axes[1, 1], lambda r: r["ring_rms_N"], "RMS of F - (k x + P) while stuck (N)",
         "Ringing in stick", False),
        (axes[1, 2], lambda r: r["slip_law_rms_N"], "RMS of F - mu(v_r) N while slipping (N)",
         "Spurious oscillation in slip", True),
        (axes[1, 3], lambda r: r["switches_per_cycle"], "stick/slip switches per cycle",
         "Switches of 'some node slips' (2 = clean)", False),
    ]
    for ax, value, label, title, with_control in metrics:
        for factor in FACTORS:
            sel = [r for r in falling if r["penalty_factor"] == factor]
            ax.plot([r["step_fraction"] for r in sel], [max(value(r), 1e-9) for r in sel], "o-",
                    color=colours[factor], label=f"f = {factor:g}")
            if with_control:
                sel = [r for r in control if r["penalty_factor"] == factor]
                ax.plot([r["step_fraction"] for r in sel], [max(value(r), 1e-9) for r in sel],
                        "s--", color=colours[factor], mfc="none",
                        label=f"f = {factor:g}, constant mu = mu_s")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("time step / stable step")
        ax.set_ylabel(label)
        ax.set_title(title)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6, ncol=2 if with_control else 1)
    fig.suptitle("Penalty contact with falling friction in the explicit module: block on a spring "
                 "dragged by a belt (contact_stick_slip, 0.11 s; r = step / stable step, f = "
                 "penalty factor)")
    fig.tight_layout()
    fig.savefig(PNG, dpi=100)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
