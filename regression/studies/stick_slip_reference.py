#!/usr/bin/env python3
"""Reference stick-slip limit cycle of a mass on a spring dragged by a belt (issue 15), for
inputs/verification/contact_stick_slip and regression/studies/explicit_stick_slip.py.

    M x'' + k x + P = F,  F = friction of the belt on the mass, the belt moving at v along +x,
                         P a constant pull backwards (a spring anchored P/k behind x = 0)
    stick  (x' = v):   F = k x + P, held while |k x + P| <= mu_s N
    slip   (x' != v):  F = mu(|v_r|) N sign(v_r),  v_r = v - x',
                       mu(v_r) = mu_d + (mu_s - mu_d) exp(-c |v_r|)

The stick phases are integrated in closed form (x = x0 + v t), the slip phases with SciPy's
solve_ivp (DOP853, rtol 1e-12, atol 1e-15 m and m/s) with events for the return of the relative
velocity to zero (end of slip: stick if |k x| <= mu_s N, otherwise slip on in the other
direction) and for x' = 0 (the extremes of x). Starting from x = 0 moving with the belt, the
first stick ends at x_s = (mu_s N - P) / k with x' = v; the spring then brakes the mass to a stop a
little further on (the largest x) and swings it back (the smallest x) before it sticks again.
Every later stick ends in the same state, so the motion is on its limit cycle from the first
slip onset: the period is the time between two slip onsets, the amplitude the largest and the
smallest x (both reached while slipping, where x' = 0).

    /usr/bin/python3 regression/studies/stick_slip_reference.py [--write]

prints the limit cycle of the case's parameters (below) and, with --write, stores it in
inputs/verification/contact_stick_slip/reference.csv, which the case's expected.xml cites.
The function limit_cycle() is imported by explicit_stick_slip.py.
"""
import argparse
import csv
import math
import os

import numpy as np
from scipy.integrate import solve_ivp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REFERENCE_CSV = os.path.join(ROOT, "inputs", "verification", "contact_stick_slip", "reference.csv")

# The case's parameters (inputs/verification/contact_stick_slip/deck.xml).
CASE = dict(mass=0.1,          # kg: the steel block (0.0314 kg) plus 0.0686 kg of nodal masses
            stiffness=1.0e4,   # N/m: springs from the block's nodes to ground along x
            preload=20.0,      # N: constant pull along -x (the spring anchored 2 mm behind), so
                               # that the block starts (x = 0) inside its limit cycle
            normal=100.0,      # N: nodal force pressing the block on the belt
            belt=0.1,          # m/s: belt speed along +x
            mu_s=0.5, mu_d=0.32, decay=6.0)  # the squeal model's law, c in s/m


def friction_coefficient(p, relative_speed):
    return p["mu_d"] + (p["mu_s"] - p["mu_d"]) * math.exp(-p["decay"] * abs(relative_speed))


def limit_cycle(p, cycles=3, rtol=1e-12, atol=1e-15, samples=None):
    """Integrates `cycles` stick-slip cycles from x = 0, x' = v (stuck). Returns a dict with the
    period (s), x_max and x_min (m), the stick and slip durations (s), the largest relative speed
    (m/s), the smallest friction force during slip (N), the slip onset times, and, if `samples`
    is an array of times, x(t), x'(t) and F(t) there."""
    M, k, N, v, mu_s = p["mass"], p["stiffness"], p["normal"], p["belt"], p["mu_s"]
    P = p.get("preload", 0.0)
    x_stick = (mu_s * N - P) / k
    pieces = []      # (t0, t1, kind, data): kind 'stick' data x0; kind 'slip' data dense solution
    onsets, extremes, stick_times, slip_times = [], [], [], []
    largest_relative, smallest_force = 0.0, math.inf
    t, x, u = 0.0, 0.0, v
    while len(onsets) < cycles + 1:
        # Stick: carried by the belt until the spring force reaches mu_s N.
        if abs(k * x + P) <= mu_s * N * (1 + 1e-14) and abs(u - v) < 1e-9:
            duration = (x_stick - x) / v
            pieces.append((t, t + duration, "stick", x))
            stick_times.append(duration)
            t, x, u = t + duration, x_stick, v
        onsets.append(t)
        # Slip: sign of the relative velocity chosen by the sign of the net force on the mass at
        # the onset (the spring pulls back: v_r > 0).
        direction = 1.0 if k * x + P > 0 else -1.0

        def rhs(_, state):
            # Smooth continuation of the slip law past v_r = 0 (the event ends the phase
            # there): no kink or jump for the integrator to stumble on.
            relative = direction * (v - state[1])
            mu = p["mu_d"] + (p["mu_s"] - p["mu_d"]) * math.exp(-p["decay"] * relative)
            return [state[1], (direction * mu * N - k * state[0] - P) / M]

        def back_to_belt(_, state):
            return state[1] - v
        back_to_belt.terminal = True
        back_to_belt.direction = 1.0 if direction > 0 else -1.0

        def turning(_, state):
            return state[1]  # x' = 0: an extreme of x (a maximum soon after the onset, where
                             # the mass, still moving with v, is braked by the spring, then the
                             # minimum at the end of the backward swing)

        # The onset is a double zero of v - x' (x'' = 0 there): a short first leg without
        # events, then the rest with them.
        lead = 1e-3 * math.sqrt(M / k)
        first = solve_ivp(rhs, (t, t + lead), [x, u], method="DOP853", rtol=rtol, atol=atol,
                          dense_output=True)
        solution = solve_ivp(rhs, (t + lead, t + 100 * math.sqrt(M / k)), first.y[:, -1],
                             method="DOP853", rtol=rtol, atol=atol,
                             events=[back_to_belt, turning], dense_output=True)
        pieces.append((t, t + lead, "slip", first.sol))
        if solution.t_events[0].size == 0:
            raise RuntimeError("the slip phase did not end")
        t_end = solution.t_events[0][0]
        x_end, u_end = solution.y_events[0][0]
        for t_turn, state in zip(solution.t_events[1], solution.y_events[1]):
            extremes.append((t_turn, state[0]))
        # Relative speed and friction force over the slip phase, on a fine grid.
        grid = np.linspace(t + lead, t_end, 4001)
        states = solution.sol(grid)
        relative = v - states[1]
        largest_relative = max(largest_relative, float(np.max(np.abs(relative))))
        forces = [friction_coefficient(p, r) * N for r in relative]
        smallest_force = min(smallest_force, min(forces))
        pieces.append((t + lead, t_end, "slip", solution.sol))
        slip_times.append(t_end - t)
        t, x, u = t_end, x_end, v
        if abs(k * x + P) > mu_s * N:
            raise RuntimeError("no re-stick at the end of slip: not covered by this reference")
    periods = np.diff(onsets)
    result = dict(period=float(periods[-1]), period_spread=float(np.ptp(periods[1:]))
                  if len(periods) > 1 else 0.0,
                  x_max=max(e[1] for e in extremes), x_min=min(e[1] for e in extremes),
                  x_onset=x_stick, x_restick=float(x),
                  stick_time=stick_times[-1], slip_time=slip_times[-1],
                  largest_relative_speed=largest_relative, smallest_friction_force=smallest_force,
                  onsets=onsets, pieces=pieces)
    if samples is not None:
        xs, us = np.zeros(len(samples)), np.zeros(len(samples))
        for i, ts in enumerate(samples):
            for t0, t1, kind, data in pieces:
                if t0 <= ts <= t1:
                    if kind == "stick":
                        xs[i], us[i] = data + v * (ts - t0), v
                    else:
                        xs[i], us[i] = data(ts)
                    break
            else:
                xs[i], us[i] = math.nan, math.nan
        result["samples"] = (np.asarray(samples), xs, us)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--write", action="store_true", help="write " + REFERENCE_CSV)
    args = parser.parse_args()
    p = CASE
    r = limit_cycle(p, cycles=4)
    loose = limit_cycle(p, cycles=4, rtol=1e-9, atol=1e-12)
    omega = math.sqrt(p["stiffness"] / p["mass"])
    print(f"M = {p['mass']} kg, k = {p['stiffness']} N/m, P = {p['preload']} N, N = {p['normal']} N,"
          f" v = {p['belt']} m/s,"
          f" mu_s = {p['mu_s']}, mu_d = {p['mu_d']}, c = {p['decay']} s/m")
    print(f"natural period 2 pi sqrt(M/k)      = {2 * math.pi / omega:.9f} s")
    print(f"limit cycle period                 = {r['period']:.9f} s"
          f"  (spread over cycles {r['period_spread']:.1e} s;"
          f" rtol 1e-9 run differs by {abs(loose['period'] - r['period']):.1e} s)")
    print(f"  stick {r['stick_time']:.9f} s + slip {r['slip_time']:.9f} s")
    print(f"x at slip onset = (mu_s N - P) / k = {r['x_onset']:.9e} m")
    print(f"x_max (the mass stops, soon after) = {r['x_max']:.9e} m"
          f"  (rtol 1e-9: {abs(loose['x_max'] - r['x_max']):.1e} m)")
    print(f"x_min (end of the backward swing)  = {r['x_min']:.9e} m"
          f"  (rtol 1e-9: {abs(loose['x_min'] - r['x_min']):.1e} m)")
    print(f"x at re-stick                      = {r['x_restick']:.9e} m")
    print(f"largest relative speed v - x'      = {r['largest_relative_speed']:.6f} m/s")
    print(f"smallest friction force in slip    = {r['smallest_friction_force']:.6f} N")
    print(f"first slip onset                   = {r['onsets'][0]:.9f} s")
    if args.write:
        os.makedirs(os.path.dirname(REFERENCE_CSV), exist_ok=True)
        with open(REFERENCE_CSV, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["quantity", "value", "unit", "what"])
            for name, value, unit, what in [
                    ("mass", p["mass"], "kg", "M"), ("stiffness", p["stiffness"], "N/m", "k"),
                    ("preload", p.get("preload", 0.0), "N", "P: constant pull along -x"),
                    ("normal_force", p["normal"], "N", "N"), ("belt_speed", p["belt"], "m/s", "v"),
                    ("mu_static", p["mu_s"], "", "mu_s"), ("mu_dynamic", p["mu_d"], "", "mu_d"),
                    ("decay", p["decay"], "s/m", "c"),
                    ("period", r["period"], "s", "time between slip onsets"),
                    ("stick_time", r["stick_time"], "s", "stick phase"),
                    ("slip_time", r["slip_time"], "s", "slip phase"),
                    ("x_onset", r["x_onset"], "m", "(mu_s N - P) / k: slip onset"),
                    ("x_max", r["x_max"], "m", "largest x: the mass stops after the onset"),
                    ("x_min", r["x_min"], "m", "end of the backward swing"),
                    ("x_restick", r["x_restick"], "m", "position where the mass sticks again"),
                    ("first_onset", r["onsets"][0], "s", "first slip onset from x = 0 stuck"),
                    ("largest_relative_speed", r["largest_relative_speed"], "m/s", "max v - x'"),
                    ("smallest_friction_force", r["smallest_friction_force"], "N",
                     "mu(max v_r) N")]:
                w.writerow([name, repr(float(value)), unit, what])
        print("wrote", REFERENCE_CSV)


if __name__ == "__main__":
    main()
