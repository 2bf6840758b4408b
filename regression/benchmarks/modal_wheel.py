#!/usr/bin/python3
"""Benchmark: every mode below 10 kHz of the railway wheel at ~1e5 DOFs, railfe on 1 and 2 ranks
against SciPy's eigsh (ARPACK Lanczos with shift-invert through SuperLU) on the same K and M.

railfe exports its constrained K and M as Matrix Market (Export matrices = true); SciPy then
solves K x = lambda M x for the same number of modes with the same shift. Reported: wall time of
each, the number of modes, and the largest relative frequency difference between the two sets.
Targets (issue 3): railfe <= 30 s on one core and >= 3x faster than eigsh.

Writes docs/data/modal_wheel_benchmark.csv. Run on an idle machine from the repository root after
building:
  /usr/bin/python3 regression/benchmarks/modal_wheel.py [--railfe build/bin/railfe]
      [--element-size 0.02] [--max-hz 10000]
"""
import argparse
import csv
import json
import math
import os
import sys
import time

import numpy as np
import scipy.io
import scipy.sparse.linalg as sla

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import csv_rows, run_deck, step_section, wheel_modal_deck  # noqa: E402

SHIFT_HZ = -1.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default="build/bin/railfe")
    parser.add_argument("--element-size", type=float, default=0.02)
    parser.add_argument("--max-hz", type=float, default=10000.0)
    parser.add_argument("--modes", type=int, default=64,
                        help="modes per Krylov-Schur batch (the band is covered batch by batch)")
    parser.add_argument("--work", default="build/benchmarks/modal_wheel")
    parser.add_argument("--rerun-scipy", action="store_true",
                        help="time eigsh again instead of reusing its last result")
    args = parser.parse_args()
    rows = []
    railfe_frequencies = None
    for ranks in (1, 2):
        print(f"railfe, {ranks} rank(s)", flush=True)
        results, summary = run_deck(args.railfe,
                                    wheel_modal_deck(args.element_size, args.modes,
                                                     (0, args.max_hz), 8, ranks == 1),
                                    args.work, f"wheel_np{ranks}", ranks)
        step = step_section(summary, "wheel")
        # The run's own wall time, less writing files (the Matrix Market export alone takes
        # longer than the solve and is not part of the comparison).
        wall = summary["Wall time"]["total [s]"] - step["time: output [s]"]
        modes = csv_rows(os.path.join(results, "wheel_modes.csv"))
        frequencies = np.array([float(m["frequency_hz"]) for m in modes])
        if ranks == 1:
            railfe_frequencies = frequencies
            matrices = results
        rows.append({"program": "railfe", "ranks": ranks, "dofs": int(step["degrees of freedom"]),
                     "modes": len(modes), "wall_s": round(wall, 2),
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
    rows.append({"program": "scipy eigsh", "ranks": 1, "dofs": rows[0]["dofs"],
                 "modes": len(reference), "wall_s": round(wall, 2),
                 "factor_s": round(factor_seconds, 2), "iterate_s": round(wall - factor_seconds, 2),
                 "max_rel_difference": f"{difference:.2e}"})
    print(rows[-1], flush=True)
    print(f"speed-up railfe (1 rank) over eigsh: {rows[2]['wall_s'] / rows[0]['wall_s']:.1f}x")
    os.makedirs("docs/data", exist_ok=True)
    with open("docs/data/modal_wheel_benchmark.csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
