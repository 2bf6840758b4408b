#!/usr/bin/env python3
"""Where central difference goes unstable, and whether railfe notices: fixed time steps at
r = 0.5 ... 1.2 times the stable limit (taken from the "stable step at start" of a first,
automatic run of the same deck) on three cases:
  bar          the bar of inputs/verification/explicit_bar_wave (1 m x 10 mm x 10 mm steel,
               200 x 2 x 2 one-point hex8 of 5 mm, bulk viscosity off) with the end xmin pushed
               by the non-symmetric velocity 0.1*(1 + y + 2*z) m/s on x, y and z (as in
               regression/bad_input/explicit_unstable_step_blows_up.xml), 400 us;
  cube         a free 0.1 m steel cube, 10 x 10 x 10 elements of 10 mm, bulk viscosity off,
               started with the rigid velocity field V + omega x (X - centre), V = {1, 2, 3}
               m/s, omega = {100, 200, 300} rad/s, 400 us;
  cube_bulkvisc  the same cube with railfe's default bulk viscosity, whose stable step is
               lowered by the viscosity (L/c_P (sqrt(1 + xi^2) - xi)).
The limit railfe reports is each element's L/c_P times one factor from a Lanczos estimate of the
mesh's highest frequency at the start (0.955 for the bar: its free surfaces carry modes above
the interior checkerboard).
Every step is run with Allow unstable step true and Energy interval 1 (the energy balance is
checked and written every step); every r > 1 is run again without Allow unstable step and must
be refused. Each run is classed as
  stable      completed, max |energy_error| < 0.05 and the kinetic energy never above 10 x the
              largest of the automatic run;
  start-up    completed and stable, but max |energy_error| >= 0.05 in the first 10 steps only
              (a velocity step applied at t = 0 gives an energy-accounting transient of order
              r x 0.1 at step 1, which then decays); below 0.05 from step 11 on;
  detected    stopped with exit 2 and 'growing without bound';
  refused     exit 2 with 'above the stable limit' (only the runs without Allow unstable step);
  undetected  completed, but max |energy_error| >= 0.05 after step 10 or the kinetic energy grew
              more than 10 x (must never happen);
  other       anything else (a refusal that did not happen, another failure).
Near r = 1 the energy error of central difference legitimately grows: the discrete energy
differs from the true one by a factor 1 / (1 - (omega dt / 2)^2) in the highest mode.

    /usr/bin/python3 regression/studies/explicit_stability.py build/bin/railfe [workdir]

Writes docs/data/explicit_stability.csv and docs/img/explicit_stability.png; exits 1 if a run is
undetected or other. About 2 minutes (63 short runs, mostly mpirun start-up).
"""
import csv
import json
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import (box_mesh_xml, mpi_prefix, output_xml, steel_materials_xml,  # noqa: E402
                         step_section)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The requested ratios plus 0.96 and 0.97, which bracket where the runs start to diverge.
RATIOS = (0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.96, 0.97, 0.98, 1.0, 1.02, 1.05, 1.1, 1.15, 1.2)
STABLE_ERROR = 0.05
KINETIC_GROWTH = 10.0
STARTUP_STEPS = 10


def step_xml(time_step, allow, safety=None):
    """The step-size parameters: automatic (time_step None, optional Safety factor) or fixed."""
    text = ""
    if time_step is not None:
        text += f'<Parameter name="Time step" type="double" value="{time_step:.17g}"/>\n'
    if safety is not None:
        text += f'      <Parameter name="Safety factor" type="double" value="{safety:g}"/>\n'
    if allow:
        text += '      <Parameter name="Allow unstable step" type="bool" value="true"/>\n'
    return text


# The Solid list that switches bulk viscosity off (it lowers the stable step).
NO_BULK_VISCOSITY = """<ParameterList name="Solid">
        <Parameter name="Bulk viscosity linear" type="double" value="0"/>
        <Parameter name="Bulk viscosity quadratic" type="double" value="0"/>
      </ParameterList>"""


def explicit_deck(title, mesh_xml, block, time_step, allow, end_time, solid, conditions):
    """A one-step explicit deck on the box `block` with energies every step: `solid` and
    `conditions` are the step's Solid and loading sublists (XML, indented for the step)."""
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="{title}"/>
{mesh_xml}{steel_materials_xml([block])}{output_xml()}  <ParameterList name="Steps">
    <ParameterList name="{block}">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:g}"/>
      {step_xml(time_step, allow)}
      {solid}
      {conditions}
      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def bar_deck(time_step=None, allow=False, end_time=400e-6):
    """The explicit_bar_wave bar pushed at xmin by 0.1*(1 + y + 2*z) m/s on x, y and z."""
    push = """<ParameterList name="Prescribed motion">
        <ParameterList name="pushed end">
          <Parameter name="Node set" type="string" value="xmin"/>
          <Parameter name="Components" type="string" value="xyz"/>
          <Parameter name="Function" type="string" value="0.1*(1 + y + 2*z)"/>
        </ParameterList>
      </ParameterList>"""
    return explicit_deck("bar, non-symmetric push", box_mesh_xml((1.0, 0.01, 0.01), (200, 2, 2), "bar"),
                         "bar", time_step, allow, end_time, NO_BULK_VISCOSITY, push)


def cube_deck(time_step=None, allow=False, end_time=400e-6, bulk_viscosity=False):
    """A free 0.1 m steel cube (10 mm elements) spinning and translating from t = 0; bulk
    viscosity off unless asked for (then railfe's defaults, which lower the stable step)."""
    spin = """<ParameterList name="Initial velocity">
        <ParameterList name="spin">
          <Parameter name="Translation" type="Array(double)" value="{1, 2, 3}"/>
          <Parameter name="Angular velocity" type="Array(double)" value="{100, 200, 300}"/>
          <Parameter name="Axis point" type="Array(double)" value="{0, 0, 0}"/>
        </ParameterList>
      </ParameterList>"""
    mesh = box_mesh_xml((0.1, 0.1, 0.1), (10, 10, 10), "cube", (-0.05, -0.05, -0.05))
    return explicit_deck("free spinning cube", mesh, "cube", time_step, allow, end_time,
                         "" if bulk_viscosity else NO_BULK_VISCOSITY, spin)


MESHES = {  # name: (deck maker, step name, legend label)
    "bar": (bar_deck, "bar", "bar 200x2x2 (5 mm), pushed end"),
    "cube": (cube_deck, "cube", "cube 10x10x10 (10 mm), spinning, free"),
    "cube_bulkvisc": (lambda *a: cube_deck(*a, bulk_viscosity=True), "cube",
                      "same cube, default bulk viscosity"),
}


def run_explicit(railfe, workdir, name, deck_text, step):
    """Runs one deck (exit status need not be 0). Returns a dict: exit, message (the 'railfe:'
    line of stderr), summary (or {}), section (the step's summary section or {}), energy (rows
    of <step>_energy.csv, or of its .part when the run failed), results (directory)."""
    os.makedirs(workdir, exist_ok=True)
    deck = os.path.join(workdir, name + ".xml")
    with open(deck, "w") as out:
        out.write(deck_text)
    results = os.path.join(workdir, name)
    completed = subprocess.run(mpi_prefix(1) + [railfe, deck, "--output", results, "--quiet"],
                               capture_output=True, text=True)
    message = next((line for line in (completed.stderr + completed.stdout).splitlines()
                    if line.startswith("railfe:")), "")
    summary, energy = {}, []
    path = os.path.join(results, "summary.json")
    if os.path.exists(path):
        with open(path) as handle:
            summary = json.load(handle)
    for candidate in (f"{step}_energy.csv", f"{step}_energy.csv.part"):
        path = os.path.join(results, candidate)
        if os.path.exists(path):
            with open(path) as table:
                energy = list(csv.DictReader(table))
            break
    try:
        section = step_section(summary, step)
    except KeyError:
        section = {}
    return {"exit": completed.returncode, "message": message, "summary": summary,
            "section": section, "energy": energy, "results": results}


def max_abs(rows, column, after_step=-1):
    """max |column| over the rows whose step is above after_step (nan if none)."""
    return max((abs(float(r[column])) for r in rows if int(r["step"]) > after_step),
               default=float("nan"))


def error_at_stop(message):
    """The energy error quoted by a 'growing without bound' message (nan if none)."""
    found = re.search(r"energy error ([-0-9.eE+]+) beyond", message)
    return float(found.group(1)) if found else float("nan")


def classify(run, allow, reference_kinetic):
    """The outcome of one run (see the module docstring)."""
    code, message = run["exit"], run["message"]
    if not allow:
        return "refused" if code == 2 and "above the stable limit" in message else "other"
    if code == 2 and "growing without bound" in message:
        return "detected"
    if code != 0:
        return "other"
    error = max_abs(run["energy"], "energy_error")
    later = max_abs(run["energy"], "energy_error", STARTUP_STEPS)
    kinetic = max_abs(run["energy"], "kinetic_J")
    if kinetic > KINETIC_GROWTH * reference_kinetic or not later < STABLE_ERROR:
        return "undetected"
    return "stable" if error < STABLE_ERROR else "start-up"


def steps_taken(run):
    if run["section"]:
        return run["section"]["steps"]
    found = re.search(r"\(step (\d+)\)", run["message"])
    if found:
        return int(found.group(1))
    return int(run["energy"][-1]["step"]) if run["energy"] else 0


COLUMNS = [  # (key, CSV header)
    ("mesh", "mesh"), ("ratio", "step_over_stable_limit"), ("stable_limit_s", "stable_limit_s"),
    ("time_step_s", "time_step_s"), ("allow", "allow_unstable_step"),
    ("exit_status", "exit_status"), ("outcome", "outcome"), ("steps", "steps"),
    ("max_error", "max_abs_energy_error"),
    ("max_error_after_startup", "max_abs_energy_error_after_step_10"),
    ("step_of_max_error", "step_of_max_error"), ("error_at_end", "energy_error_at_end"),
    ("error_at_stop", "energy_error_at_stop"),
    ("kinetic_ratio", "max_kinetic_over_automatic_run"), ("message", "message")]


def main():
    railfe = os.path.abspath(sys.argv[1])
    workdir = sys.argv[2] if len(sys.argv) > 2 else "/tmp/railfe_explicit_stability"
    os.makedirs(workdir, exist_ok=True)
    rows = []
    for mesh, (deck, step, _) in MESHES.items():
        automatic = run_explicit(railfe, workdir, f"{mesh}_automatic", deck(), step)
        assert automatic["exit"] == 0, automatic["message"]
        limit = automatic["section"]["stable step at start [s]"]
        reference_kinetic = max_abs(automatic["energy"], "kinetic_J")
        print(f"{mesh}: stable limit {limit:.6g} s, automatic run "
              f"{automatic['section']['steps']} steps, max |energy error| "
              f"{max_abs(automatic['energy'], 'energy_error'):.3g}", flush=True)
        cases = [(r, True) for r in RATIOS] + [(r, False) for r in RATIOS if r > 1]
        for ratio, allow in cases:
            name = f"{mesh}_r{ratio:g}" + ("" if allow else "_not_allowed")
            run = run_explicit(railfe, workdir, name, deck(ratio * limit, allow), step)
            energy = run["energy"]
            worst = max(energy, key=lambda r: abs(float(r["energy_error"])), default=None)
            completed = run["exit"] == 0 and energy
            rows.append({
                "mesh": mesh, "ratio": ratio, "stable_limit_s": limit,
                "time_step_s": ratio * limit, "allow": allow, "exit_status": run["exit"],
                "outcome": classify(run, allow, reference_kinetic),
                "steps": steps_taken(run) if run["exit"] != 1 else 0,
                "max_error": max_abs(energy, "energy_error"),
                "max_error_after_startup": max_abs(energy, "energy_error", STARTUP_STEPS),
                "step_of_max_error": int(worst["step"]) if worst else "",
                "error_at_end": float(energy[-1]["energy_error"]) if completed else float("nan"),
                "error_at_stop": error_at_stop(run["message"]),
                "kinetic_ratio": max_abs(energy, "kinetic_J") / reference_kinetic,
                "message": run["message"][len("railfe: "):] if run["exit"] else ""})
            r = rows[-1]
            print(f"{name:26s} exit {r['exit_status']}  {r['outcome']:10s} max|err| "
                  f"{r['max_error']:9.3g} (step {r['step_of_max_error']}), after step "
                  f"{STARTUP_STEPS} {r['max_error_after_startup']:9.3g}, at stop "
                  f"{r['error_at_stop']:7.3g}  steps {r['steps']:4d}  {r['message'][:50]}",
                  flush=True)
    data = os.path.join(ROOT, "docs", "data", "explicit_stability.csv")
    with open(data, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow([header for _, header in COLUMNS])
        for r in rows:
            writer.writerow([f"{r[k]:.6g}" if isinstance(r[k], float) else r[k]
                             for k, _ in COLUMNS])
    chart(rows, os.path.join(ROOT, "docs", "img", "explicit_stability.png"))
    return 1 if any(r["outcome"] in ("undetected", "other") for r in rows) else 0


def chart_error(r):
    """The error plotted for a run: its largest written |energy_error|, or for a stopped run
    the error quoted at the stop when that is larger."""
    values = [v for v in (r["max_error"], r["error_at_stop"]) if v == v]
    return max(values) if values else float("nan")


def chart(rows, png):
    markers = {"stable": "o", "start-up": "D", "detected": "^", "refused": "x",
               "undetected": "*", "other": "s"}
    colours = {"bar": "tab:blue", "cube": "tab:orange", "cube_bulkvisc": "tab:green"}
    floor = 1e-9
    band = {"bar": 4.5 * floor, "cube": 2.6 * floor, "cube_bulkvisc": 1.5 * floor}
    fig, ax = plt.subplots(figsize=(9, 5.6))
    ax.axhspan(floor, 7 * floor, color="0.93", zorder=0)
    ax.text(0.47, 8.5 * floor, "refused without Allow unstable step (not run):", fontsize=8,
            va="bottom")
    for mesh, colour in colours.items():
        mine = [r for r in rows if r["mesh"] == mesh]
        ran = sorted((r["ratio"], chart_error(r)) for r in mine if r["allow"])
        ax.plot([x for x, _ in ran], [y for _, y in ran], color=colour, linewidth=0.8,
                alpha=0.5, zorder=2)
        for r in mine:
            outcome = r["outcome"]
            y = band[mesh] if not r["allow"] else chart_error(r)
            ax.scatter(r["ratio"], y, marker=markers[outcome], s=55, color=colour,
                       edgecolor=None if outcome == "refused" else "k",
                       linewidths=1.8 if outcome == "refused" else 0.6, zorder=3)
    ax.axvline(1.0, color="k", linestyle="--", linewidth=1)
    ax.axhline(STABLE_ERROR, color="grey", linestyle=":", linewidth=1)
    ax.text(0.47, STABLE_ERROR * 0.62, "0.05: stable threshold", fontsize=8, color="grey")
    ax.axhline(0.1, color="tab:red", linestyle=":", linewidth=1)
    ax.text(0.47, 0.1 * 1.15, "0.1: railfe stops (Energy error limit)", fontsize=8,
            color="tab:red")
    ax.set_yscale("log")
    ax.set_ylim(floor, 1.5)
    ax.set_xlim(0.45, 1.25)
    for r in rows:
        if r["mesh"] == "bar" and r["allow"] and r["ratio"] == 1.0 and r["steps"] <= 1:
            ax.annotate("bar, r >= 1: stopped at step 1\n(start-up transient > 0.1)",
                        (1.0, chart_error(r)), xytext=(1.03, 2e-3), fontsize=8,
                        arrowprops={"arrowstyle": "->", "color": "tab:blue"})
    ax.set_xlabel("fixed time step / stable limit railfe reports (L/c_P x its Lanczos "
                  "calibration; green: lowered for the viscosity)")
    ax.set_ylabel("max |energy error| (stopped runs: error at the stop)")
    ax.set_title("Central difference around the stable limit (Energy interval 1)")
    handles = [plt.Line2D([], [], marker="o", linestyle="", color=c, markeredgecolor="k",
                          label=MESHES[m][2]) for m, c in colours.items()]
    handles += [plt.Line2D([], [], marker=markers[o], linestyle="", color="0.6",
                           markeredgecolor=None if o == "refused" else "k",
                           markeredgewidth=1.8 if o == "refused" else 0.6, label=o)
                for o in markers if any(r["outcome"] == o for r in rows)]
    ax.legend(handles=handles, loc="center left", fontsize=8, framealpha=0.9)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
