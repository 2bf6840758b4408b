#!/usr/bin/env python3
"""Benchmark of a squeal scene run (issue 16): the full-scale case 1 to 19 ms on two cores, or the
demo, from the summary.json of its results directory. A run that went in pieces (checkpoint and
restart) gives one directory per piece, in order: the stepping times and steps are summed, and
the setup (modes, preload) counted once, as the run needs it once.

Appends a row to docs/data/squeal_full_scale_benchmark.csv (or --csv) with: deck, ranks, pieces,
elements, nodes, the stable step and the contact's critical step, steps, the mean step, wall
time of the modal and static steps and of the rolling, time per element-step (wall x ranks), the
contact's share and the peak memory; prints it as a table row for the notes.

    /usr/bin/python3 regression/benchmarks/squeal_full_scale.py RESULTS [RESULTS ...] \\
        --deck inputs/scenes/squeal_case1.xml [--end-time 0.019] [--note "machine shared ..."]
"""
import argparse
import csv
import json
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CSV = os.path.join(ROOT, "docs", "data", "squeal_full_scale_benchmark.csv")
COLUMNS = ["deck", "ranks", "pieces", "elements", "nodes", "stable_step_s", "contact_step_s",
           "steps", "mean_step_s", "end_time_s", "modes_wall_s", "preload_wall_s",
           "roll_wall_s", "roll_cpu_rank0_s", "us_per_element_step", "contact_share",
           "energy_error", "peak_memory_per_rank_MiB", "note"]


def section(summary, prefix):
    """The summary section whose name starts with `prefix` (e.g. 'Step roll')."""
    return next((value for key, value in summary.items() if key.startswith(prefix)), {})


def row(directories, deck, end_time, note):
    pieces = [json.load(open(os.path.join(d, "summary.json"))) for d in directories]
    first, last = pieces[0], pieces[-1]
    roll = [section(p, "Step roll") for p in pieces]
    steps = sum(r["steps"] for r in roll)
    wall = sum(p["Wall time"].get("step roll [s]", 0) for p in pieces)
    cpu = sum(r["time: stepping, CPU of rank 0 [s]"] for r in roll)
    stepping = sum(r["time: stepping [s]"] for r in roll)
    elements = last["Model"]["elements"]
    contact = sum(r.get("time: contact (exchange, search, forces) [s]", 0) for r in roll)
    ranks = last["Run"]["MPI ranks"]
    return {
        "deck": deck, "ranks": ranks, "pieces": len(pieces), "elements": elements,
        "nodes": last["Model"]["nodes"],
        "stable_step_s": roll[0]["stable step at start [s]"],
        "contact_step_s": roll[0].get("contact critical step [s]", ""),
        "steps": steps, "mean_step_s": end_time / steps, "end_time_s": end_time,
        "modes_wall_s": first["Wall time"].get("step modes [s]", 0),
        "preload_wall_s": first["Wall time"].get("step preload [s]", 0),
        "roll_wall_s": wall, "roll_cpu_rank0_s": cpu,
        "us_per_element_step": 1e6 * stepping * ranks / (steps * elements),
        "contact_share": contact / stepping if stepping else "",
        "energy_error": roll[-1].get("energy error at end", ""),
        "peak_memory_per_rank_MiB": max(r.get("peak memory per rank [MiB]", 0) for r in roll),
        "note": note}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", nargs="+", help="results directories, one per piece, in order")
    parser.add_argument("--deck", required=True)
    parser.add_argument("--end-time", type=float, default=0.019, help="the roll's End time (s)")
    parser.add_argument("--note", default="")
    parser.add_argument("--csv", default=CSV)
    args = parser.parse_args()
    r = row(args.results, args.deck, args.end_time, args.note)
    new = not os.path.exists(args.csv)
    with open(args.csv, "a", newline="") as out:
        writer = csv.DictWriter(out, COLUMNS)
        if new:
            writer.writeheader()
        writer.writerow(r)
    print("| " + " | ".join(str(r[c]) for c in COLUMNS) + " |")


if __name__ == "__main__":
    main()
