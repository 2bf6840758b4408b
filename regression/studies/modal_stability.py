#!/usr/bin/env python3
"""Where the modal eigensolver breaks, and whether railfe notices: a free thin ring (six rigid-body
modes, then flexural doublets) solved for its 18 lowest modes with too small Krylov spaces, block
size 1 (which sees only one vector of each repeated eigenvalue per step), few restarts and shifts
that put K - sigma M off its positive definite range. Every run has the Sturm check on.

Each run is classed as
  correct     all 18 modes match the reference run and every check passes;
  detected    something is wrong and railfe says so (failed status, unconverged modes, Sturm
              mismatch, or a refusal with a message);
  undetected  the modes are wrong but every check passed (must never happen).

    /usr/bin/python3 regression/studies/modal_stability.py build/bin/railfe [workdir]

Writes docs/data/modal_stability.csv and docs/img/modal_stability.png.
"""
import csv
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import mpi_prefix, steel_materials_xml  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SECTION = os.path.join(ROOT, "inputs", "meshes", "ring_section_n4.msh")
N_MODES = 18


def ring_deck(block_size, krylov_dimension, restarts, shift):
    blocks = math.ceil(krylov_dimension / block_size)
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="ring stability"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="revolved"/>
    <ParameterList name="Revolved">
      <Parameter name="Section file" type="string" value="{SECTION}"/>
      <Parameter name="Elements around" type="int" value="128"/>
    </ParameterList>
  </ParameterList>
{steel_materials_xml(["ring"], young=200e9, density=8000)}  <ParameterList name="Steps">
    <ParameterList name="ring">
      <Parameter name="Module" type="string" value="modal"/>
      <Parameter name="Modes" type="int" value="{N_MODES}"/>
      <Parameter name="Block size" type="int" value="{block_size}"/>
      <Parameter name="Krylov blocks" type="int" value="{blocks}"/>
      <Parameter name="Maximum restarts" type="int" value="{restarts}"/>
      <Parameter name="Shift" type="double" value="{shift}"/>
      <Parameter name="Sturm check" type="bool" value="true"/>
      <Parameter name="Exodus" type="bool" value="false"/>
      <Parameter name="On failed check" type="string" value="warn"/>
      <ParameterList name="Classification">
        <Parameter name="Axisymmetric" type="bool" value="true"/>
        <Parameter name="Rim fraction" type="double" value="0.99"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def run(railfe, workdir, name, deck_text):
    deck = os.path.join(workdir, name + ".xml")
    with open(deck, "w") as out:
        out.write(deck_text)
    results = os.path.join(workdir, name)
    completed = subprocess.run(mpi_prefix(1) + [railfe, deck, "--output", results, "--quiet"],
                               capture_output=True, text=True)
    modes, summary = [], {}
    for candidate in ("ring_modes.csv", "ring_modes.csv.part"):
        path = os.path.join(results, candidate)
        if os.path.exists(path):
            with open(path) as table:
                modes = list(csv.DictReader(table))
    path = os.path.join(results, "summary.json")
    if os.path.exists(path):
        with open(path) as handle:
            summary = json.load(handle)
    message = next((line for line in completed.stderr.splitlines() if line.startswith("railfe:")),
                   "")
    return completed.returncode, modes, summary, message


def judge(returncode, modes, summary, reference):
    step = next((v for k, v in summary.items() if k.startswith("Step ring")), {})
    sturm = next((v for k, v in step.items() if k.startswith("Sturm check")), "")
    flagged = [m for m in modes if m["status"].startswith("failed")]
    unconverged = step.get("modes converged", N_MODES) < N_MODES
    sturm_ok = sturm != "" and sturm.split()[0] == sturm.split()[2]
    frequencies = [float(m["frequency_hz"]) for m in modes]
    right = (len(frequencies) == len(reference) and
             all(abs(a - b) <= 1e-6 * max(1.0, b) for a, b in zip(frequencies, reference)))
    if returncode == 1 and not modes:
        return "refused", sturm
    if right and not flagged and not unconverged and sturm_ok:
        return "correct", sturm
    if flagged or unconverged or not sturm_ok or returncode != 0:
        return "detected", sturm
    return "undetected", sturm


def main():
    railfe = os.path.abspath(sys.argv[1])
    workdir = sys.argv[2] if len(sys.argv) > 2 else "/tmp/railfe_modal_stability"
    os.makedirs(workdir, exist_ok=True)
    code, modes, summary, message = run(railfe, workdir, "reference", ring_deck(4, 48, 100, -1))
    assert code == 0, message
    reference = [float(m["frequency_hz"]) for m in modes]
    rows = []
    cases = [(bs, dim, restarts, -1.0) for bs in (1, 2, 4) for dim in (20, 24, 28, 36, 48)
             for restarts in (0, 2)]
    cases += [(4, 48, 100, shift) for shift in (-10.0, 0.0, 30.0, 100.0)]
    for bs, dim, restarts, shift in cases:
        name = f"bs{bs}_dim{dim}_r{restarts}_s{shift:g}"
        code, modes, summary, message = run(railfe, workdir, name,
                                            ring_deck(bs, dim, restarts, shift))
        outcome, sturm = judge(code, modes, summary, reference)
        flagged = sum(m["status"].startswith("failed") for m in modes)
        rows.append({"block_size": bs, "krylov_dimension": dim, "maximum_restarts": restarts,
                     "shift_hz": shift, "exit_status": code, "modes_returned": len(modes),
                     "modes_flagged": flagged, "sturm": sturm, "outcome": outcome,
                     "message": message if code != 0 else ""})
        print(f"{name:28s} exit {code}  {outcome:10s} returned {len(modes):2d} flagged "
              f"{flagged:2d}  {sturm}  {rows[-1]['message'][:70]}", flush=True)
    data = os.path.join(ROOT, "docs", "data", "modal_stability.csv")
    with open(data, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    chart(rows, os.path.join(ROOT, "docs", "img", "modal_stability.png"))
    return 1 if any(r["outcome"] == "undetected" for r in rows) else 0


def chart(rows, png):
    colours = {"correct": "tab:green", "detected": "tab:orange", "refused": "tab:blue",
               "undetected": "tab:red"}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [3, 1]})
    dims = sorted({r["krylov_dimension"] for r in rows if r["shift_hz"] == -1.0})
    ax = axes[0]
    for r in rows:
        if r["shift_hz"] != -1.0:
            continue
        y = r["block_size"] + (0.15 if r["maximum_restarts"] == 2 else -0.15)
        x = dims.index(r["krylov_dimension"])
        ax.scatter(x, y, s=260, color=colours[r["outcome"]], marker="s", edgecolor="k")
        ax.annotate(f"{r['modes_returned']}/{N_MODES}", (x, y), ha="center", va="center",
                    fontsize=7)
    ax.set_xticks(range(len(dims)), [str(d) for d in dims])
    ax.set_yticks([1, 2, 4])
    ax.set_xlabel(f"Krylov space dimension ({N_MODES} modes wanted)")
    ax.set_ylabel("block size (lower row: 0 restarts, upper: 2)")
    ax.set_title("free ring, shift -1 Hz: modes returned / wanted")
    ax = axes[1]
    shifts = [r for r in rows if r["shift_hz"] != -1.0]
    for i, r in enumerate(shifts):
        ax.scatter(0, i, s=260, color=colours[r["outcome"]], marker="s", edgecolor="k")
        ax.annotate(f"shift {r['shift_hz']:g} Hz: {r['outcome']}", (0.15, i), va="center",
                    fontsize=8)
    ax.set_xlim(-0.3, 2.0)
    ax.set_ylim(-0.7, len(shifts) - 0.3)
    ax.axis("off")
    ax.set_title("shift (block 4, dim 48)")
    handles = [plt.Line2D([], [], marker="s", linestyle="", color=c, markeredgecolor="k",
                          label=k) for k, c in colours.items()]
    fig.legend(handles=handles, loc="lower center", ncol=4, fontsize=8)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
