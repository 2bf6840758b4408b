#!/usr/bin/env python3
"""Test of rim_vibration.py on a synthetic rolling wheel: a rim node whose elastic vibration,
in the wheel's turning frame, is a sum of sines at known frequencies per component (lateral,
radial, circumferential) plus white noise, carried by the rigid rolling motion (centre moving
along x and bobbing, spin varying around V / R). The chart must find every frequency within
the Welch frequency resolution in the right component, match each to the nearest mode of
a modes CSV, and its Morlet transform must peak at a sine's frequency; the damped-sine fit
(--poles) must find each within 1 Hz in its own component.

    /usr/bin/python3 regression/charts/rim_vibration_test.py WORK_DIR
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rim_vibration  # noqa: E402

SINES = {"lateral": [(163.0, 2e-6), (1921.0, 1e-6)], "radial": [(1172.0, 1e-6)],
         "circumferential": [(560.0, 1.5e-6)]}
MODES = [(1, 0.0, "rigid-body", 0, 0), (7, 183.0, "axial", 0, 0), (9, 560.5, "radial", 0, 2),
         (12, 1075.0, "axial", 0, 3), (15, 1180.0, "radial", 0, 3), (18, 1934.0, "axial", 0, 4)]
CENTRE, RIM = np.array([0.5, 0.0, 0.46]), np.array([0.5, 0.07, 0.91])


def motion(t):
    """Rim and centre positions, the spin, and the rim's elastic displacement at times t."""
    speed, radius = 27.78, 0.46
    spin = speed / radius * (1 + 0.05 * np.sin(2 * np.pi * 7 * t))
    theta = np.concatenate(([0], np.cumsum(0.5 * (spin[1:] + spin[:-1]) * np.diff(t))))
    centre = np.stack([CENTRE[0] + speed * t, 1e-4 * np.sin(2 * np.pi * 3 * t),
                       CENTRE[2] + 2e-5 * np.sin(2 * np.pi * 5 * t)], 1)
    d0 = RIM - CENTRE
    c, s = np.cos(theta), np.sin(theta)
    d = np.stack([c * d0[0] + s * d0[2], np.full_like(t, d0[1]), -s * d0[0] + c * d0[2]], 1)
    radial = d * [1, 0, 1] / np.hypot(d[:, 0], d[:, 2])[:, None]
    directions = {"lateral": np.array([0.0, 1.0, 0.0]), "radial": radial,
                  "circumferential": np.cross([0.0, 1.0, 0.0], radial)}
    elastic = np.zeros_like(d)
    for name, sines in SINES.items():
        amplitude = sum(a * np.sin(2 * np.pi * f * t + f) for f, a in sines)
        elastic += amplitude[:, None] * directions[name]
    return centre + d + elastic, centre, spin, elastic


def write_inputs(work, quantity):
    """A histories CSV of quantity (derivatives by finite differences on a 4x finer grid,
    white noise of a tenth of the vibration's rms added) and a modes CSV; returns their paths."""
    fine = np.arange(0, 0.2, 2.5e-6)
    rim, centre, spin, elastic = motion(fine)
    if quantity == "displacement":
        rim, centre = rim - RIM, centre - CENTRE
    for _ in range(["displacement", "velocity", "acceleration"].index(quantity)):
        rim, centre = np.gradient(rim, fine, axis=0), np.gradient(centre, fine, axis=0)
        elastic = np.gradient(elastic, fine, axis=0)
    rng = np.random.default_rng(16)
    rim += 0.1 * np.sqrt(np.mean(elastic**2)) * rng.standard_normal(rim.shape)
    step = slice(None, None, 4)
    unit = rim_vibration.UNITS[quantity]
    histories = os.path.join(work, f"{quantity}_histories.csv")
    with open(histories, "w", newline="") as handle:
        out = csv.writer(handle)
        # Both namings: one history "rim" per node set, or "axle x", "axle y", ... per component.
        out.writerow(["time_s"] + [f"rim_{quantity}_{c}_{unit}" for c in "xyz"] +
                     [f"axle {c}_{quantity}_{c}_{unit}" for c in "xyz"] +
                     ["axle spin_angular_velocity_y_rad_per_s"])
        for row in zip(fine[step], *rim[step].T, *centre[step].T, spin[step]):
            out.writerow([f"{v:.17g}" for v in row])
    modes = os.path.join(work, "modes.csv")
    with open(modes, "w", newline="") as handle:
        out = csv.writer(handle)
        out.writerow(["mode", "frequency_hz", "family", "nodal_circles", "nodal_diameters"])
        out.writerows(MODES)
    return histories, modes


def separation(spectra, quantity):
    """Each sine's own component holds at least 100 times the PSD the others hold at its
    frequency: the turning frame is followed (a wrong one mixes radial and circumferential)."""
    failures = []
    for name, sines in SINES.items():
        for f, _ in sines:
            own = spectra[name][1][np.argmin(abs(spectra[name][0] - f))]
            for other in SINES:
                if other != name:
                    leak = spectra[other][1][np.argmin(abs(spectra[other][0] - f))] / own
                    print(f"{quantity:12s} {f:7.1f} Hz {name} sine seen in {other}: {leak:.1e}")
                    if leak > 1e-2:
                        failures.append(f"{quantity} {name} {f} Hz: {leak:.2g} of it in {other}")
    return failures


def check(rows, resolution, quantity):
    """Every sine found within the resolution in its own component and strongest there; from
    displacements nothing else is found (accelerations in the turning frame carry Coriolis
    terms 2 Omega / omega of another component's vibration, a few % at these frequencies)."""
    failures = []
    for name, sines in SINES.items():
        found = [float(r[1]) for r in rows if r[0] == name]
        for f, _ in sines:
            error = min(abs(p - f) for p in found)
            print(f"{quantity:12s} {name:15s} {f:7.1f} Hz: peak at {error:.2f} Hz from it "
                  f"(resolution {resolution:.2f} Hz)")
            if error > resolution:
                failures.append(f"{quantity} {name} {f} Hz: nearest peak {error:.2f} Hz off")
        if quantity == "displacement" and len(found) != len(sines):
            failures.append(f"{quantity} {name}: peaks {found}, expected only {sines}")
        strongest = max((r for r in rows if r[0] == name), key=lambda r: float(r[2]))
        if min(abs(float(strongest[1]) - f) for f, _ in sines) > resolution:
            failures.append(f"{quantity} {name}: strongest peak {strongest[1]} Hz is another "
                            "component's sine")
    for row in rows:
        mode = min(MODES[1:], key=lambda m: abs(m[1] - float(row[1])))
        if row[3] != str(mode[0]) or abs(float(row[8]) / (100 * (float(row[1]) / mode[1] - 1)) - 1) > 1e-3:
            failures.append(f"peak {row[1]} Hz matched to mode {row[3]}, not {mode[0]}")
    return failures


def check_poles(path):
    """Every sine found by the damped-sine fit within 1 Hz in its own component, as the nearest
    mode's neighbour: the fit sees the same turning-frame components as the PSD."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    failures = []
    for name, sines in SINES.items():
        found = [float(r["frequency_hz"]) for r in rows if r["component"] == name]
        for f, _ in sines:
            error = min((abs(p - f) for p in found), default=float("inf"))
            print(f"poles        {name:15s} {f:7.1f} Hz: fitted at {error:.3f} Hz from it")
            if error > 1:
                failures.append(f"poles: {name} {f} Hz: nearest fitted sine {error:.2f} Hz off")
    return failures


def main(work):
    os.makedirs(work, exist_ok=True)
    failures = []
    for quantity in ("displacement", "acceleration"):
        histories, modes = write_inputs(work, quantity)
        args = [histories, modes, os.path.join(work, quantity), "--history", "rim",
                "--quantity", quantity, "--rim", *map(str, RIM), "--centre", *map(str, CENTRE),
                "--centre-history", "axle", "--spin-history", "axle spin", "--segments", "8",
                "--peaks", "3", "--max-hz", "2500"]
        if quantity == "displacement":
            args += ["--poles", "24"]
        rows, spectra = rim_vibration.main(args)
        resolution = 1 / (0.2 * 2 / 9)  # Welch segment length: 2 T / (segments + 1)
        failures += check(rows, resolution, quantity)
        if quantity == "displacement":
            failures += separation(spectra, quantity)
            failures += check_poles(os.path.join(work, quantity + "_poles.csv"))
    t = np.arange(0, 0.05, 1e-5)
    frequencies = np.linspace(100, 2000, 96)
    power = rim_vibration.morlet_power(np.sin(2 * np.pi * 700 * t), 1e-5, frequencies)
    f_peak = frequencies[np.argmax(power[:, len(t) // 2])]
    print(f"Morlet power of a 700 Hz sine peaks at {f_peak:.1f} Hz (grid 20 Hz)")
    if abs(f_peak - 700) > 20:
        failures.append(f"Morlet power peaks at {f_peak} Hz for a 700 Hz sine")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "rim_vibration_test"))
