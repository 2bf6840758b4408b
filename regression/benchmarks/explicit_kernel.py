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
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import (box_mesh_xml, output_xml, run_deck, steel_materials_xml,  # noqa: E402
                         step_section)


def deck(n, steps):
    """A free spinning cube of n^3 elements run for about `steps` automatic steps."""
    stable = (1.0 / n) / 6001.4
    end_time = 0.9 * stable * steps
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
      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1000000"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--sizes", type=int, nargs="+", default=[46, 100])
    parser.add_argument("--steps", type=int, nargs="+", default=[400, 60])
    parser.add_argument("--work", default="build/benchmarks/explicit_kernel")
    args = parser.parse_args()
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
