#!/usr/bin/env python3
"""Rigid-body modes of a 4-wheelset railway vehicle (car body, 2 bogies, 4 wheelsets) and the fit
of a representative parameter set to the nine modes published for the RTRI rolling-stock
test-plant car of the lateral train-structure interaction paper (narrow gauge 1067 mm,
wheel radius 0.43 m).

The model is the one railfe builds (docs/vehicle_parameters.md):
  axes x forward, y right, z down; origin on the track centre line in the top-of-rail plane.
  Each body is rigid, 6 DOFs [ux, uy, uz, rx, ry, rz] at its centre of mass, small rotations,
  point mass with a diagonal inertia.
  car body at (0, 0, -h_c); bogies at (+-a, 0, -h_b); wheelsets at (+-a +- b, 0, -r0).
  primary: per wheelset two axle boxes at (x_w, +-d_p, -r0), translational bushings
           (k_px, k_py, k_pz), (c_px, c_py, c_pz) between wheelset and bogie.
  secondary: per bogie two springs at (+-a, +-d_s, -h_s), (k_sx, k_sy, k_sz), (c_sx, c_sy, c_sz)
           between bogie and car body; per bogie a relative-roll stiffness k_sr (anti-roll bar)
           and a relative-yaw stiffness k_syaw, at the bogie centre.
  bushing between A and B at P: u_P(K) = u_K + theta_K x (P - G_K) = T_K q_K,
           T_K = [I, -[P - G_K]x]; d = u_P(B) - u_P(A); force on B = -k d (global axes).
  No gravity (pendulum) stiffness. Modes with the 4 wheelsets held (18 DOFs), K phi = w^2 M phi.

    /usr/bin/python3 regression/studies/vehicle_modes_fit.py          # fit from the source set
    /usr/bin/python3 regression/studies/vehicle_modes_fit.py check    # modes of the CSV values
    /usr/bin/python3 regression/studies/vehicle_modes_fit.py fit --write   # refit, rewrite CSV

The fit: scipy least squares on log(f_model / f_published) of the nine modes, plus a weak
penalty (weight LAMBDA) on log(p / p_source) of each free parameter (on p / scale for those the
source sets to zero), so that what the modes do not ask for stays at its source value. Free
parameters are bounded to plausible ranges (BOUNDS). Uses NumPy and SciPy; runs in seconds.
"""
import csv
import os
import sys

import numpy as np
import scipy.linalg as sla
from scipy.optimize import least_squares

HERE = os.path.dirname(os.path.abspath(__file__))
CSV_PATH = os.path.join(HERE, "vehicle_parameters.csv")
WHEEL_RADIUS = 0.43  # m, r0
DOF_NAMES = ("ux", "uy", "uz", "rx", "ry", "rz")
BODY_NAMES = ("car body", "bogie front", "bogie rear",
              "wheelset 1", "wheelset 2", "wheelset 3", "wheelset 4")

# Published modes of the test car (Hz). Bogie values are matched to the lower of each
# in-phase/anti-phase pair of the two bogies.
PUBLISHED = [
    ("car body rolling (lower sway)", "car", "sway_lower", 0.82),
    ("car body bouncing", "car", "uz", 1.71),
    ("car body yawing", "car", "rz", 2.03),
    ("car body pitching", "car", "ry", 2.08),
    ("car body 2nd rolling (upper sway)", "car", "sway_upper", 2.15),
    ("bogie bouncing", "bogie", "uz", 11.64),
    ("bogie rolling", "bogie", "rx", 12.21),
    ("bogie pitching", "bogie", "ry", 14.2),
    ("bogie yawing", "bogie", "rz", 29.95),
]

# Source values (SI). HD: Huo F., Dai H., "Formulation of a Linearized Model for Vehicle-Track
# Interactions", Shock and Vibration 2019, 2015465, Table 1 (a CRH-type passenger car, r0 =
# 0.43 m). WY: Wu Y.-S., Yang Y.-B., "Steady-state response and riding comfort of trains moving
# over a series of simply supported bridges", Eng. Struct. 25 (2003) 251-265 (Shinkansen 300,
# vertical plane; values as transcribed in github.com/DanielCanteroNTNU/TTB-2D,
# TrainProp_ShinkansenS300.m). Estimates: 1067 mm gauge geometry, no table found.
SOURCE = {
    "car_body_mass": (34500.0, "kg", "Huo&Dai 2019 Tab1"),
    "car_body_inertia_x": (124304.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "car_body_inertia_y": (1560400.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "car_body_inertia_z": (1521000.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "car_body_cg_height": (1.8, "m", "estimate for 1067 mm gauge"),
    "bogie_mass": (3500.0, "kg", "Huo&Dai 2019 Tab1"),
    "bogie_inertia_x": (2522.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "bogie_inertia_y": (1722.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "bogie_inertia_z": (3100.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "bogie_cg_height": (0.6, "m", "estimate for 1067 mm gauge"),
    "wheelset_mass": (2200.0, "kg", "Huo&Dai 2019 Tab1"),
    "wheelset_inertia_x": (730.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "wheelset_inertia_y": (84.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "wheelset_inertia_z": (990.0, "kg m2", "Huo&Dai 2019 Tab1"),
    "half_bogie_spacing": (8.75, "m", "Huo&Dai 2019 Tab1; Wu&Yang 2003"),
    "half_wheelbase": (1.25, "m", "Huo&Dai 2019 Tab1; Wu&Yang 2003"),
    "primary_half_span": (0.82, "m", "estimate for 1067 mm gauge"),
    "secondary_half_span": (0.95, "m", "estimate for 1067 mm gauge"),
    "secondary_height": (0.9, "m", "estimate for 1067 mm gauge"),
    "primary_stiffness_x": (11.68e6, "N/m", "Huo&Dai 2019 Tab1"),
    "primary_stiffness_y": (7.40e6, "N/m", "Huo&Dai 2019 Tab1"),
    "primary_stiffness_z": (1.173e6, "N/m", "Huo&Dai 2019 Tab1"),
    "primary_damping_x": (0.0, "N s/m", "none in Huo&Dai 2019"),
    "primary_damping_y": (0.0, "N s/m", "none in Huo&Dai 2019"),
    "primary_damping_z": (19.6e3, "N s/m",
                          "Huo&Dai 2019 Tab1 = Wu&Yang 2003 (39.2 kN s/m per axle)"),
    "secondary_stiffness_x": (0.179e6, "N/m", "Huo&Dai 2019 Tab1"),
    "secondary_stiffness_y": (0.179e6, "N/m", "Huo&Dai 2019 Tab1"),
    "secondary_stiffness_z": (0.61e6, "N/m", "Huo&Dai 2019 Tab1"),
    "secondary_damping_x": (0.0, "N s/m", "none in Huo&Dai 2019"),
    "secondary_damping_y": (54.8e3, "N s/m", "Huo&Dai 2019 Tab1"),
    "secondary_damping_z": (9.8e3, "N s/m", "Huo&Dai 2019 Tab1"),
    "anti_roll_stiffness": (0.0, "N m/rad", "none in Huo&Dai 2019"),
    "secondary_yaw_stiffness": (0.0, "N m/rad", "none in Huo&Dai 2019"),
}

# Free parameters of the fit, one per published mode, with the plausible range each may take:
#   bogie bouncing -> primary_stiffness_z     car body bouncing -> secondary_stiffness_z
#   car body pitching -> car_body_inertia_y (car_body_inertia_z follows it, TIED)
#   bogie pitching -> bogie_inertia_y         bogie rolling -> bogie_inertia_x
#   bogie yawing -> primary_stiffness_x       car body yawing -> secondary_stiffness_y
#   the sway pair -> car_body_inertia_x and secondary_half_span (roll stiffness)
BOUNDS = {
    "primary_stiffness_z": (0.8e6, 5e6),
    "secondary_stiffness_z": (0.3e6, 1.5e6),
    "car_body_inertia_y": (1.0e6, 2.2e6),
    "bogie_inertia_y": (1000.0, 4000.0),
    "bogie_inertia_x": (1000.0, 3500.0),
    "primary_stiffness_x": (5e6, 30e6),
    "secondary_stiffness_y": (0.1e6, 1.2e6),
    "car_body_inertia_x": (40e3, 130e3),
    "secondary_half_span": (0.75, 1.05),
}
# A car body's yaw and pitch inertias are both set by its length (I_z ~ I_y): the yaw inertia
# keeps the source's ratio to the pitch inertia.
TIED = {"car_body_inertia_z": ("car_body_inertia_y",
                               SOURCE["car_body_inertia_z"][0] / SOURCE["car_body_inertia_y"][0])}
LAMBDA = 1e-4


def source_params():
    return {k: v[0] for k, v in SOURCE.items()}


def read_csv(path=CSV_PATH):
    with open(path, newline="") as f:
        return {row["name"]: float(row["value"]) for row in csv.DictReader(f)}


def _skew(r):
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def _transfer(point, centre):
    """T with u_P = T q for q = [u, theta] of the body whose centre of mass is `centre`."""
    return np.hstack([np.eye(3), -_skew(np.asarray(point, float) - np.asarray(centre, float))])


def body_centres(p):
    a, b, r0 = p["half_bogie_spacing"], p["half_wheelbase"], WHEEL_RADIUS
    centres = [(0.0, 0.0, -p["car_body_cg_height"]),
               (a, 0.0, -p["bogie_cg_height"]), (-a, 0.0, -p["bogie_cg_height"])]
    centres += [(x, 0.0, -r0) for x in (a + b, a - b, -a + b, -a - b)]
    return centres


def full_matrices(p):
    """M, K, C (42 x 42) of all 7 bodies: car body, bogie front, bogie rear, wheelsets front to
    rear, each [ux, uy, uz, rx, ry, rz]."""
    a, b, r0 = p["half_bogie_spacing"], p["half_wheelbase"], WHEEL_RADIUS
    centres = body_centres(p)
    n = 6 * len(centres)
    M, K, C = np.zeros((n, n)), np.zeros((n, n)), np.zeros((n, n))
    inertia = ([("car_body", p["car_body_mass"])] + [("bogie", p["bogie_mass"])] * 2
               + [("wheelset", p["wheelset_mass"])] * 4)
    for i, (name, m) in enumerate(inertia):
        M[6 * i:6 * i + 6, 6 * i:6 * i + 6] = np.diag(
            [m, m, m, p[name + "_inertia_x"], p[name + "_inertia_y"], p[name + "_inertia_z"]])

    def bushing(A, B, point, k, c):
        TA, TB = _transfer(point, centres[A]), _transfer(point, centres[B])
        sA, sB = slice(6 * A, 6 * A + 6), slice(6 * B, 6 * B + 6)
        for mat, diag in ((K, k), (C, c)):
            d = np.diag(diag)
            mat[sA, sA] += TA.T @ d @ TA
            mat[sB, sB] += TB.T @ d @ TB
            mat[sA, sB] -= TA.T @ d @ TB
            mat[sB, sA] -= TB.T @ d @ TA

    def rotational(A, B, k):
        d = np.diag(k)
        sA, sB = slice(6 * A + 3, 6 * A + 6), slice(6 * B + 3, 6 * B + 6)
        K[sA, sA] += d
        K[sB, sB] += d
        K[sA, sB] -= d
        K[sB, sA] -= d

    kp = [p["primary_stiffness_" + c] for c in "xyz"]
    cp = [p["primary_damping_" + c] for c in "xyz"]
    ks = [p["secondary_stiffness_" + c] for c in "xyz"]
    cs = [p["secondary_damping_" + c] for c in "xyz"]
    for j, xw in enumerate((a + b, a - b, -a + b, -a - b)):
        bogie = 1 if j < 2 else 2
        for side in (1.0, -1.0):
            bushing(3 + j, bogie, (xw, side * p["primary_half_span"], -r0), kp, cp)
    for bogie, xb in ((1, a), (2, -a)):
        for side in (1.0, -1.0):
            bushing(bogie, 0, (xb, side * p["secondary_half_span"], -p["secondary_height"]),
                    ks, cs)
        rotational(bogie, 0, (p["anti_roll_stiffness"], 0.0, p["secondary_yaw_stiffness"]))
    return M, K, C


def vehicle_matrices(p):
    """M, K (18 x 18) of car body and bogies with the 4 wheelsets held."""
    M, K, _ = full_matrices(p)
    return M[:18, :18], K[:18, :18]


def modes(p):
    M, K = vehicle_matrices(p)
    w2, V = sla.eigh(K, M)
    return np.sqrt(np.clip(w2, 0.0, None)) / (2 * np.pi), V, M


def energy_shares(v, M):
    """Kinetic-energy share of each (body, DOF), shape (3, 6), summing to 1."""
    e = v ** 2 * np.diag(M)
    return (e / e.sum()).reshape(3, 6)


def name_mode(v, M):
    """(group, dof, label) from the kinetic-energy shares. group: 'car' or 'bogie'; dof: one of
    DOF_NAMES, or 'sway_lower'/'sway_upper' for the car body's coupled lateral-roll modes
    (roll centre below / above the centre of mass)."""
    e = energy_shares(v, M)
    if e[0].sum() >= e[1:].sum():
        d = int(np.argmax(e[0]))
        if d in (1, 3):  # lateral-roll pair; roll centre at dz = uy / rx below the CG (z down)
            dz = v[1] / v[3] if abs(v[3]) > 1e-14 else np.inf
            which = "lower" if dz > 0 else "upper"
            lab = "car body %s sway (roll centre %.2f m %s CG; %.0f%% uy, %.0f%% rx)" % (
                which, abs(dz), "below" if dz > 0 else "above", 100 * e[0, 1], 100 * e[0, 3])
            return "car", "sway_" + which, lab
        return "car", DOF_NAMES[d], "car body %s (%.0f%%)" % (DOF_NAMES[d], 100 * e[0, d])
    eb = e[1] + e[2]
    d = int(np.argmax(eb))
    front, rear = v[6 + d], v[12 + d]
    # same sign of the same DOF on both bogies = in phase (for ux, rx, rz this is the sense
    # that moves the car body; for uz and ry too)
    phase = "in-phase" if front * rear > 0 else "anti-phase"
    return "bogie", DOF_NAMES[d], "bogie %s %s (%.0f%%)" % (DOF_NAMES[d], phase, 100 * eb[d])


def identify(p):
    """Model frequency of each published mode, and the named list of all 18 modes."""
    f, V, M = modes(p)
    named = [(f[i],) + name_mode(V[:, i], M) for i in range(len(f))]
    shares = [energy_shares(V[:, i], M) for i in range(len(f))]
    out = []
    for _, group, dof, _ in PUBLISHED:
        if group == "car" and dof.startswith("sway"):
            # the two modes with the most car-body lateral + roll energy, by frequency
            score = [s[0, 1] + s[0, 3] for s in shares]
            pair = sorted(np.argsort(score)[-2:])
            out.append(f[pair[0] if dof == "sway_lower" else pair[1]])
        elif group == "car":
            k = DOF_NAMES.index(dof)
            out.append(f[int(np.argmax([s[0, k] for s in shares]))])
        else:
            k = DOF_NAMES.index(dof)
            score = [s[1, k] + s[2, k] for s in shares]
            pair = np.argsort(score)[-2:]
            out.append(min(f[pair[0]], f[pair[1]]))
    return np.array(out), named


def apply_ties(p):
    for k, (master, ratio) in TIED.items():
        p[k] = p[master] * ratio
    return p


def fit(p_start, free=tuple(BOUNDS), lam=LAMBDA):
    """Least squares on log(f_model / f_published), plus lam * log(p / p_source) per free
    parameter (a weak pull towards the source that only matters where the modes leave a
    parameter undetermined). Parameters are scaled by their source values and bounded."""
    ref = {k: SOURCE[k][0] for k in free}
    lo = np.array([BOUNDS[k][0] / ref[k] for k in free])
    hi = np.array([BOUNDS[k][1] / ref[k] for k in free])
    target = np.log([m[3] for m in PUBLISHED])

    def unpack(x):
        p = dict(p_start)
        p.update({k: xi * ref[k] for k, xi in zip(free, x)})
        return apply_ties(p)

    def residual(x):
        f, _ = identify(unpack(x))
        return np.concatenate([np.log(f) - target, lam * np.log(x)])

    x0 = np.clip([p_start[k] / ref[k] for k in free], lo + 1e-9, hi - 1e-9)
    sol = least_squares(residual, x0, bounds=(lo, hi), x_scale="jac", xtol=1e-12,
                        ftol=1e-12, gtol=1e-12)
    return unpack(sol.x)


def print_report(p, title):
    f, named = identify(p)
    print(title)
    print("%-36s %10s %10s %8s" % ("published mode", "paper Hz", "model Hz", "error %"))
    for (label, _, _, fp), fm in zip(PUBLISHED, f):
        print("%-36s %10.2f %10.3f %8.2f" % (label, fp, fm, 100 * (fm / fp - 1)))
    print("\nall 18 modes (wheelsets held):")
    for fi, _, _, lab in named:
        print("  %8.3f Hz  %s" % (fi, lab))
    return f


def write_csv(p, path=CSV_PATH):
    rows = []
    for k, (v0, unit, src) in SOURCE.items():
        changed = "yes" if abs(p[k] - v0) > 1e-9 * max(1.0, abs(v0)) else "no"
        rows.append([k, "%.6g" % p[k], unit, "%.6g" % v0, src, changed])
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["name", "value", "unit", "source_value", "source", "changed_by_fit"])
        w.writerows(rows)


def vehicle_deck_xml(p, wheel_radius=WHEEL_RADIUS, yaw_damping=0.0):
    """The Mesh (Mesh/Type vehicle) and Sections of a railfe deck for parameters \p p, the
    wheelset centres at \p wheel_radius (the track's nominal rolling radius), with a yaw damper
    of \p yaw_damping N m s/rad between the car body and each bogie when it is positive."""
    def g(k):
        return "%.6g" % p[k]

    def point_mass(name, block, prefix):
        return f"""    <ParameterList name="{name}">
      <Parameter name="Blocks" type="Array(string)" value="{{{block}}}"/>
      <Parameter name="Element" type="string" value="point mass"/>
      <Parameter name="Mass" type="double" value="{g(prefix + '_mass')}"/>
      <Parameter name="Inertia" type="Array(double)" value="{{{g(prefix + '_inertia_x')}, {g(prefix + '_inertia_y')}, {g(prefix + '_inertia_z')}}}"/>
    </ParameterList>
"""

    def spring(name, block, prefix):
        k = ", ".join(g(prefix + "_stiffness_" + c) for c in "xyz")
        c = ", ".join(g(prefix + "_damping_" + c) for c in "xyz")
        return f"""    <ParameterList name="{name}">
      <Parameter name="Blocks" type="Array(string)" value="{{{block}}}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{{{k}, 0, 0, 0}}"/>
      <Parameter name="Damping" type="Array(double)" value="{{{c}, 0, 0, 0}}"/>
    </ParameterList>
"""

    dampers = ""
    if yaw_damping > 0:
        dampers = f"""    <ParameterList name="yaw dampers">
      <Parameter name="Blocks" type="Array(string)" value="{{secondary_rotation}}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{{0, 0, 0, 0, 0, 0}}"/>
      <Parameter name="Damping" type="Array(double)" value="{{0, 0, 0, 0, 0, {yaw_damping:g}}}"/>
    </ParameterList>
"""
    rotation = "true" if yaw_damping > 0 else "false"
    return f"""  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="vehicle"/>
    <ParameterList name="Vehicle">
      <Parameter name="Half bogie spacing" type="double" value="{g('half_bogie_spacing')}"/>
      <Parameter name="Half wheelbase" type="double" value="{g('half_wheelbase')}"/>
      <Parameter name="Wheel radius" type="double" value="{wheel_radius:g}"/>
      <Parameter name="Car body height" type="double" value="{g('car_body_cg_height')}"/>
      <Parameter name="Bogie height" type="double" value="{g('bogie_cg_height')}"/>
      <Parameter name="Primary half span" type="double" value="{g('primary_half_span')}"/>
      <Parameter name="Secondary half span" type="double" value="{g('secondary_half_span')}"/>
      <Parameter name="Secondary height" type="double" value="{g('secondary_height')}"/>
      <Parameter name="Secondary rotation" type="bool" value="{rotation}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Sections">
{point_mass("car body", "car_body", "car_body")}{point_mass("bogie", "bogies", "bogie")}{point_mass("wheelset", "wheelsets", "wheelset")}{spring("axle box", "primary", "primary")}{spring("air spring", "secondary", "secondary")}{dampers}  </ParameterList>
"""


def main(argv):
    mode = argv[1] if len(argv) > 1 else "fit"
    if mode == "check":
        print_report(read_csv(), "modes of %s" % os.path.relpath(CSV_PATH))
        return 0
    p0 = source_params()
    print_report(p0, "source parameter set (before the fit)")
    p = fit(p0)
    print("\nfree parameters: source -> fitted")
    for k in list(BOUNDS) + list(TIED):
        print("  %-26s %12.5g -> %12.5g %s" % (k, p0[k], p[k], SOURCE[k][1]))
    print()
    f = print_report(p, "fitted parameter set")
    worst = np.max(np.abs(f / np.array([m[3] for m in PUBLISHED]) - 1))
    print("\nlargest error %.2f %%" % (100 * worst))
    if "--write" in argv:
        write_csv(p)
        print("wrote", os.path.relpath(CSV_PATH))
    return 0 if worst < 0.05 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
