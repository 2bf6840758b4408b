#!/usr/bin/env python3
"""Where central difference goes unstable, and whether railfe notices: fixed time steps at
r = 0.5 ... 1.2 times the stable limit (L / c_P of the smallest element, taken from the
"stable step at start" of a first, automatic run) on two meshes:
  bar    the bar of inputs/verification/explicit_bar_wave (1 m x 10 mm x 10 mm steel, 200 x 2 x 2
         one-point hex8 of 5 mm, bulk viscosity off) with the end xmin pushed by the
         non-symmetric velocity 0.1*(1 + y + 2*z) m/s on x, y and z (as in
         regression/bad_input/explicit_unstable_step_blows_up.xml), 170 us;
  cube   a free 0.1 m steel cube, 10 x 10 x 10 elements of 10 mm, started with the rigid
         velocity field V + omega x X (V = {1, 2, 3} m/s, omega = {100, 200, 300} rad/s about
         its centre), 200 us.
Every step is run with Allow unstable step true; every r > 1 is run again without it, and must
be refused. Each run is classed as
  stable      completed, max |energy_error| < 0.05 and the kinetic energy never above 10 x the
              largest of the automatic run;
  detected    stopped with exit 2 and 'growing without bound';
  refused     exit 1 with 'above the stable limit' (only the runs without Allow unstable step);
  undetected  completed, but max |energy_error| >= 0.05 or the kinetic energy grew more than
              10 x (must never happen);
  other       anything else (a refusal that did not happen, another failure).
Near r = 1 the energy error of central difference legitimately grows: the discrete energy
differs from the true one by a factor 1 / (1 - (omega dt / 2)^2) in the highest mode.

    /usr/bin/python3 regression/studies/explicit_stability.py build/bin/railfe [workdir]

Writes docs/data/explicit_stability.csv and docs/img/explicit_stability.png; exits 1 if a run is
undetected or other.
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
from railfe_runs import mpi_prefix, steel_materials_xml  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RATIOS = (0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.98, 1.0, 1.02, 1.05, 1.1, 1.15, 1.2)
STABLE_ERROR = 0.05
KINETIC_GROWTH = 10.0


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


def bar_deck(time_step=None, allow=False, end_time=170e-6):
    """The explicit_bar_wave bar pushed at xmin by 0.1*(1 + y + 2*z) m/s on x, y and z."""
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="bar, non-symmetric push"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="box"/>
    <ParameterList name="Box">
      <Parameter name="Lengths" type="Array(double)" value="{{1.0, 0.01, 0.01}}"/>
      <Parameter name="Elements" type="Array(int)" value="{{200, 2, 2}}"/>
      <Parameter name="Block name" type="string" value="bar"/>
    </ParameterList>
  </ParameterList>
{steel_materials_xml(["bar"])}  <ParameterList name="Output">
    <Parameter name="Exodus" type="bool" value="false"/>
  </ParameterList>
  <ParameterList name="Steps">
    <ParameterList name="bar">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:g}"/>
      {step_xml(time_step, allow)}
      <ParameterList name="Solid">
        <Parameter name="Bulk viscosity linear" type="double" value="0"/>
        <Parameter name="Bulk viscosity quadratic" type="double" value="0"/>
      </ParameterList>
      <ParameterList name="Prescribed motion">
        <ParameterList name="pushed end">
          <Parameter name="Node set" type="string" value="xmin"/>
          <Parameter name="Components" type="string" value="xyz"/>
          <Parameter name="Function" type="string" value="0.1*(1 + y + 2*z)"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def cube_deck(time_step=None, allow=False, end_time=200e-6):
    """A free 0.1 m steel cube (10 mm elements) spinning and translating from t = 0."""
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="free spinning cube"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="box"/>
    <ParameterList name="Box">
      <Parameter name="Origin" type="Array(double)" value="{{-0.05, -0.05, -0.05}}"/>
      <Parameter name="Lengths" type="Array(double)" value="{{0.1, 0.1, 0.1}}"/>
      <Parameter name="Elements" type="Array(int)" value="{{10, 10, 10}}"/>
      <Parameter name="Block name" type="string" value="cube"/>
    </ParameterList>
  </ParameterList>
{steel_materials_xml(["cube"])}  <ParameterList name="Output">
    <Parameter name="Exodus" type="bool" value="false"/>
  </ParameterList>
  <ParameterList name="Steps">
    <ParameterList name="cube">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:g}"/>
      {step_xml(time_step, allow)}
      <ParameterList name="Initial velocity">
        <ParameterList name="spin">
          <Parameter name="Translation" type="Array(double)" value="{{1, 2, 3}}"/>
          <Parameter name="Angular velocity" type="Array(double)" value="{{100, 200, 300}}"/>
          <Parameter name="Axis point" type="Array(double)" value="{{0, 0, 0}}"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


MESHES = {"bar": bar_deck, "cube": cube_deck}


def explicit_section(summary, step):
    """The summary section of explicit step `step` (key "explicit step '<step>'")."""
    for key, value in summary.items():
        if key.endswith(f"step '{step}'"):
            return value
    raise KeyError(step)


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
        section = explicit_section(summary, step)
    except KeyError:
        section = {}
    return {"exit": completed.returncode, "message": message, "summary": summary,
            "section": section, "energy": energy, "results": results}


def max_abs(rows, column):
    return max((abs(float(r[column])) for r in rows), default=float("nan"))


def classify(run, allow, reference_kinetic):
    """The outcome of one run (see the module docstring)."""
    code, message = run["exit"], run["message"]
    if not allow:
        return "refused" if code == 1 and "above the stable limit" in message else "other"
    if code == 2 and "growing without bound" in message:
        return "detected"
    if code != 0:
        return "other"
    error = max_abs(run["energy"], "energy_error")
    kinetic = max_abs(run["energy"], "kinetic_J")
    if error < STABLE_ERROR and kinetic <= KINETIC_GROWTH * reference_kinetic:
        return "stable"
    return "undetected"


def steps_taken(run):
    if run["section"]:
        return run["section"]["steps"]
    found = re.search(r"\(step (\d+)\)", run["message"])
    if found:
        return int(found.group(1))
    return int(run["energy"][-1]["step"]) if run["energy"] else 0


def main():
    railfe = os.path.abspath(sys.argv[1])
    workdir = sys.argv[2] if len(sys.argv) > 2 else "/tmp/railfe_explicit_stability"
    os.makedirs(workdir, exist_ok=True)
    rows = []
    for mesh, deck in MESHES.items():
        automatic = run_explicit(railfe, workdir, f"{mesh}_automatic", deck(), mesh)
        assert automatic["exit"] == 0, automatic["message"]
        limit = automatic["section"]["stable step at start [s]"]
        reference_kinetic = max_abs(automatic["energy"], "kinetic_J")
        print(f"{mesh}: stable limit {limit:.6g} s, automatic run "
              f"{automatic['section']['steps']} steps, max |energy error| "
              f"{max_abs(automatic['energy'], 'energy_error'):.3g}", flush=True)
        cases = [(r, True) for r in RATIOS] + [(r, False) for r in RATIOS if r > 1]
        for ratio, allow in cases:
            name = f"{mesh}_r{ratio:g}" + ("" if allow else "_not_allowed")
            run = run_explicit(railfe, workdir, name, deck(ratio * limit, allow), mesh)
            outcome = classify(run, allow, reference_kinetic)
            kinetic = max_abs(run["energy"], "kinetic_J")
            rows.append({
                "mesh": mesh, "ratio": ratio, "stable_limit_s": limit,
                "time_step_s": ratio * limit, "allow_unstable_step": allow,
                "exit_status": run["exit"], "outcome": outcome,
                "max_abs_energy_error": max_abs(run["energy"], "energy_error"),
                "max_kinetic_over_automatic": kinetic / reference_kinetic,
                "steps": steps_taken(run) if run["exit"] != 1 else 0,
                "message": run["message"][len("railfe: "):] if run["exit"] else ""})
            r = rows[-1]
            print(f"{name:22s} exit {r['exit_status']}  {outcome:10s} max|err| "
                  f"{r['max_abs_energy_error']:9.3g}  KE/KE_auto "
                  f"{r['max_kinetic_over_automatic']:9.3g}  steps {r['steps']:4d}  "
                  f"{r['message'][:60]}", flush=True)
    data = os.path.join(ROOT, "docs", "data", "explicit_stability.csv")
    header = {"mesh": "mesh", "ratio": "step_over_stable_limit", "stable_limit_s":
              "stable_limit_s", "time_step_s": "time_step_s", "allow_unstable_step":
              "allow_unstable_step", "exit_status": "exit_status", "outcome": "outcome",
              "max_abs_energy_error": "max_abs_energy_error",
              "max_kinetic_over_automatic": "max_kinetic_over_automatic_run",
              "steps": "steps", "message": "message"}
    with open(data, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(header.values())
        for r in rows:
            writer.writerow([f"{r[k]:.6g}" if isinstance(r[k], float) else r[k] for k in header])
    chart(rows, os.path.join(ROOT, "docs", "img", "explicit_stability.png"))
    return 1 if any(r["outcome"] in ("undetected", "other") for r in rows) else 0


def chart(rows, png):
    markers = {"stable": "o", "detected": "^", "refused": "x", "undetected": "*", "other": "s"}
    colours = {"bar": "tab:blue", "cube": "tab:orange"}
    floor = 1e-9
    fig, ax = plt.subplots(figsize=(8.5, 5))
    bottom = {"bar": 3 * floor, "cube": 1.5 * floor}
    for r in rows:
        if r["outcome"] == "refused":
            y = bottom[r["mesh"]]
        else:
            y = max(r["max_abs_energy_error"], floor * 10)
        filled = r["outcome"] != "refused"
        ax.scatter(r["ratio"], y, marker=markers[r["outcome"]], s=70 if filled else 60,
                   color=colours[r["mesh"]],
                   edgecolor="k" if filled and r["outcome"] != "refused" else None,
                   linewidths=0.6 if r["outcome"] != "refused" else 1.8, zorder=3)
    for mesh in colours:
        series = sorted((r["ratio"], r["max_abs_energy_error"]) for r in rows
                        if r["mesh"] == mesh and r["allow_unstable_step"]
                        and r["outcome"] != "refused")
        ax.plot([s[0] for s in series], [max(s[1], floor * 10) for s in series],
                color=colours[mesh], linewidth=0.8, alpha=0.6, zorder=2)
    ax.axvline(1.0, color="k", linestyle="--", linewidth=1)
    ax.axhline(STABLE_ERROR, color="grey", linestyle=":", linewidth=1)
    ax.text(0.49, STABLE_ERROR * 1.15, "0.05: stable threshold", fontsize=8, color="grey")
    ax.axhspan(floor, 6 * floor, color="0.92", zorder=0)
    ax.text(0.49, 4.2 * floor, "refused without Allow unstable step (no run)", fontsize=8,
            va="center")
    ax.set_yscale("log")
    ax.set_ylim(floor, 1)
    ax.set_xlim(0.45, 1.25)
    ax.set_xlabel("fixed time step / stable limit L/c_P")
    ax.set_ylabel("max |energy error| over the run")
    ax.set_title("Central difference stability: fixed steps around the stable limit")
    handles = [plt.Line2D([], [], marker="o", linestyle="", color=c, markeredgecolor="k",
                          label=f"{m}") for m, c in colours.items()]
    handles += [plt.Line2D([], [], marker=markers[o], linestyle="", color="0.5",
                           markeredgecolor="k" if o != "refused" else None,
                           label=o) for o in markers
                if any(r["outcome"] == o for r in rows)]
    ax.legend(handles=handles, loc="upper left", fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
