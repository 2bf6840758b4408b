#!/usr/bin/env python3
"""Speed against accuracy of the explicit module: how the error of two verification cases falls
with the mesh and the safety factor, and what each run costs.
  bar         inputs/verification/explicit_bar_wave (1 m x 10 mm x 10 mm steel bar, one end
              pushed at 0.1 m/s along the bar, bulk viscosity off, 170 us) with 100, 200 and 400
              elements along the bar (10, 5, 2.5 mm; always 2 x 2 across) and safety factors
              0.5, 0.7, 0.9: error of the measured bar speed (bar_wave_speeds.csv, 'bar speed')
              against sqrt(E/rho) = 5172.19 m/s;
  cantilever  inputs/verification/explicit_cantilever (statics 'bend' under a 500 N tip load,
              then free vibration 'swing'), meshes 40x2x2, 80x4x4, 120x6x6, End time 0.1 s
              (4.2 periods), safety factors 0.9 and 0.5: error of the tip period
              (swing_measurements.csv, 'tip', period_s) against the Timoshenko value
              1/41.694 Hz = 23.984 ms, and max |energy_error| (swing_energy.csv).
Cost is the wall time of the explicit stepping (summary.json "time: stepping"; the bar runs are
repeated five times and the fastest kept, they take milliseconds); the run's total wall time is
written too.

    /usr/bin/python3 regression/studies/explicit_speed_accuracy.py build/bin/railfe [workdir]

Writes docs/data/explicit_speed_accuracy.csv and docs/img/explicit_speed_accuracy.png. About 4
minutes on 2 cores, most of it the 120x6x6 cantilever.
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from explicit_stability import max_abs, run_explicit  # noqa: E402
from railfe_runs import csv_rows  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BAR_SPEED = (210e9 / 7850) ** 0.5  # 5172.19 m/s
PERIOD = 1 / 41.694  # s, Timoshenko beam, first bending mode
BAR_ELEMENTS = (100, 200, 400)  # along the 1 m bar: 10, 5, 2.5 mm
BAR_SAFETY = (0.5, 0.7, 0.9)
BAR_REPEATS = 5
CANTILEVER_MESHES = ((40, 2), (80, 4), (120, 6))  # (along, across)
CANTILEVER_SAFETY = (0.9, 0.5)
CANTILEVER_END = 0.1  # s


def verification_deck(case, elements, safety, end_time=None):
    """The deck of inputs/verification/<case> with Box Elements `elements`, the automatic step
    at `safety`, End time `end_time` (if given) and no Exodus output."""
    with open(os.path.join(ROOT, "inputs", "verification", case, "deck.xml")) as deck:
        text = deck.read()
    text = re.sub(r'(name="Elements" type="Array\(int\)" value=)"\{[^}]*\}"',
                  lambda m: m.group(1) + '"{%d, %d, %d}"' % elements, text, count=1)
    end = re.search(r'<Parameter name="End time" type="double" value="([^"]*)"/>', text)
    text = (text[:end.start()] +
            f'<Parameter name="End time" type="double" value="{end_time or end.group(1)}"/>\n'
            f'      <Parameter name="Safety factor" type="double" value="{safety:g}"/>' +
            text[end.end():])
    if '<Parameter name="Exodus" type="bool" value="false"/>' not in text:
        text = text.replace('  <ParameterList name="Materials">',
                            '  <ParameterList name="Output">\n'
                            '    <Parameter name="Exodus" type="bool" value="false"/>\n'
                            '  </ParameterList>\n  <ParameterList name="Materials">', 1)
    return text


def bar_deck(along, safety):
    """The explicit_bar_wave deck with `along` elements along the bar (2 x 2 across)."""
    return verification_deck("explicit_bar_wave", (along, 2, 2), safety)


def cantilever_deck(along, across, safety, end_time):
    """The explicit_cantilever deck on an along x across x across mesh."""
    return verification_deck("explicit_cantilever", (along, across, across), safety, end_time)


def cost(run):
    section = run["section"]
    return {"time_step_s": section["stable step at start [s]"] * run["safety"],
            "steps": section["steps"], "elements": section["elements"],
            "stepping_time_s": section["time: stepping [s]"],
            "total_wall_time_s": run["summary"]["Wall time"]["total [s]"],
            "time_per_element_step_us": section["time per element-step (wall x ranks) [us]"]}


def bar_runs(railfe, workdir):
    rows = []
    for along in BAR_ELEMENTS:
        for safety in BAR_SAFETY:
            name = f"bar_{along}_s{safety:g}"
            runs = []
            for repeat in range(BAR_REPEATS):
                run = run_explicit(railfe, workdir, name, bar_deck(along, safety), "bar")
                assert run["exit"] == 0, run["message"]
                run["safety"] = safety
                runs.append(run)
            run = min(runs, key=lambda r: r["section"]["time: stepping [s]"])
            speed = next(float(r["speed_m_per_s"]) for r in
                         csv_rows(os.path.join(run["results"], "bar_wave_speeds.csv"))
                         if r["wave"] == "bar speed")
            rows.append({"case": "bar", "mesh": f"{along}x2x2", "element_size_mm": 1000 / along,
                         "safety_factor": safety, **cost(run), "wave_speed_m_per_s": speed,
                         "wave_speed_error": abs(speed - BAR_SPEED) / BAR_SPEED,
                         "max_abs_energy_error": max_abs(run["energy"], "energy_error")})
            print(f"{name:18s} dt {rows[-1]['time_step_s']:.3e} s  {rows[-1]['steps']:5d} steps  "
                  f"c {speed:8.2f} m/s  error {rows[-1]['wave_speed_error']:.2e}  stepping "
                  f"{rows[-1]['stepping_time_s']:.4f} s", flush=True)
    return rows


def cantilever_runs(railfe, workdir):
    rows = []
    for along, across in CANTILEVER_MESHES:
        for safety in CANTILEVER_SAFETY:
            name = f"cantilever_{along}x{across}x{across}_s{safety:g}"
            run = run_explicit(railfe, workdir, name,
                               cantilever_deck(along, across, safety, CANTILEVER_END), "swing")
            assert run["exit"] == 0, run["message"]
            run["safety"] = safety
            period = next(float(r["period_s"]) for r in
                          csv_rows(os.path.join(run["results"], "swing_measurements.csv"))
                          if r["history"] == "tip")
            rows.append({"case": "cantilever", "mesh": f"{along}x{across}x{across}",
                         "element_size_mm": 1000 / along, "safety_factor": safety,
                         **cost(run), "period_s": period,
                         "period_error": abs(period - PERIOD) / PERIOD,
                         "max_abs_energy_error": max_abs(run["energy"], "energy_error"),
                         "max_hourglass_ratio": max_abs(run["energy"], "hourglass_ratio")})
            r = rows[-1]
            print(f"{name:28s} dt {r['time_step_s']:.3e} s  {r['steps']:6d} steps  period "
                  f"{period * 1e3:.4f} ms  error {r['period_error']:.2e}  max|energy error| "
                  f"{r['max_abs_energy_error']:.2e}  stepping {r['stepping_time_s']:.2f} s  "
                  f"total {r['total_wall_time_s']:.2f} s", flush=True)
    return rows


COLUMNS = ["case", "mesh", "element_size_mm", "safety_factor", "time_step_s", "steps",
           "elements", "wave_speed_m_per_s", "wave_speed_error", "period_s", "period_error",
           "max_abs_energy_error", "max_hourglass_ratio", "stepping_time_s", "total_wall_time_s",
           "time_per_element_step_us"]


def main():
    railfe = os.path.abspath(sys.argv[1])
    workdir = sys.argv[2] if len(sys.argv) > 2 else "/tmp/railfe_explicit_speed_accuracy"
    os.makedirs(workdir, exist_ok=True)
    rows = bar_runs(railfe, workdir) + cantilever_runs(railfe, workdir)
    data = os.path.join(ROOT, "docs", "data", "explicit_speed_accuracy.csv")
    with open(data, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(COLUMNS)  # errors are relative; times in s, per element-step in us
        for r in rows:
            writer.writerow([(f"{r[k]:.6g}" if isinstance(r[k], float) else r[k])
                             if k in r else "" for k in COLUMNS])
    chart(rows, os.path.join(ROOT, "docs", "img", "explicit_speed_accuracy.png"))
    return 0


def chart(rows, png):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.4))
    colours = {0.5: "tab:blue", 0.7: "tab:green", 0.9: "tab:red"}
    ax = axes[0]
    for safety in BAR_SAFETY:
        mine = [r for r in rows if r["case"] == "bar" and r["safety_factor"] == safety]
        ax.plot([r["stepping_time_s"] for r in mine], [r["wave_speed_error"] for r in mine],
                marker="o", color=colours[safety], label=f"safety factor {safety:g}")
        for r in mine:
            ax.annotate(f"{r['element_size_mm']:g} mm", (r["stepping_time_s"],
                        r["wave_speed_error"]), textcoords="offset points", xytext=(5, 4),
                        fontsize=8, color=colours[safety])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the stepping [s]")
    ax.set_ylabel("|c - 5172.19| / 5172.19")
    ax.set_title("(a) bar wave: bar-speed error, 10 / 5 / 2.5 mm along, 2x2 across")
    ax.text(0.02, 0.03, "10 mm elements are 10x5x5 mm: L = V / largest face = 5 mm,\n"
            "so they take the same step as the 5 mm mesh.\nBar times are a few ms: "
            f"fastest of {BAR_REPEATS} runs, still noisy.", transform=ax.transAxes,
            fontsize=8, va="bottom")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax = axes[1]
    for safety in CANTILEVER_SAFETY:
        mine = [r for r in rows if r["case"] == "cantilever" and r["safety_factor"] == safety]
        times = [r["stepping_time_s"] for r in mine]
        ax.plot(times, [r["period_error"] for r in mine], marker="o", color=colours[safety],
                label=f"period error, safety {safety:g}")
        ax.plot(times, [r["max_abs_energy_error"] for r in mine], marker="s", linestyle="--",
                color=colours[safety], label=f"max |energy error|, safety {safety:g}")
        for r in mine:
            for value in (r["period_error"], r["max_abs_energy_error"]):
                ax.annotate(r["mesh"], (r["stepping_time_s"], value),
                            textcoords="offset points", xytext=(5, 4), fontsize=8,
                            color=colours[safety])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the stepping [s]")
    ax.set_ylabel("relative error")
    ax.set_title(f"(b) cantilever swing, {CANTILEVER_END:g} s: period vs 23.984 ms, energy")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
