#!/usr/bin/python3
"""Cantilever under a tip load: mesh convergence of hex8 statics towards beam theory.

Runs the cantilever of inputs/verification/cantilever_timoshenko (L = 1 m, 0.1 x 0.1 m, 1000 N)
on meshes of n = 1, 2, 4, ... elements through the thickness (10 n along the length) with three
solvers, and writes
  docs/data/cantilever_convergence.csv   one row per run (units in the header)
  docs/img/cantilever_convergence.png    error against DOFs and against wall time
and prints the Markdown table used in docs/verification.md.

With --elements it instead compares the two hex8 formulations (Materials/.../Element: full
integration and enhanced strain) on n = 1, 2, 4, 8 with cholmod, against the converged value of
the table above, and writes docs/data/cantilever_elements.csv and docs/img/cantilever_elements.png.

Run from the repository root after building:
  /usr/bin/python3 regression/studies/cantilever_convergence.py [--railfe build/bin/railfe]
                                                               [--largest 32] [--elements]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import box_statics_deck, csv_rows, run_deck, step_section  # noqa: E402

E, NU, P, L, B = 210e9, 0.3, 1000.0, 1.0, 0.1
G = E / (2 * (1 + NU))
KAPPA = 10 * (1 + NU) / (12 + 11 * NU)  # Cowper's shear coefficient for a rectangle
TIMOSHENKO = P * L**3 / (3 * E * B**4 / 12) + P * L / (KAPPA * G * B * B)

SOLVERS = {
    "cg + muelu-sa": {"Method": "cg", "Preconditioner": "muelu-sa"},
    "cg + muelu": {"Method": "cg", "Preconditioner": "muelu"},
    "cholmod": {"Method": "cholmod"},
}


ELEMENTS = ("full integration", "enhanced strain")


def deck(n, solver, element="full integration"):
    text = box_statics_deck((L, B, B), (10 * n, n, n), "xmin", "xmax",
                            ("Total force", (0, 0, -P)), SOLVERS[solver], probe="xmax")
    blocks = '      <Parameter name="Blocks"'
    assert text.count(blocks) == 1
    return text.replace(blocks, f'      <Parameter name="Element" type="string" value="{element}"/>\n'
                        + blocks)


def converged_from_table():
    """The converged tip deflection of the full-integration series in the stored table."""
    with open("docs/data/cantilever_convergence.csv") as table:
        reference = next(r for r in csv.DictReader(table) if r["solver"] == "cg + muelu-sa")
    return float(reference["tip_deflection_m"]) / (1 + float(reference["error_vs_converged"]))


def compare_elements(args):
    converged = converged_from_table()
    rows = []
    for element in ELEMENTS:
        for n in (1, 2, 4, 8):
            name = f"n{n}_{element.replace(' ', '_')}"
            print(f"running n = {n} with the {element} hex8", flush=True)
            results, summary = run_deck(args.railfe, deck(n, "cholmod", element), args.work, name)
            tip = next(r for r in csv_rows(os.path.join(results, "load_probes.csv"))
                       if r["probe"] == "xmax")
            deflection = -float(tip["uz_m"])
            rows.append({"element": element, "elements_through_thickness": n,
                         "dofs": int(step_section(summary, "load")["degrees of freedom"]),
                         "tip_deflection_m": deflection,
                         "wall_time_s": summary["Wall time"]["total [s]"],
                         "error_vs_converged": deflection / converged - 1,
                         "error_vs_timoshenko": deflection / TIMOSHENKO - 1})
    with open("docs/data/cantilever_elements.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axis = plt.subplots(figsize=(6, 4.3))
    for element, marker in zip(ELEMENTS, "os"):
        runs = [r for r in rows if r["element"] == element]
        axis.loglog([r["dofs"] for r in runs], [abs(r["error_vs_converged"]) for r in runs],
                    marker + "-", label=element)
        for r in runs:
            axis.annotate(f"n={r['elements_through_thickness']}",
                          (r["dofs"], abs(r["error_vs_converged"])), textcoords="offset points",
                          xytext=(4, 4), fontsize=7)
    axis.set_xlabel("degrees of freedom (10n x n x n elements)")
    axis.set_ylabel("|tip deflection error| vs converged 3-D value")
    axis.set_title("Cantilever tip load: hex8 formulations")
    axis.legend(fontsize=8)
    axis.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig("docs/img/cantilever_elements.png", dpi=120)
    print(f"\nTimoshenko {TIMOSHENKO:.6e} m, converged 3-D {converged:.6e} m\n")
    print("| element | n | DOFs | tip deflection (m) | error vs converged | error vs Timoshenko "
          "| wall time (s) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['element']} | {r['elements_through_thickness']} | {r['dofs']} | "
              f"{r['tip_deflection_m']:.6e} | {r['error_vs_converged']:+.3%} | "
              f"{r['error_vs_timoshenko']:+.3%} | {r['wall_time_s']:.3f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--largest", type=int, default=32, help="finest n (power of 2)")
    parser.add_argument("--cholmod-largest", type=int, default=16)
    parser.add_argument("--work", default="build/studies/cantilever")
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the chart from docs/data/cantilever_convergence.csv")
    parser.add_argument("--elements", action="store_true",
                        help="compare the full-integration and enhanced-strain hex8 instead")
    args = parser.parse_args()
    if args.elements:
        compare_elements(args)
        return
    if args.plot_only:
        with open("docs/data/cantilever_convergence.csv") as table:
            rows = [{k: (v if k == "solver" else float(v)) for k, v in r.items()}
                    for r in csv.DictReader(table)]
        reference = next(r for r in rows if r["solver"] == "cg + muelu-sa")
        converged = reference["tip_deflection_m"] / (1 + reference["error_vs_converged"])
        plot(rows, converged)
        return

    rows = []
    sizes = [n for n in (1, 2, 4, 8, 16, 32, 64) if n <= args.largest]
    for solver in SOLVERS:
        for n in sizes:
            if solver == "cholmod" and n > args.cholmod_largest:
                continue
            name = f"n{n}_{solver.replace(' + ', '_').replace('-', '_')}"
            print(f"running n = {n:2d} with {solver}", flush=True)
            results, summary = run_deck(args.railfe, deck(n, solver), args.work, name)
            tip = next(r for r in csv_rows(os.path.join(results, "load_probes.csv"))
                       if r["probe"] == "xmax")
            step = step_section(summary, "load")
            rows.append({
                "elements_through_thickness": n,
                "dofs": int(step["degrees of freedom"]),
                "solver": solver,
                "tip_deflection_m": -float(tip["uz_m"]),
                "wall_time_s": summary["Wall time"]["total [s]"],
                "peak_memory_MiB": summary["Memory"]["peak resident, all ranks [MiB]"],
                "iterations": int(step["iterations"]),
            })

    # Converged value: Aitken extrapolation of the three finest runs of the reference solver.
    finest = [r["tip_deflection_m"] for r in rows if r["solver"] == "cg + muelu-sa"][-3:]
    d1, d2 = finest[1] - finest[0], finest[2] - finest[1]
    converged = finest[2] - d2 * d2 / (d2 - d1)
    for row in rows:
        row["error_vs_converged"] = row["tip_deflection_m"] / converged - 1
        row["error_vs_timoshenko"] = row["tip_deflection_m"] / TIMOSHENKO - 1

    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/cantilever_convergence.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, converged)

    print(f"\nTimoshenko (Cowper kappa = {KAPPA:.4f}): {TIMOSHENKO:.6e} m")
    print(f"converged hex8 value (Aitken, cg + muelu-sa): {converged:.6e} m "
          f"({converged / TIMOSHENKO - 1:+.3%} from Timoshenko)\n")
    print("| n | DOFs | solver | tip deflection (m) | error vs converged | error vs Timoshenko "
          "| iterations | wall time (s) | peak memory (MiB) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['elements_through_thickness']} | {r['dofs']} | {r['solver']} | "
              f"{r['tip_deflection_m']:.6e} | {r['error_vs_converged']:+.3%} | "
              f"{r['error_vs_timoshenko']:+.3%} | {r['iterations']} | {r['wall_time_s']:.2f} | "
              f"{r['peak_memory_MiB']:.0f} |")


def plot(rows, converged):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.3))
    reference = [r for r in rows if r["solver"] == "cg + muelu-sa"]
    dofs = [r["dofs"] for r in reference]
    left.loglog(dofs, [abs(r["error_vs_converged"]) for r in reference], "o-",
                label="discretisation error (vs converged hex8)")
    left.loglog(dofs, [abs(r["error_vs_timoshenko"]) for r in reference], "s--",
                label="difference from Timoshenko beam theory")
    slope_x = [dofs[1], dofs[-1]]
    slope_y = [abs(reference[1]["error_vs_converged"]) * (x / dofs[1]) ** (-2 / 3) for x in slope_x]
    left.loglog(slope_x, slope_y, "k:", label="$h^2$ (DOFs$^{-2/3}$)")
    floor = abs(converged / TIMOSHENKO - 1)
    left.axhline(floor, color="grey", lw=0.8)
    left.annotate(f"converged hex8 vs beam theory: {floor:.2%}\n(the clamped 3-D root)",
                  (dofs[0], floor), xytext=(0, -22), textcoords="offset points", fontsize=7,
                  color="grey")
    left.set_xlabel("degrees of freedom")
    left.set_ylabel("relative error of the tip deflection")
    left.set_title("Convergence (fully integrated hex8)")
    left.legend(fontsize=8)
    left.grid(True, which="both", alpha=0.3)
    for solver, marker in zip(SOLVERS, "o^s"):
        runs = [r for r in rows if r["solver"] == solver]
        right.loglog([r["wall_time_s"] for r in runs], [abs(r["error_vs_converged"]) for r in runs],
                     marker + "-", label=solver)
    right.set_xlabel("wall time of the whole run, 1 core (s)")
    right.set_ylabel("relative discretisation error")
    right.set_title("Accuracy against cost")
    right.legend(fontsize=8)
    right.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    os.makedirs("docs/img", exist_ok=True)
    figure.savefig("docs/img/cantilever_convergence.png", dpi=120)


if __name__ == "__main__":
    main()
