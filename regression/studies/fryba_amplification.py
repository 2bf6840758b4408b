#!/usr/bin/env python3
"""Frýba's moving force from a deck (inputs/verification/implicit_fryba_moving_force): the
dynamic amplification of the midspan deflection against the speed parameter alpha = c/(2 f1 L),
railfe's implicit module (Moving loads, HHT alpha = 0) against Frýba's closed-form series
(regression/references/fryba_moving_force.py), and the error of the peak against the wall time of
the time loop for several element counts and time steps. Writes docs/data/fryba_amplification.csv
and docs/img/fryba_amplification.png.
Usage: fryba_amplification.py [build/bin/railfe] [--work DIR] [--replot]"""
import importlib.util
import math
import os
import re
import sys
from concurrent.futures import ThreadPoolExecutor

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.dirname(__file__))
from railfe_runs import csv_rows, run_deck, step_section, study_parser, typed_rows, write_rows  # noqa: E402

spec = importlib.util.spec_from_file_location(
    "fryba", os.path.join(ROOT, "regression/references/fryba_moving_force.py"))
fryba = importlib.util.module_from_spec(spec)
spec.loader.exec_module(fryba)

DECK = os.path.join(ROOT, "inputs/verification/implicit_fryba_moving_force/deck.xml")
CSV = os.path.join(ROOT, "docs/data/fryba_amplification.csv")
PNG = os.path.join(ROOT, "docs/img/fryba_amplification.png")
L, EI, MU, P = 25.0, 8.323e9, 2303.0, 1e5
F1 = math.pi / (2 * L * L) * math.sqrt(EI / MU)
STATIC = P * L ** 3 / (48 * EI)
ALPHAS = [0.1, 0.2, 0.3, 0.4, 0.5, 0.62, 0.7, 0.8, 1.2, 1.5]
MESHES = [(4, 5e-3), (10, 2e-3), (10, 0.5e-3), (20, 0.5e-3), (40, 0.25e-3)]  # (elements/half, dt)


def deck_text(alpha, half_elements, dt):
    speed = alpha * 2 * F1 * L
    text = open(DECK).read()
    text = re.sub(r'(name="Speed" type="double" value=")[^"]*', rf"\g<1>{speed!r}", text)
    text = re.sub(r'(name="End time" type="double" value=")[^"]*', rf"\g<1>{2 * L / speed!r}",
                  text)
    text = re.sub(r'(name="Time step" type="double" value=")[^"]*', rf"\g<1>{dt!r}", text)
    return re.sub(r'(name="Elements" type="Array\(int\)" value=")[^"]*',
                  rf"\g<1>{{{half_elements}}}", text)


def run_case(railfe, work, alpha, half_elements, dt):
    name = f"a{alpha}_n{half_elements}_dt{dt}"
    results, summary = run_deck(railfe, deck_text(alpha, half_elements, dt), work, name)
    peak = float(csv_rows(os.path.join(results, "cross_measurements.csv"))[0]["peak_abs"])
    reference = fryba.amplification(alpha) if alpha != 1.0 else float("nan")
    section = step_section(summary, "cross")
    return {"alpha": alpha, "elements": 2 * half_elements, "dt_s": dt,
            "daf_railfe": peak / STATIC, "daf_fryba": reference,
            "daf_fryba_first_mode": fryba.amplification(alpha, modes=1),
            "peak_error_percent": 100 * (peak / STATIC / reference - 1),
            "stepping_wall_s": section["time: stepping [s]"]}


def plot(rows):
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    fine = [r for r in rows if r["elements"] == 20 and r["dt_s"] == 0.5e-3]
    alphas = [a / 100 for a in range(5, 201)]
    left.plot(alphas, [fryba.amplification(a, points=4001) if abs(a - 1) > 1e-9 else math.nan
                       for a in alphas], "k-", label="Frýba series (25 odd modes)")
    left.plot(alphas, [fryba.amplification(a, modes=1, points=4001) if abs(a - 1) > 1e-9
                       else math.nan for a in alphas], "k:", label="Frýba, first mode")
    left.plot([r["alpha"] for r in fine], [r["daf_railfe"] for r in fine], "o", color="C3",
              label="railfe, 20 beams, dt 0.5 ms")
    left.set_xlabel("speed parameter alpha = c / (2 f1 L)")
    left.set_ylabel("dynamic amplification of midspan deflection")
    left.legend(loc="lower right")
    left.grid(alpha=0.3)
    for (half, dt), marker in zip(MESHES, "sv^oD"):
        subset = [r for r in rows if r["elements"] == 2 * half and r["dt_s"] == dt]
        right.loglog([r["stepping_wall_s"] for r in subset],
                     [max(abs(r["peak_error_percent"]), 1e-4) for r in subset], marker,
                     label=f"{2 * half} beams, dt {dt * 1e3:g} ms")
    right.axhline(1, color="k", lw=0.8, ls="--")
    right.set_xlabel("wall time of the time loop (s, one rank, shared 2-core machine)")
    right.set_ylabel("|error of the peak| against Frýba (%)")
    right.legend(fontsize=8)
    right.grid(alpha=0.3, which="both")
    fig.suptitle("Moving force on a simply supported beam: railfe implicit against Frýba")
    fig.tight_layout()
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=110)


def main():
    args = study_parser(__doc__, "/tmp/railfe_fryba", ROOT).parse_args()
    if not args.replot:
        cases = [(a, half, dt) for a in ALPHAS for half, dt in MESHES]
        with ThreadPoolExecutor(args.jobs) as pool:
            rows = list(pool.map(lambda c: run_case(args.railfe, args.work, *c), cases))
        write_rows(CSV, rows)
    rows = typed_rows(CSV, [])
    plot(rows)
    worst = max(abs(r["peak_error_percent"]) for r in rows
                if r["elements"] == 20 and r["dt_s"] == 0.5e-3)
    print(f"largest |peak error| at 20 beams, dt 0.5 ms: {worst:.3f} %")


if __name__ == "__main__":
    main()
