#!/usr/bin/python3
"""Benchmark: linear statics of a steel cube at ~1e5 and ~1e6 DOFs on 1 and 2 ranks.

The cube (1 m, hex8 n x n x n, clamped at z = 0, 1 MPa on z = 1, gravity) is solved with CG to
1e-10, preconditioned by the default MueLu plain aggregation and, for comparison, by Jacobi. Reported per run: sparsity and assembly time,
assembly rate, solver set-up and solve time, iterations, peak memory per DOF (all ranks), and the
2-rank parallel efficiency t1 / (2 t2). Targets (issue 2): assembly >= 1e6 elements/s/core,
the 1e5-DOF solve <= 2 s on one core, <= 2 kB per DOF, efficiency >= 80 %.

Writes docs/data/statics_block_benchmark.csv and prints a Markdown table. Run on an idle machine
from the repository root after building:
  /usr/bin/python3 regression/benchmarks/statics_block.py [--railfe build/bin/railfe] [--sizes 32 69]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import box_statics_deck, run_deck, step_section  # noqa: E402


def deck(n, preconditioner):
    return box_statics_deck((1, 1, 1), (n, n, n), "zmin", "zmax", ("Pressure", (1e6,)),
                            {"Preconditioner": preconditioner, "Maximum iterations": 10000},
                            gravity=(0, 0, -9.81))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--sizes", type=int, nargs="+", default=[32, 69])
    parser.add_argument("--preconditioners", nargs="+", default=["muelu", "jacobi"])
    parser.add_argument("--work", default="build/benchmarks/statics_block")
    args = parser.parse_args()
    rows = []
    runs = [(n, p, ranks) for n in args.sizes for p in args.preconditioners for ranks in (1, 2)]
    for n, preconditioner, ranks in runs:
        print(f"n = {n} ({n ** 3} elements), {preconditioner}, {ranks} rank(s)", flush=True)
        _, summary = run_deck(args.railfe, deck(n, preconditioner), args.work,
                              f"cube{n}_{preconditioner}_np{ranks}", ranks)
        step = step_section(summary, "load")
        dofs = step["degrees of freedom"]
        rows.append({
            "preconditioner": preconditioner,
            "elements": n ** 3,
            "dofs": int(dofs),
            "ranks": ranks,
            "graph_s": step["time: sparsity graph [s]"],
            "assembly_s": step["time: stiffness assembly [s]"],
            "assembly_rate_elements_per_s_per_core":
                n ** 3 / ranks / step["time: stiffness assembly [s]"],
            "solver_setup_s": step["time: solver setup [s]"],
            "solve_s": step["time: solve [s]"],
            "iterations": int(step["iterations"]),
            "step_s": summary["Wall time"]["step load [s]"],
            "peak_memory_bytes_per_dof":
                summary["Memory"]["peak resident, all ranks [MiB]"] * 2**20 / dofs,
        })
    one = {(r["elements"], r["preconditioner"]): r for r in rows if r["ranks"] == 1}
    for row in rows:
        base = one[(row["elements"], row["preconditioner"])]
        row["assembly_efficiency"] = base["assembly_s"] / (row["ranks"] * row["assembly_s"])
        row["solve_efficiency"] = (base["solver_setup_s"] + base["solve_s"]) / (
            row["ranks"] * (row["solver_setup_s"] + row["solve_s"]))
        row["step_efficiency"] = base["step_s"] / (row["ranks"] * row["step_s"])
    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/statics_block_benchmark.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("\n| DOFs | preconditioner | ranks | graph (s) | assembly (s) | assembly rate per core (el/s) | "
          "set-up (s) | solve (s) | iterations | set-up + solve (s) | bytes per DOF | "
          "efficiency assembly / solve / step |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['dofs']:,} | {r['preconditioner']} | {r['ranks']} | {r['graph_s']:.2f} | {r['assembly_s']:.3f} | "
              f"{r['assembly_rate_elements_per_s_per_core']:,.0f} | {r['solver_setup_s']:.2f} | "
              f"{r['solve_s']:.2f} | {r['iterations']} | "
              f"{r['solver_setup_s'] + r['solve_s']:.2f} | {r['peak_memory_bytes_per_dof']:,.0f} | "
              f"{r['assembly_efficiency']:.0%} / {r['solve_efficiency']:.0%} / "
              f"{r['step_efficiency']:.0%} |")


if __name__ == "__main__":
    main()
