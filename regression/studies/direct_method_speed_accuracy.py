#!/usr/bin/env python3
"""Speed against accuracy of the direct method on the sprung mass crossing a simply supported
beam (Yang & Yau 1997; physics/tests/moving_sprung_mass.py): error in the peak midspan deflection
and in the peak body acceleration against the SciPy modal solution (30 modes, evaluated every
10 us), against the wall time of the time loop, for several time steps, element counts and HHT
alpha. Writes docs/data/direct_method_speed_accuracy.csv and docs/img/direct_method_speed_accuracy.png.
Usage: direct_method_speed_accuracy.py [--exe build/bin/railfe-moving-study]"""
import argparse
import csv
import importlib.util
import os
import subprocess
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
spec = importlib.util.spec_from_file_location(
    "sprung", os.path.join(ROOT, "physics/tests/moving_sprung_mass.py"))
sprung = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sprung)


def run(exe, out, **settings):
    args = [exe, f"csv={out}"] + [f"{k}={v}" for k, v in settings.items()]
    text = subprocess.run(["nice"] + args, check=True, capture_output=True, text=True).stdout
    summary = dict(line.split("=", 1) for line in text.splitlines() if "=" in line)
    return sprung.read(out), float(summary["wall_s"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default=os.path.join(ROOT, "build/bin/railfe-moving-study"))
    parser.add_argument("--repeat", type=int, default=3)
    a = parser.parse_args()
    crossing = sprung.L / sprung.V
    fine = np.linspace(0, crossing, int(crossing / 1e-5) + 1)
    ref_deflection, ref_acceleration = sprung.modal_solution(fine)
    peak_d, peak_a = np.max(np.abs(ref_deflection)), np.max(np.abs(ref_acceleration))
    print(f"modal reference: peak deflection {peak_d:.6e} m, peak acceleration {peak_a:.6e} m/s2")
    rows = []
    cases = [(dt, e, al) for al in (0.0, -0.1, -0.3) for e in (10, 20, 40)
             for dt in (4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4)]
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "run.csv")
        for dt, elements, alpha in cases:
            best = None
            for _ in range(a.repeat):
                fe, wall = run(a.exe, out, dt=dt, elements=elements, alpha=alpha)
                best = wall if best is None else min(best, wall)
            row = {"dt": dt, "elements": elements, "alpha": alpha, "wall_s": best,
                   "peak_deflection": np.max(np.abs(fe["midspan_deflection"])),
                   "peak_acceleration": np.max(np.abs(fe["vehicle_acceleration"]))}
            row["deflection_error"] = abs(row["peak_deflection"] - peak_d) / peak_d
            row["acceleration_error"] = abs(row["peak_acceleration"] - peak_a) / peak_a
            rows.append(row)
            print({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in row.items()},
                  flush=True)
    path = os.path.join(ROOT, "docs/data/direct_method_speed_accuracy.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharex=True)
    markers = {10: "s", 20: "o", 40: "^"}
    colors = {0.0: "tab:blue", -0.1: "tab:orange", -0.3: "tab:red"}
    for ax, key, title in ((axes[0], "deflection_error", "peak midspan deflection"),
                           (axes[1], "acceleration_error", "peak body acceleration")):
        for alpha in colors:
            for elements in markers:
                sel = [r for r in rows if r["alpha"] == alpha and r["elements"] == elements]
                ax.loglog([r["wall_s"] for r in sel], [max(r[key], 1e-7) for r in sel],
                          marker=markers[elements], color=colors[alpha], lw=1,
                          label=f"alpha {alpha:g}, {elements} elements")
        ax.axhline(0.01, color="k", ls=":", lw=1)
        ax.set_xlabel("wall time of the time loop (s)")
        ax.set_ylabel("relative error against the modal solution")
        ax.set_title(f"{title} (dt 4 ms ... 0.25 ms along each line)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Direct method, sprung mass on a 25 m beam at 100 km/h: error against cost")
    fig.tight_layout()
    png = os.path.join(ROOT, "docs/img/direct_method_speed_accuracy.png")
    fig.savefig(png, dpi=110)
    print("wrote", path, "and", png)


if __name__ == "__main__":
    main()
