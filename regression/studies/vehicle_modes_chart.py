#!/usr/bin/python3
"""Study: the vehicle's modes from railfe's modal module against the published test car's (issue
19). Runs inputs/verification/vehicle_modes/deck.xml (the vehicle part, wheelsets held), names
each railfe mode by the shape of the same-frequency mode of the independent dense model in
vehicle_modes_fit.py (kinetic-energy shares), and charts the nine published modes against
railfe's. Writes docs/data/vehicle_modes.csv and docs/img/vehicle_modes.png.

Run from the repository root: /usr/bin/python3 regression/studies/vehicle_modes_chart.py [railfe]
"""
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import vehicle_modes_fit as fit  # noqa: E402


def railfe_modes(railfe):
    deck = os.path.join(ROOT, "inputs", "verification", "vehicle_modes", "deck.xml")
    with tempfile.TemporaryDirectory() as work:
        subprocess.run([railfe, deck, "--output", os.path.join(work, "out")], check=True,
                       stdout=subprocess.DEVNULL)
        rows = list(csv.DictReader(open(os.path.join(work, "out", "modes_modes.csv"))))
    return [float(r["frequency_hz"]) for r in rows]


def main():
    railfe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "railfe")
    frequencies = railfe_modes(railfe)
    p = fit.read_csv()
    model, named = fit.identify(p)
    # railfe's modes in frequency order are the dense model's (same matrices): name them so.
    names = [label for (_, _, _, label) in sorted(named, key=lambda n: n[0])]
    dense = sorted(n[0] for n in named)
    out_csv = os.path.join(ROOT, "docs", "data", "vehicle_modes.csv")
    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mode", "shape", "railfe_hz", "dense_model_hz", "published_hz",
                    "error_percent"])
        for i, (fr, name) in enumerate(zip(frequencies, names)):
            published = ""
            error = ""
            for (label, _, _, value), matched in zip(fit.PUBLISHED, model):
                if abs(matched - dense[i]) < 1e-9 * max(1.0, matched):
                    published, error = value, 100 * (fr - value) / value
            w.writerow([i + 1, name, "%.6f" % fr, "%.6f" % dense[i], published,
                        "" if error == "" else "%.3f" % error])
    rows = list(csv.DictReader(open(out_csv)))
    published_rows = [r for r in rows if r["published_hz"]]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    x = range(len(published_rows))
    ax.bar([i - 0.2 for i in x], [float(r["published_hz"]) for r in published_rows], 0.4,
           label="published test car", color="0.6")
    ax.bar([i + 0.2 for i in x], [float(r["railfe_hz"]) for r in published_rows], 0.4,
           label="railfe modal module (vehicle part, wheelsets held)", color="C0")
    for i, r in zip(x, published_rows):
        ax.text(i + 0.2, float(r["railfe_hz"]) * 1.05, "%+.2f%%" % float(r["error_percent"]),
                ha="center", fontsize=7)
    ax.set_yscale("log")
    ax.set_xticks(list(x))
    ax.set_xticklabels([r["shape"].split(" (")[0] for r in published_rows], rotation=30,
                       ha="right", fontsize=7)
    ax.set_ylabel("frequency (Hz)")
    ax.set_title("Vehicle modes: railfe against the published test car (tolerance 5 %)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "vehicle_modes.png"), dpi=110)
    for r in rows:
        print(r["mode"], r["shape"], r["railfe_hz"], r["published_hz"], r["error_percent"])


if __name__ == "__main__":
    main()
