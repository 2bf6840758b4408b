#!/usr/bin/python3
"""Benchmark: every mode below 10 kHz of the railway wheel at ~1e5 DOFs, railfe on 1 and 2 ranks
against SciPy's eigsh (ARPACK Lanczos with shift-invert through SuperLU) on the same K and M.

railfe exports its constrained K and M as Matrix Market (Export matrices = true); SciPy then
solves K x = lambda M x for the same number of modes with the same shift. Reported: wall time of
each, the number of modes, and the largest relative frequency difference between the two sets.
Targets (issue 3): railfe <= 30 s on one core and >= 3x faster than eigsh.

The railfe runs use the deck's defaults for the band search (Modes and Block size automatic:
batch and block sizes chosen from the band and the model), as a user's deck would; --modes and
--block-size set them by hand, and --tuned adds a one-rank run with the hand-tuned configuration
of issue 3 (Modes 140, Block size 8) for comparison.

Writes docs/data/modal_wheel_benchmark.csv. Run on an idle machine from the repository root after
building:
  /usr/bin/python3 regression/benchmarks/modal_wheel.py [--railfe build/bin/railfe]
      [--element-size 0.02] [--max-hz 10000] [--tuned] [--ranks 1 2]
"""
import argparse
import csv
import json
import math
import os
import re
import sys
import time

import numpy as np
import scipy.io
import scipy.sparse.linalg as sla

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import csv_rows, run_deck, step_section, wheel_modal_deck  # noqa: E402

SHIFT_HZ = -1.0
TUNED = (140, 8)  # Modes, Block size: the hand-tuned configuration of issue 3


def benchmark_deck(element_size, modes, block_size, band, export):
    """The wheel deck with Modes and Block size left to their defaults where they are None."""
    deck = wheel_modal_deck(element_size, modes or 1, band, block_size or 1, export)
    if modes is None:
        deck = re.sub(r'\s*<Parameter name="Modes"[^>]*/>', "", deck)
    if block_size is None:
        deck = re.sub(r'\s*<Parameter name="Block size"[^>]*/>', "", deck)
    return deck


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--element-size", type=float, default=0.02)
    parser.add_argument("--max-hz", type=float, default=10000.0)
    parser.add_argument("--modes", type=int, default=None,
                        help="first Krylov-Schur batch (default: the deck's automatic choice)")
    parser.add_argument("--block-size", type=int, default=None,
                        help="Krylov block size (default: the deck's automatic choice)")
    parser.add_argument("--tuned", action="store_true",
                        help=f"also run one rank with Modes {TUNED[0]}, Block size {TUNED[1]}")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--work", default="build/benchmarks/modal_wheel")
    parser.add_argument("--rerun-scipy", action="store_true",
                        help="time eigsh again instead of reusing its last result")
    args = parser.parse_args()
    rows = []
    railfe_frequencies = None
    runs = [(ranks, args.modes, args.block_size, "defaults" if args.modes is None and
             args.block_size is None else "by hand") for ranks in args.ranks]
    if args.tuned:
        runs.append((1, TUNED[0], TUNED[1], "tuned (issue 3)"))
    for ranks, modes, block_size, configuration in runs:
        print(f"railfe, {ranks} rank(s), {configuration}", flush=True)
        export = railfe_frequencies is None
        name = f"wheel_np{ranks}" + ("_tuned" if configuration.startswith("tuned") else "")
        results, summary = run_deck(args.railfe,
                                    benchmark_deck(args.element_size, modes, block_size,
                                                   (0, args.max_hz), export),
                                    args.work, name, ranks)
        step = step_section(summary, "wheel")
        # The run's own wall time, less writing files (the Matrix Market export alone takes
        # longer than the solve and is not part of the comparison).
        wall = summary["Wall time"]["total [s]"] - step["time: output [s]"]
        modes_found = csv_rows(os.path.join(results, "wheel_modes.csv"))
        frequencies = np.array([float(m["frequency_hz"]) for m in modes_found])
        if export:
            railfe_frequencies = frequencies
            matrices = results
        rows.append({"program": "railfe", "configuration": configuration, "ranks": ranks,
                     "dofs": int(step["degrees of freedom"]), "modes": len(modes_found),
                     "batches": int(step["eigensolver batches"]),
                     "block_size": step["block size"],
                     "operator_applications": int(step["operator applications"]),
                     "wall_s": round(wall, 2),
                     "factor_s": round(step["time: factorization [s]"], 2),
                     "iterate_s": round(step["time: eigensolver iterations [s]"], 2),
                     "max_rel_difference": ""})
        print(rows[-1], flush=True)

    cache = os.path.join(args.work, "scipy_eigsh.json")
    if os.path.exists(cache) and not args.rerun_scipy:
        print(f"scipy eigsh: reusing {cache} (--rerun-scipy to time it again)", flush=True)
        with open(cache) as handle:
            saved = json.load(handle)
        wall, factor_seconds, reference = saved["wall_s"], saved["factor_s"], np.array(
            saved["frequencies_hz"])
    else:
        print("scipy eigsh (ARPACK + SuperLU shift-invert)", flush=True)
        K = scipy.io.mmread(os.path.join(matrices, "wheel_K.mtx")).tocsc()
        M = scipy.io.mmread(os.path.join(matrices, "wheel_M.mtx")).tocsc()
        sigma = -(2 * math.pi * SHIFT_HZ) ** 2
        start = time.perf_counter()
        factor = sla.splu(K - sigma * M)
        factor_seconds = time.perf_counter() - start
        op = sla.LinearOperator(K.shape, matvec=factor.solve, dtype=float)
        values = sla.eigsh(K, k=len(railfe_frequencies), M=M, sigma=sigma, which="LM",
                           OPinv=op, tol=1e-10, return_eigenvectors=False)
        wall = time.perf_counter() - start
        reference = np.sort(np.sqrt(np.abs(values)) / (2 * math.pi))
        with open(cache, "w") as handle:
            json.dump({"wall_s": wall, "factor_s": factor_seconds,
                       "frequencies_hz": reference.tolist()}, handle)
    elastic = railfe_frequencies > 1.0
    if len(reference) == len(railfe_frequencies):
        difference = np.max(np.abs(railfe_frequencies[elastic] - reference[elastic]) /
                            reference[elastic])
    else:
        difference = float("nan")
    rows.append({"program": "scipy eigsh", "configuration": "shift-invert, same shift",
                 "ranks": 1, "dofs": rows[0]["dofs"], "modes": len(reference), "batches": 1,
                 "block_size": 1, "operator_applications": "", "wall_s": round(wall, 2),
                 "factor_s": round(factor_seconds, 2), "iterate_s": round(wall - factor_seconds, 2),
                 "max_rel_difference": f"{difference:.2e}"})
    print(rows[-1], flush=True)
    for row in rows[:-1]:
        print(f"eigsh / railfe ({row['configuration']}, {row['ranks']} rank(s)): "
              f"{wall / row['wall_s']:.1f}x")
    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/modal_wheel_benchmark.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
