#!/usr/bin/env python3
"""Sprung mass crossing a simply supported beam (Yang & Yau 1997; Biggs 1964): the direct method
(railfe-moving-study, moving constraint + HHT-alpha) against a semi-analytic modal solution of the
published equations, integrated here with SciPy's solve_ivp on the first N modes.

Beam: L = 25 m, E = 2.87 GPa, I = 2.9 m^4, m = 2303 kg/m; vehicle 5750 kg on 1595 kN/m at
100 km/h, starting at the left support with the beam at rest and the spring at its static
preload. With q_n the modal amplitudes (phi_n = sin(n pi x / L)):
    q_n'' + w_n^2 q_n = 2 / (m L) phi_n(v t) F,   F = -M g + k (z - u(v t)),
    z'' = -k (z - u(v t)) / M,
z the body's displacement from its static position, u the deflection (up positive).
Usage: moving_sprung_mass.py STUDY_EXE WORK_DIR [key=value ...]
       moving_sprung_mass.py --histories CSV   (a railfe deck's <step>_histories.csv with the
                                                columns time_s, midspan_m and body_m/s2)
Exits 1 when the midspan deflection or the body acceleration (peaks and whole histories,
normalised by the peak) differ from the modal solution by more than 1 %.
"""
import csv
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

L, E, I, MBAR = 25.0, 2.87e9, 2.9, 2303.0
MV, K, V, G = 5750.0, 1595e3, 100 / 3.6, 9.81
TOLERANCE = 0.01


def modal_solution(times, n_modes=30):
    n = np.arange(1, n_modes + 1)
    omega = (n * np.pi / L) ** 2 * np.sqrt(E * I / MBAR)

    def rhs(t, y):
        q, qd, z, zd = y[:n_modes], y[n_modes:2 * n_modes], y[-2], y[-1]
        phi = np.sin(n * np.pi * V * t / L)
        u = phi @ q
        force = -MV * G + K * (z - u)
        qdd = -omega**2 * q + 2 / (MBAR * L) * phi * force
        zdd = -K * (z - u) / MV
        return np.concatenate([qd, qdd, [zd, zdd]])

    y0 = np.zeros(2 * n_modes + 2)
    sol = solve_ivp(rhs, (0, times[-1]), y0, method="DOP853", t_eval=times, rtol=1e-11,
                    atol=1e-15, max_step=1e-3)
    q, z = sol.y[:n_modes], sol.y[-2]
    midspan = np.sin(n * np.pi / 2) @ q
    u_contact = np.array([np.sin(n * np.pi * V * t / L) @ q[:, i] for i, t in enumerate(times)])
    acceleration = -K * (z - u_contact) / MV
    return midspan, acceleration


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([float(r[key]) for r in rows]) for key in rows[0]}


def main():
    if sys.argv[1] == "--histories":
        deck = read(sys.argv[2])
        time, deflection, body = deck["time_s"], deck["midspan_m"], deck["body_m/s2"]
    else:
        exe, work = sys.argv[1], sys.argv[2]
        os.makedirs(work, exist_ok=True)
        out = os.path.join(work, "sprung_mass.csv")
        args = ["elements=20", "dt=0.0005", "alpha=0", "csv=" + out] + sys.argv[3:]
        subprocess.run([exe] + args, check=True, stdout=subprocess.DEVNULL)
        fe = read(out)
        time, deflection, body = (fe["time"], fe["midspan_deflection"],
                                  fe["vehicle_acceleration"])
    midspan, acceleration = modal_solution(time)
    failed = False
    for name, computed, reference in (("midspan deflection", deflection, midspan),
                                      ("body acceleration", body, acceleration)):
        peak_ref = np.max(np.abs(reference))
        peak_error = abs(np.max(np.abs(computed)) - peak_ref) / peak_ref
        history_error = np.max(np.abs(computed - reference)) / peak_ref
        ok = peak_error <= TOLERANCE and history_error <= TOLERANCE
        failed |= not ok
        print(f"{name}: peak {np.max(np.abs(computed)):.6e} vs modal {peak_ref:.6e}: "
              f"peak error {100 * peak_error:.3f} %, history error {100 * history_error:.3f} % "
              f"of the peak (limit {100 * TOLERANCE:.0f} %) {'ok' if ok else 'FAILED'}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
