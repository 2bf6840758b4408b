#!/usr/bin/python3
"""Benchmark: time per element-step of the explicit module ("time per zone cycle", as LS-DYNA
reports it) for ~1e5 and ~1e6 one-point hex8 elements on 1 and 2 ranks, and memory per element.

A free steel block (1 m cube, n x n x n one-point hex8 with stiffness hourglass control and the
default bulk viscosity) spins and translates (initial velocity field), so every element strains
and every force path runs; the automatic step (0.9 x stable) is recomputed every step. Reported
per run: steps, stepping wall time, wall time per element-step (us) and that time x ranks (core
time), 2-rank parallel efficiency t1 / (2 t2), peak memory of all ranks per element, and the
marginal memory per element between the two sizes (what one more element costs: the kernel's
arrays, the nodal state, the replicated mesh). Targets (issue 4): <= 0.25 us per element-step on
one core (the LULESH 2.0 proxy runs at 0.54 us on this class of machine), >= 85 % efficiency on
2 ranks, <= 1 kB per element.

Writes docs/data/explicit_benchmark.csv and prints a Markdown table. Run on an idle machine from
the repository root after building:
  /usr/bin/python3 regression/benchmarks/explicit_kernel.py [--railfe build/bin/railfe]
      [--sizes 46 100] [--steps 400 60]

With --compare, it instead times the scalar and the batched (SIMD) kernel side by side (issue 16:
<= 0.08 us per element-step): one rank, the two kernels (Solid/Kernel) run in turn, the order
rotated every round, best of --repeats rounds, wall and CPU time of the stepping (CPU: the rank's
processor time, fairer on a shared machine), and the ratios to the scalar kernel. --baseline adds
another railfe executable (e.g. the main branch's build, whose only kernel is the scalar one),
wall time only where it does not report CPU time. Each run records the pass it took (summary's
"solid kernel": 8 lanes with AVX-512, 4 with AVX2). Writes --csv (default
docs/data/explicit_kernel_simd.csv, the AVX-512 machine's; docs/data/explicit_kernel_avx2.csv
holds an AVX2 machine's):
  /usr/bin/python3 regression/benchmarks/explicit_kernel.py --compare [--sizes 46 100]
      [--steps 200 30] [--repeats 5] [--baseline ../main/build/bin/railfe] [--csv FILE]
"""
import argparse
import csv
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import (box_mesh_xml, output_xml, run_deck, steel_materials_xml,  # noqa: E402
                         step_section)


def deck(n, steps, kernel=None):
    """A free spinning cube of n^3 elements run for about `steps` automatic steps; `kernel`
    (scalar or batched) sets Solid/Kernel, None leaves the default."""
    stable = (1.0 / n) / 6001.4
    end_time = 0.9 * stable * steps
    solid = ("" if kernel is None else f"""      <ParameterList name="Solid">
        <Parameter name="Kernel" type="string" value="{kernel}"/>
      </ParameterList>
""")
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="explicit benchmark"/>
{box_mesh_xml((1, 1, 1), (n, n, n), "block")}{output_xml()}{steel_materials_xml(["block"])}  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:.9g}"/>
      <ParameterList name="Initial velocity">
        <ParameterList name="spin">
          <Parameter name="Translation" type="Array(double)" value="{{1, 2, 3}}"/>
          <Parameter name="Angular velocity" type="Array(double)" value="{{30, 20, 10}}"/>
          <Parameter name="Axis point" type="Array(double)" value="{{0.3, 0.5, 0.5}}"/>
        </ParameterList>
      </ParameterList>
{solid}      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1000000"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def compare_kernels(args):
    """The scalar and batched kernels (and --baseline) side by side, best of args.repeats."""
    configurations = [("scalar", args.railfe, "scalar"), ("batched", args.railfe, "batched")]
    if args.baseline:
        configurations.append(("baseline", args.baseline, None))
    runs = []
    for n, steps in zip(args.sizes, args.steps):
        for round_index in range(args.repeats):
            shift = round_index % len(configurations)
            for label, railfe, kernel in configurations[shift:] + configurations[:shift]:
                _, summary = run_deck(railfe, deck(n, steps, kernel), args.work,
                                      f"compare{n}_{label}")
                step = step_section(summary, "run")
                element_steps = n ** 3 * step["steps"]
                cpu = step.get("time: stepping, CPU of rank 0 [s]")
                runs.append({
                    "elements": n ** 3, "kernel": label, "round": round_index,
                    "utc": time.strftime("%H:%M:%S", time.gmtime()), "steps": int(step["steps"]),
                    "wall_us_per_element_step": 1e6 * step["time: stepping [s]"] / element_steps,
                    "cpu_us_per_element_step":
                        "" if cpu is None else 1e6 * cpu / element_steps,
                    "energy_error_at_end": step["energy error at end"],
                    "pass": step.get("solid kernel", ""),
                })
                print(f"{n ** 3} elements, {label}: wall {runs[-1]['wall_us_per_element_step']:.4f}"
                      f" us, CPU {runs[-1]['cpu_us_per_element_step']} us", flush=True)
    os.makedirs(os.path.dirname(args.csv) or ".", exist_ok=True)
    with open(args.csv, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(runs[0].keys()))
        writer.writeheader()
        writer.writerows(runs)
    print(f"\nbest of {args.repeats} rounds, one rank (us per element-step; ratio = scalar / this)")
    print("| elements | kernel | wall | CPU | wall ratio | CPU ratio |")
    print("|---|---|---|---|---|---|")
    for n in args.sizes:
        best = {}
        for label, _, _ in configurations:
            mine = [r for r in runs if r["elements"] == n ** 3 and r["kernel"] == label]
            cpus = [r["cpu_us_per_element_step"] for r in mine
                    if r["cpu_us_per_element_step"] != ""]
            best[label] = (min(r["wall_us_per_element_step"] for r in mine),
                           min(cpus) if cpus else None)
        for label, (wall, cpu) in best.items():
            scalar_wall, scalar_cpu = best["scalar"]
            cpu_text = f"{cpu:.4f}" if cpu is not None else "—"
            cpu_ratio = f"{scalar_cpu / cpu:.2f}" if cpu is not None else "—"
            print(f"| {n ** 3:,} | {label} | {wall:.4f} | {cpu_text} | {scalar_wall / wall:.2f} | "
                  f"{cpu_ratio} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--sizes", type=int, nargs="+", default=[46, 100])
    parser.add_argument("--steps", type=int, nargs="+", default=None,
                        help="steps per size (default 400 60; with --compare 200 30)")
    parser.add_argument("--work", default="build/benchmarks/explicit_kernel")
    parser.add_argument("--compare", action="store_true",
                        help="scalar against batched kernel, interleaved, best of --repeats")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--baseline", help="another railfe executable to time beside them")
    parser.add_argument("--csv", default="docs/data/explicit_kernel_simd.csv",
                        help="with --compare: where the runs go (one file per instruction set: "
                        "the batched pass is 8 lanes with AVX-512, 4 with AVX2 only)")
    args = parser.parse_args()
    if args.steps is None:
        args.steps = [200, 30] if args.compare else [400, 60]
    if args.compare:
        compare_kernels(args)
        return
    rows = []
    for n, steps in zip(args.sizes, args.steps):
        for ranks in (1, 2):
            print(f"n = {n} ({n ** 3} elements), {ranks} rank(s)", flush=True)
            _, summary = run_deck(args.railfe, deck(n, steps), args.work, f"cube{n}_np{ranks}",
                                  ranks)
            step = step_section(summary, "run")
            elements = n ** 3
            taken = step["steps"]
            seconds = step["time: stepping [s]"]
            rows.append({
                "elements": elements,
                "ranks": ranks,
                "steps": int(taken),
                "stepping_s": seconds,
                "setup_s": step["time: setup [s]"],
                "wall_us_per_element_step": 1e6 * seconds / (elements * taken),
                "core_us_per_element_step": 1e6 * seconds * ranks / (elements * taken),
                "peak_memory_all_ranks_MiB": summary["Memory"]["peak resident, all ranks [MiB]"],
                "bytes_per_element_all_ranks":
                    summary["Memory"]["peak resident, all ranks [MiB]"] * 2**20 / elements,
            })
    one = {r["elements"]: r for r in rows if r["ranks"] == 1}
    for row in rows:
        base = one[row["elements"]]
        row["parallel_efficiency"] = base["stepping_s"] / base["steps"] / (
            row["ranks"] * row["stepping_s"] / row["steps"])
    small, large = min(one), max(one)
    marginal = (one[large]["peak_memory_all_ranks_MiB"] - one[small]["peak_memory_all_ranks_MiB"]
                ) * 2**20 / (large - small)
    for row in rows:
        row["marginal_bytes_per_element_1_rank"] = marginal
    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/explicit_benchmark.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("\n| elements | ranks | steps | stepping (s) | wall us / element-step | "
          "core us / element-step | efficiency | peak memory, all ranks (MiB) | bytes / element |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['elements']:,} | {r['ranks']} | {r['steps']} | {r['stepping_s']:.2f} | "
              f"{r['wall_us_per_element_step']:.3f} | {r['core_us_per_element_step']:.3f} | "
              f"{r['parallel_efficiency']:.0%} | {r['peak_memory_all_ranks_MiB']:.0f} | "
              f"{r['bytes_per_element_all_ranks']:.0f} |")
    print(f"\nmarginal memory per element (1 rank, {small:,} -> {large:,}): {marginal:.0f} bytes")


if __name__ == "__main__":
    main()
