#!/usr/bin/env python3
"""Speed against accuracy of the contact theories on the issue's Hertz patch (0.46 m wheel on a
0.30 m crown, 100 kN, steel, mu 0.3), for six cases: longitudinal xi = 1e-3 and 3e-3, lateral
eta = 1e-3 and 3e-3, and spin phi = 0.5 and 2 /m (partial slip, from about half to mostly
sliding). Reference: the exact solver at 80 x 80. Each theory's error is the largest
|F - F_ref| / (mu N) over the cases (F = (Fx, Fy)); its time is the mean evaluation time the
contact-patch scene reports (for the exact solver, the normal problem included). The table is
the shipped creep-force table (exact solver at 30 x 30, interpolated).

Also writes, case by case, each theory's force along its creepage (Fx for xi, Fy for eta and
spin) and the spin moment against the reference: docs/data/contact_theories_by_case.csv.

    /usr/bin/python3 regression/studies/contact_speed_accuracy.py [build/bin/railfe] [workdir]

Writes docs/data/contact_speed_accuracy.csv, docs/data/contact_theories_by_case.csv and
docs/img/contact_speed_accuracy.png. Timings
need an idle machine.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import csv_rows, run_deck, xml_array  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "contact_speed_accuracy.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_speed_accuracy.png")
BY_CASE = os.path.join(ROOT, "docs", "data", "contact_theories_by_case.csv")
CASES = {"xi 1e-3": [1e-3, 0, 0], "xi 3e-3": [3e-3, 0, 0], "eta 1e-3": [0, 1e-3, 0],
         "eta 3e-3": [0, 3e-3, 0], "phi 0.5/m": [0, 0, 0.5], "phi 2/m": [0, 0, 2.0]}
MU_N = 0.3 * 1e5


def number(cell):
    """A CSV cell as a float; railfe leaves a cell empty where a theory defines no value."""
    return float(cell) if cell != "" else math.nan


def patch_deck(theories, fastsim_cells=20, exact_grid=40):
    # A deck gives only the parameters its theories use (railfe refuses the others).
    lines = []
    if "fastsim" in theories:
        lines.append(f'      <Parameter name="FASTSIM cells" type="int" value="{fastsim_cells}"/>')
    if "exact" in theories:
        lines.append(f'      <Parameter name="Exact grid" type="int" value="{exact_grid}"/>')
    if "fastsim" in theories or "exact" in theories:
        lines.append('      <Parameter name="Traction fields" type="bool" value="false"/>')
    grid_lines = "\n".join(lines)
    return f"""<ParameterList name="railfe">
  <ParameterList name="Steps">
    <ParameterList name="patch">
      <Parameter name="Module" type="string" value="contact patch"/>
      <Parameter name="Longitudinal creepage" type="Array(double)" value="{xml_array([c[0] for c in CASES.values()])}"/>
      <Parameter name="Lateral creepage" type="Array(double)" value="{xml_array([c[1] for c in CASES.values()])}"/>
      <Parameter name="Spin creepage" type="Array(double)" value="{xml_array([c[2] for c in CASES.values()])}"/>
      <Parameter name="Theories" type="Array(string)" value="{xml_array(theories)}"/>
{grid_lines}
      <Parameter name="Chart" type="bool" value="false"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def forces(railfe, workdir, name, theories, **grid):
    results, _ = run_deck(railfe, patch_deck(theories, **grid), workdir, name)
    return csv_rows(os.path.join(results, "patch_forces.csv"))


def main():
    railfe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe")
    workdir = sys.argv[2] if len(sys.argv) > 2 else "/tmp/railfe_contact_speed_accuracy"
    reference = {r["case"]: r for r in forces(railfe, workdir, "reference", ["exact"], exact_grid=80)}
    runs = [("linear", "linear", {}), ("shen-hedrick-elkins", "shen-hedrick-elkins", {}),
            ("polach", "polach", {}), ("table", "table", {})]
    runs += [(f"fastsim {n}x{n}", "fastsim", {"fastsim_cells": n}) for n in (5, 10, 20, 40, 80)]
    runs += [(f"exact {n}x{n}", "exact", {"exact_grid": n}) for n in (10, 20, 30, 40, 60)]
    out, by_case = [], []
    names = list(CASES)
    for label, theory, grid in runs:
        rows = forces(railfe, workdir, label.replace(" ", "_"), [theory], **grid)
        for r in rows:
            ref = reference[r["case"]]
            force = "Fx_N" if names[int(r["case"])].startswith("xi") else "Fy_N"
            relative = lambda column: (number(r[column]) / number(ref[column]) - 1) * 100  # noqa: E731
            by_case.append({"theory": label, "case": names[int(r["case"])], "force": force[:2],
                            "F_N": float(r[force]), "F_reference_N": float(ref[force]),
                            "F_difference_percent": relative(force),
                            "Mz_Nm": number(r["Mz_Nm"]), "Mz_reference_Nm": number(ref["Mz_Nm"]),
                            "Mz_difference_percent": relative("Mz_Nm") if force == "Fy_N" else ""})
        error = max(math.hypot(float(r["Fx_N"]) - float(reference[r["case"]]["Fx_N"]),
                               float(r["Fy_N"]) - float(reference[r["case"]]["Fy_N"])) / MU_N for r in rows)
        seconds = sum(float(r["time_s"]) for r in rows) / len(rows)
        out.append({"theory": label, "time_s": seconds, "max_error_over_muN": error})
        print(f"{label:22s} {seconds:10.3e} s  error {error:.2e} mu N")
    with open(CSV, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["theory", "time_s", "max_error_over_muN"])
        writer.writeheader()
        writer.writerows(out)
    with open(BY_CASE, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(by_case[0]))
        writer.writeheader()
        writer.writerows(by_case)
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for family, marker in (("linear", "s"), ("shen", "D"), ("polach", "v"), ("table", "P"), ("fastsim", "o"),
                           ("exact", "^")):
        mine = [r for r in out if r["theory"].startswith(family)]
        ax.loglog([r["time_s"] for r in mine], [r["max_error_over_muN"] for r in mine], marker + "-",
                  label=family if family != "shen" else "shen-hedrick-elkins")
        for r in mine:
            ax.annotate(r["theory"].split(" ")[-1] if " " in r["theory"] else "", (r["time_s"], r["max_error_over_muN"]),
                        textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.axvline(50e-3, color="grey", ls="--", lw=0.8)
    ax.text(50e-3, ax.get_ylim()[1], " exact target 50 ms", fontsize=7, va="top")
    ax.set_xlabel("evaluation time, one core (s)")
    ax.set_ylabel("largest creep-force error / (μN) against exact 80 × 80")
    ax.set_title("Contact theories: speed against accuracy (two ξ, two η and two spin cases)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(PNG, dpi=110)
    print("wrote", PNG)


if __name__ == "__main__":
    main()
