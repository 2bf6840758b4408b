"""Carter's 2-D steady rolling of two identical elastic bodies, and its measurement on a run of the
case inputs/verification/contact_rolling_carter (or a study variant of it). Shared by
contact_rolling_speed_accuracy.py; `python3 carter_rolling.py RESULTS_DIR [OMEGA_FREE]` prints
the comparison of one run of the case. Uses NumPy.

Reference (Carter 1926; Johnson, Contact Mechanics, 1985, section 8.4): two identical elastic
cylinders (or a cylinder on a block) in plane strain, pressed by P' per unit length, with
1/E* = 2 (1 - nu^2)/E and 1/R the relative curvature. Normal and tangential problems uncouple
(identical materials); Hertz gives the half-width b = sqrt(4 P' R / (pi E*)) and
p(x) = p0 sqrt(1 - x^2/b^2), p0 = 2 P' / (pi b). Under a creep force Q' < mu P' the adhesion
zone is at the leading edge, b - 2c <= x <= b, with c = b sqrt(1 - Q'/(mu P')), and
  q(x) = mu p0 sqrt(1 - x^2/b^2) - mu p0 (c/b) sqrt(1 - (x - (b - c))^2 / c^2)  (adhesion)
  q(x) = mu p(x)                                                              (slip)
The relative surface strain the adhesion zone needs is uniform there and equals the creepage
  xi = (V1 - V2) / V = (mu b / R) (1 - sqrt(1 - Q'/(mu P'))),
so Q'/(mu P') = 1 - (1 - xi R / (mu b))^2 for xi < mu b / R (full slip beyond). x is measured
along the rolling direction: the contact moves over both surfaces towards +x (material enters
at x = +b). Here V1 is the circumferential speed of the driving (faster) body, V2 the other's,
V their mean; creepage is measured against free rolling: xi = omega / omega_free - 1 at the same
translation speed.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from railfe_runs import csv_rows  # noqa: E402

YOUNG, POISSON, RADIUS = 210e9, 0.3, 0.1
THICKNESS = 1e-3  # m, the slice along y
HUB_HALF_LENGTH = 0.1  # m: the hub's end nodes lie at x = +-0.1 on the cylinder's axis
E_STAR = YOUNG / (2 * (1 - POISSON**2))


def hertz(load_per_length):
    """(b, p0) of Hertz's line contact of the case's two steels under P' (N/m)."""
    b = math.sqrt(4 * load_per_length * RADIUS / (math.pi * E_STAR))
    return b, 2 * load_per_length / (math.pi * b)


def carter(load_per_length, traction_ratio, mu):
    """Carter's solution at P' (N/m) and Q'/(mu P'): dict with b, p0, c, the adhesion zone's
    trailing edge, the creepage xi and the shear traction q(x)."""
    b, p0 = hertz(load_per_length)
    c = b * math.sqrt(max(0.0, 1 - traction_ratio))

    def shear(x):
        x = np.asarray(x, dtype=float)
        full = mu * p0 * np.sqrt(np.clip(1 - (x / b) ** 2, 0, None))
        local = (x - (b - c)) / c if c > 0 else np.full_like(x, 2.0)
        stick = mu * p0 * (c / b) * np.sqrt(np.clip(1 - local**2, 0, None))
        return full - stick

    return {"b": b, "p0": p0, "c": c, "stick_start": b - 2 * c,
            "creepage": mu * b / RADIUS * (1 - c / b), "shear": shear}


def carter_force_ratio(load_per_length, creepage, mu):
    """Q'/(mu P') Carter gives at creepage xi (1 at and beyond full slip)."""
    b, _ = hertz(load_per_length)
    return 1 - max(0.0, 1 - creepage * RADIUS / (mu * b)) ** 2


def hub_angle(rows):
    """Times and rotation angles of the hub about y from the histories of its end nodes."""
    t = np.array([float(r["time_s"]) for r in rows])
    left = np.array([float(r["hub left_displacement_z_m"]) for r in rows])
    right = np.array([float(r["hub right_displacement_z_m"]) for r in rows])
    return t, np.arcsin((left - right) / (2 * HUB_HALF_LENGTH))


def mean_rate(t, theta, window):
    """Least-squares slope of theta(t) over the time window (s)."""
    pick = (t >= window[0]) & (t <= window[1])
    return np.polyfit(t[pick], theta[pick], 1)[0]


def window_mean(rows, column, window):
    """Mean of a contact-history column over the time window."""
    values = [float(r[column]) for r in rows if window[0] <= float(r["time_s"]) <= window[1]]
    return sum(values) / len(values)


def measure(results, step, pair, mu, window, patch_index, omega_free):
    """Measures one driven run against Carter; returns a dict of measured and reference values.

    window: (start, end) in s over which the hub's angular speed and the contact forces are
    averaged; patch_index: the patch file (1-based) to compare; omega_free: the free-rolling
    angular speed (rad/s) of the same model, the reference of the creepage."""
    t, theta = hub_angle(csv_rows(os.path.join(results, f"{step}_histories.csv")))
    omega = mean_rate(t, theta, window)
    contact = csv_rows(os.path.join(results, f"{step}_contact_{pair}.csv"))
    normal = window_mean(contact, "normal_force_N", window)
    creep_force = window_mean(contact, "tangential_1_N", window)
    load = normal / THICKNESS
    ratio = abs(creep_force) / (mu * normal)
    reference = carter(load, ratio, mu)
    creepage = omega / omega_free - 1
    patch = csv_rows(os.path.join(results, f"{step}_contact_{pair}_patch_{patch_index}.csv"))
    s = np.array([float(r["s1_m"]) for r in patch])
    p = np.array([float(r["pressure_Pa"]) for r in patch])
    q = np.array([float(r["shear_1_Pa"]) for r in patch])
    slipping = np.array([float(r["slipping"]) for r in patch]) > 0.5
    # x along the rolling direction: the contact moves towards +x over both surfaces (the
    # block is driven along -x), which is s1's direction.
    stick = s[~slipping]
    b = reference["b"]
    q_ref = reference["shear"](s) * np.sign(creep_force)
    shear_error = float(np.sqrt(np.mean((q - q_ref) ** 2)) / (mu * reference["p0"]))
    stick_length = (stick.max() - stick.min()) if stick.size else 0.0
    return {
        "omega_rad/s": omega,
        "creepage": creepage,
        "normal_force_N": normal,
        "creep_force_N": creep_force,
        "traction_ratio": ratio,
        "carter_creepage": reference["creepage"],
        "creepage_error": creepage / reference["creepage"] - 1,
        "carter_force_ratio_at_creepage": carter_force_ratio(load, creepage, mu),
        "creep_force_error": ratio / carter_force_ratio(load, creepage, mu) - 1,
        "b_mm": 0.5 * (s.max() - s.min()) * 1e3,
        "hertz_b_mm": b * 1e3,
        "b_error": 0.5 * (s.max() - s.min()) / b - 1,
        "p0_MPa": p.max() * 1e-6,
        "hertz_p0_MPa": reference["p0"] * 1e-6,
        "p0_error": p.max() / reference["p0"] - 1,
        "adhesion_mm": stick_length * 1e3,
        "carter_adhesion_mm": 2 * reference["c"] * 1e3,
        "adhesion_error": stick_length / (2 * reference["c"]) - 1 if reference["c"] > 0 else 0.0,
        "adhesion_start_mm": (stick.min() if stick.size else b) * 1e3,
        "carter_adhesion_start_mm": reference["stick_start"] * 1e3,
        "shear_rms_error": shear_error,
    }


if __name__ == "__main__":
    # RESULTS_DIR [OMEGA_FREE]: the case's run (patch 2 at 0.8 ms, means over 0.5-0.8 ms)
    free = float(sys.argv[2]) if len(sys.argv) > 2 else 199.966291
    row = measure(sys.argv[1], "roll", "rolling", 0.3, (5e-4, 8e-4), 2, free)
    for key, value in row.items():
        print(f"{key:32s} {value:.6g}")
