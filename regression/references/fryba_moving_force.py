#!/usr/bin/env python3
"""Frýba's closed-form series for a constant force P crossing a simply supported Euler–Bernoulli
beam at constant speed c (L. Frýba, Vibration of Solids and Structures under Moving Loads, 1972,
ch. 1): each mode j (shape sin(jπx/L), natural frequency ω_j = j²π²/L² √(EI/μ)) obeys
q̈_j + ω_j² q_j = (2P/μL) sin(jΩt), Ω = πc/L, while the force is on the span (0 ≤ t ≤ L/c), and
vibrates freely after it leaves. Solved exactly per mode from rest:
    q_j(t) = 2PL³/(π⁴EI j⁴) · [sin(jΩt) − (α/j) sin(ω_j t)] / (1 − α²/j²),  α = Ω/ω_1 = c/(2 f_1 L),
then continued as free vibration. The dynamic amplification is max_t w(L/2, t) / (PL³/48EI).

Usage:
  fryba_moving_force.py amplification [--alphas A,B,...]     the DAF curve (first-mode and
                                                            converged series)
  fryba_moving_force.py history --length L --ei EI --mass-per-length MU --force P --speed C
                                [--modes N] [--points N] [--after S]   midspan history as CSV
  fryba_moving_force.py check CSV COLUMN --length ... (as history)  [--tolerance 0.01]
      compares a railfe history column (time_s, deflection in m; --scale -1 when the force acts
      along -z) with the series: the peak within the tolerance and the history within
      tolerance × peak.
"""
import argparse
import math
import sys

import numpy as np


def modal_response(t, j, alpha, omega1, crossing_time):
    """q_j(t) / (2PL³/(π⁴EI)) for mode j (forced phase exact, then free vibration)."""
    omega_j = j * j * omega1
    big_omega = alpha * omega1
    scale = 1.0 / (j ** 4 * (1.0 - alpha ** 2 / j ** 2))

    def forced(tt):
        return scale * (np.sin(j * big_omega * tt) - alpha / j * np.sin(omega_j * tt))

    def forced_rate(tt):
        return scale * (j * big_omega * np.cos(j * big_omega * tt)
                        - alpha / j * omega_j * np.cos(omega_j * tt))

    t = np.asarray(t, dtype=float)
    q = np.where(t <= crossing_time, forced(np.minimum(t, crossing_time)), 0.0)
    q0, v0 = forced(crossing_time), forced_rate(crossing_time)
    after = t - crossing_time
    free = q0 * np.cos(omega_j * after) + v0 / omega_j * np.sin(omega_j * after)
    return np.where(t <= crossing_time, q, free)


def midspan_history(length, ei, mu, force, speed, modes=49, points=4001, after=1.0):
    """Times (s) and midspan deflection (m) from 0 to (1 + after) L/c."""
    omega1 = math.pi ** 2 / length ** 2 * math.sqrt(ei / mu)
    alpha = math.pi * speed / length / omega1
    crossing = length / speed
    t = np.linspace(0.0, (1.0 + after) * crossing, points)
    w = np.zeros_like(t)
    for j in range(1, modes + 1, 2):  # even modes vanish at midspan
        if abs(alpha - j) < 1e-12:
            raise SystemExit(f"resonance: alpha = {alpha} equals mode {j}")
        w += modal_response(t, j, alpha, omega1, crossing) * math.sin(j * math.pi / 2)
    return t, 2 * force * length ** 3 / (math.pi ** 4 * ei) * w, alpha


def amplification(alpha, modes=49, after=1.0, points=20001):
    """max w(L/2) / (PL³/48EI) for speed parameter alpha (unit beam)."""
    length, ei, mu, force = 1.0, 1.0, 1.0, 1.0
    omega1 = math.pi ** 2
    speed = alpha * omega1 * length / math.pi
    _, w, _ = midspan_history(length, ei, mu, force, speed, modes, points, after)
    return w.max() / (force * length ** 3 / (48 * ei))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["amplification", "history", "check"])
    parser.add_argument("csv", nargs="?")
    parser.add_argument("column", nargs="?")
    parser.add_argument("--alphas", default="0.1,0.2,0.3,0.4,0.5,0.6,0.62,0.7,0.8,1.0")
    for name in ["length", "ei", "mass-per-length", "force", "speed"]:
        parser.add_argument("--" + name, type=float)
    parser.add_argument("--modes", type=int, default=49)
    parser.add_argument("--points", type=int, default=4001)
    parser.add_argument("--after", type=float, default=1.0)
    parser.add_argument("--tolerance", type=float, default=0.01)
    parser.add_argument("--scale", type=float, default=1.0,
                        help="factor on the railfe column (-1 for a deflection along -z)")
    args = parser.parse_args()
    if args.mode == "amplification":
        print("alpha,daf_first_mode,daf_series")
        for a in [float(x) for x in args.alphas.split(",")]:
            print(f"{a},{amplification(a, modes=1):.6f},{amplification(a):.6f}")
        return 0
    t, w, alpha = midspan_history(args.length, args.ei, args.mass_per_length, args.force,
                                  args.speed, args.modes, args.points, args.after)
    if args.mode == "history":
        print(f"# alpha = {alpha:.6f}")
        print("time_s,midspan_deflection_m")
        for ti, wi in zip(t, w):
            print(f"{ti:.9g},{wi:.9g}")
        return 0
    import csv
    with open(args.csv) as f:
        rows = list(csv.DictReader(f))
    tc = np.array([float(r["time_s"]) for r in rows])
    wc = args.scale * np.array([float(r[args.column]) for r in rows])
    reference = np.interp(tc, t, w, right=np.nan)
    keep = ~np.isnan(reference)
    peak_ref, peak = w.max(), wc[keep].max()
    history_error = np.abs(wc[keep] - reference[keep]).max() / peak_ref
    static = args.force * args.length ** 3 / (48 * args.ei)
    print(f"alpha {alpha:.4f}: peak {peak:.6e} m against {peak_ref:.6e} m "
          f"({(peak / peak_ref - 1) * 100:+.3f} %), DAF {peak / static:.4f} against "
          f"{peak_ref / static:.4f}; largest history difference {history_error * 100:.3f} % of the "
          f"peak")
    ok = abs(peak / peak_ref - 1) <= args.tolerance and history_error <= args.tolerance
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
