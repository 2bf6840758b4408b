#!/usr/bin/env python3
"""Direct method benchmark: a vehicle of ~10^3 unknowns (8 wheels tied to the bridge) crossing a
simply supported grillage of ~10^4 and ~10^5 unknowns for 1000 HHT-alpha steps, each step one
saddle-point solve, with the block solver (structure factored once by CHOLMOD, constraints
through the Schur complement) against the monolithic one (the whole saddle-point matrix through
UMFPACK every step). The configurations run interleaved, best of --repeat; wall and CPU time per
step and per Newton iteration go to docs/data/direct_method_benchmark.csv.
Wall and CPU time are each the best of the repeats.
Usage: direct_method_benchmark.py [--exe build/bin/railfe-moving-study] [--repeat 3]
       [--monolithic-steps-large 100] [--repeat-large 3] (the monolithic 10^5 run takes about
       0.7 s a step on one core: by default 100 steps and per-step figures; say so when quoting
       them)."""
import argparse
import csv
import os
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# (label, lines, elements): 6 DOFs a node, n_lines * (elements + 1) nodes, less the supports.
BRIDGES = [("1e4", 4, 416), ("1e5", 10, 1666)]


def run(exe, lines, elements, solver, steps):
    args = [exe, "span=100", f"lines={lines}", f"elements={elements}", "wheels=8",
            "vehicle_dofs=1000", "wheel_mass=500", "vehicle_mass=5000", "dt=0.001",
            "alpha=-0.05", f"solver={solver}", f"steps={steps}", "every=100"]
    out = subprocess.run(["nice"] + args, check=True, capture_output=True, text=True).stdout
    return {k: v for k, v in (line.split("=", 1) for line in out.splitlines() if "=" in line)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default=os.path.join(ROOT, "build/bin/railfe-moving-study"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--monolithic-steps-large", type=int, default=100)
    parser.add_argument("--repeat-large", type=int, default=3)
    a = parser.parse_args()
    rows = []
    for label, lines, elements in BRIDGES:
        best = {}
        for _ in range(a.repeat if label == "1e4" else a.repeat_large):
            for solver in ("block", "monolithic"):
                steps = a.steps
                if solver == "monolithic" and label == "1e5":
                    steps = a.monolithic_steps_large
                r = run(a.exe, lines, elements, solver, steps)
                if solver not in best:
                    best[solver] = dict(r)
                for key in ("wall_s", "cpu_s"):  # best of the repeats, each on its own
                    best[solver][key] = str(min(float(best[solver][key]), float(r[key])))
        for solver, r in best.items():
            steps, iterations = int(r["steps"]), int(r["newton_iterations"])
            rows.append({
                "bridge": label, "structure_unknowns": r["structure_unknowns"],
                "unknowns": r["unknowns"], "solver": solver, "steps": steps,
                "wall_s": float(r["wall_s"]), "cpu_s": float(r["cpu_s"]),
                "wall_ms_per_step": 1e3 * float(r["wall_s"]) / steps,
                "cpu_ms_per_step": 1e3 * float(r["cpu_s"]) / steps,
                "wall_ms_per_iteration": 1e3 * float(r["wall_s"]) / iterations,
                "structure_factorizations": r["structure_factorizations"]})
            print(rows[-1], flush=True)
        ratio = rows[-1]["cpu_ms_per_step"] / rows[-2]["cpu_ms_per_step"]
        print(f"bridge {label}: monolithic / block CPU time per step = {ratio:.1f}", flush=True)
    path = os.path.join(ROOT, "docs/data/direct_method_benchmark.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote", path)


if __name__ == "__main__":
    main()
