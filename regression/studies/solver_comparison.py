#!/usr/bin/python3
"""Linear solvers on 3-D elasticity: time, iterations and memory of each method.

Solves the clamped cube of the statics benchmark (16^3 and 32^3 hex8: 15k and 108k DOFs) and the
slender cantilever (80 x 8 x 8) with every Method/Preconditioner pair railfe offers (KLU2 only on
the small cube: it takes minutes beyond). Writes docs/data/solver_comparison.csv and
docs/img/solver_comparison.png and prints a Markdown table (docs/solvers.md).

  /usr/bin/python3 regression/studies/solver_comparison.py [--railfe build/bin/railfe]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import box_statics_deck, run_deck, step_section  # noqa: E402

METHODS = [("cg", "muelu"), ("cg", "muelu-sa"), ("cg", "ilu"), ("cg", "jacobi"),
           ("gmres", "muelu"), ("cholmod", "none"), ("klu2", "none")]


def deck(problem, method, preconditioner):
    solver = {"Method": method}
    if method in ("cg", "gmres"):  # direct methods refuse Krylov settings
        solver.update({"Preconditioner": preconditioner, "Maximum iterations": 5000})
    if problem.startswith("cube"):
        n = int(problem[4:])
        return box_statics_deck((1, 1, 1), (n, n, n), "zmin", "zmax",
                                ("Total force", (0, 0, -1e6)), solver)
    return box_statics_deck((1, 0.1, 0.1), (80, 8, 8), "xmin", "xmax",
                            ("Total force", (0, 0, -1000)), solver)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--work", default="build/studies/solvers")
    args = parser.parse_args()
    rows = []
    for problem in ("cube16", "cube32", "cantilever"):
        for method, preconditioner in METHODS:
            if method == "klu2" and problem != "cube16":
                continue
            label = method if preconditioner == "none" else f"{method} + {preconditioner}"
            print(f"{problem}: {label}", flush=True)
            name = f"{problem}_{method}_{preconditioner}".replace("-", "_")
            try:
                _, summary = run_deck(args.railfe, deck(problem, method, preconditioner),
                                      args.work, name)
            except RuntimeError as error:
                print(f"  failed: {str(error).splitlines()[-1]}")
                continue
            step = step_section(summary, "load")
            rows.append({
                "problem": problem, "method": label, "dofs": int(step["degrees of freedom"]),
                "iterations": int(step["iterations"]),
                "setup_s": step["time: solver setup [s]"], "solve_s": step["time: solve [s]"],
                "setup_plus_solve_s": step["time: solver setup [s]"] + step["time: solve [s]"],
                "peak_memory_MiB": summary["Memory"]["peak resident, all ranks [MiB]"],
                "relative_residual": step["relative residual"],
                "backward_error": step["backward error"],
            })
    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/solver_comparison.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("\n| problem | DOFs | method | iterations | set-up (s) | solve (s) | set-up + solve (s) "
          "| peak memory (MiB) | backward error |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['problem']} | {r['dofs']:,} | {r['method']} | {r['iterations']} | "
              f"{r['setup_s']:.2f} | {r['solve_s']:.2f} | {r['setup_plus_solve_s']:.2f} | "
              f"{r['peak_memory_MiB']:.0f} | {r['backward_error']:.1e} |")
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    problems = ["cube16", "cube32", "cantilever"]
    figure, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    for axis, problem in zip(axes, problems):
        runs = [r for r in rows if r["problem"] == problem]
        for r in runs:
            axis.scatter(r["peak_memory_MiB"], r["setup_plus_solve_s"], s=40)
            axis.annotate(f"{r['method']} ({r['iterations']} it)",
                          (r["peak_memory_MiB"], r["setup_plus_solve_s"]), fontsize=7,
                          xytext=(4, 3), textcoords="offset points")
        axis.set_yscale("log")
        axis.set_xlabel("peak memory of the run (MiB)")
        axis.set_ylabel("solver set-up + solve, 1 core (s)")
        axis.set_title(f"{problem} ({runs[0]['dofs']:,} DOFs)" if runs else problem)
        axis.grid(True, which="both", alpha=0.3)
    figure.suptitle("Linear solvers on hex8 elasticity: all solutions checked to the same "
                    "accuracy (relative residual 1e-10 or backward error at round-off)",
                    fontsize=9)
    figure.tight_layout()
    os.makedirs("docs/img", exist_ok=True)
    figure.savefig("docs/img/solver_comparison.png", dpi=120)


if __name__ == "__main__":
    main()
