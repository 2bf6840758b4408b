#!/usr/bin/python3
"""Critical speed of the whole vehicle (car body, 2 bogies, 4 wheelsets) on 1:40 cones and
300 mm crowns: eigenvalues of the linearised equations against speed, against railfe's vehicle
dynamics module (time simulations, Kalker's linear creep).

The linear model is the 42-DOF rigid-body vehicle of vehicle_modes_fit.py (full_matrices(): the
calibrated parameter set of vehicle_parameters.csv, the wheelsets free; the wheelset centres and
axle boxes at R_NOMINAL = 0.46 m, the height railfe gives them, not the test car's 0.43 m) plus,
at each wheelset, the linearised wheel-rail forces at the static contact, with V as parameter.
Two versions of the contact terms:

  "classical": Wickens' equations (wickens_critical_speed.py, same profiles, same helpers):
      the wheelset's roll and vertical motion follow its lateral shift on the rigid rails
      (roll = -sigma y, railfe's sign: y > 0 lifts the right wheel), and per wheelset
        F_y = -2 f22 [(1 + kappa) y'/V - psi] - 2 f23 psi'/V - k_g y
        M_z = -2 f11 e (e psi'/V + lambda y / r0) + 2 f23 [(1 + kappa) y'/V - psi]
              - 2 f33 psi'/V
        F_x = -2 f11 (x' + r0 theta')/V,   M_theta = r0 F_x      (spin about the axle)
      f11 = G ab C11, f22 = G ab C22, f23 = G (ab)^1.5 C23, f33 = G (ab)^2 C33 at the static
      Hertz ellipse of each wheel; lambda, e, r0, sigma of wickens_critical_speed; kappa =
      r0 sigma; k_g = W sigma (W the wheelset's vertical load). The roll-slip term has the sign
      of railfe's kinematics (the contact point, r0 below the centre, moves with y' (1 + kappa):
      roll = -sigma y, slip_y = y' - r0 roll'), as wickens_critical_speed.py's; the yaw's
      lateral creepage is Wickens' psi (wickens_critical_speed's gamma = 1).
  "railfe": the same creepage and force formulas as railfe's contact element
      (contact/enforcement/wheel_rail_contact.cpp: swept velocity omega x p, creepages
      (slip_x, slip.t, omega.n)/V, Kalker linear forces along x, t = n x x and n, the contact
      search ignoring yaw, Hertz's normal spring), on the exact 2-D cone/crown geometry,
      differentiated numerically about the static contact: 6 DOFs per wheelset, nothing
      constrained. It adds to "classical" what railfe does besides Wickens: the yaw-neglected
      contact point (the yaw's lateral creepage is (1 + e tan(delta) / r0) psi: +4 %,
      wickens_critical_speed.YAW_CREEP, the reference of that script), the static
      spin creepage's forces and the loads' changes.

The railfe runs: the vehicle and Sections of vehicle_parameters.csv (as
inputs/verification/vehicle_modes/deck.xml) on the cone/crown profiles, Creep theory linear,
HHT alpha 0, time step 0.5 ms, a lateral bump of the rails (s = 12..14 m, sin^2; 1 mm below V_cr,
0.1 mm above) to start the motion. Measured on wheelset 1's lateral motion after the bump has
passed wheelset 4 and one more cycle: the growth per cycle from successive positive peaks (mean
over the last 6 cycles; the critical speed where it crosses 1), and the dominant poles of a
matrix-pencil fit (above V_cr two car-body modes grow at close frequencies and beat, which puts
the peak ratios several per cent off; the poles match the eigenvalues to 0.25 %).

Results (regenerate with `all`): car-body hunting (car body yaw 72 % of the kinetic energy, the
bogies' wheelsets in antiphase, 1.36 Hz, 43 m wavelength ~ the rigid bogie's kinematic 44.9 m)
sets V_cr = 58.71 m/s (linear, railfe kinematics) / 58.92 (classical) against 58.65 m/s from the
railfe runs (growth 0.919 at 55.78 m/s, 1.002 at 58.71 m/s). Stable at 83.33 m/s with yaw
dampers between car body and each bogie of FIX_YAW_DAMPING (railfe's 'secondary_rotation' block):
V_cr 104.4 m/s linear, bracketed by railfe's runs at 99.19 (0.880 per cycle) and 109.64 m/s
(1.117). See docs/data/vehicle_critical_speed.csv and docs/img/vehicle_critical_speed.png.

Usage:
  vehicle_critical_speed.py linear                     eigenvalues only (seconds)
  vehicle_critical_speed.py all RAILFE [--quick]       plus the railfe runs, CSV and chart
    --out-csv docs/data/vehicle_critical_speed.csv  --out-png docs/img/vehicle_critical_speed.png
Uses NumPy, SciPy, Matplotlib.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
import vehicle_modes_fit as vm  # noqa: E402
import wickens_critical_speed as wk  # noqa: E402

GRAVITY = 9.81
E, NU = wk.E, wk.NU
G_SHEAR = E / (2 * (1 + NU))
E_STAR = E / (2 * (1 - NU ** 2))
DELTA = wk.DELTA                 # cone angle atan(1/40)
CROWN = 0.3                      # rail crown radius (m)
RAIL_Y = 0.75                    # crown tops and running points at y = +-0.75 m
# The track's nominal rolling radius: the wheel radius at the running point, and the height of the
# wheelset centres (and axle boxes) both in the linear model and in the railfe decks (railfe
# refuses a vehicle whose Wheel radius differs from it).
R_NOMINAL = 0.46
GAUGE = 1.31884813001241
N_BODIES = 7
WHEELSET_BODIES = (3, 4, 5, 6)
X, Y, Z, RX, RY, RZ = range(6)


# ---------------------------------------------------------------- static contact, Kalker
def kalker4(a, b):
    """C11, C22, C23, C33 at a/b for NU: wickens_critical_speed.kalker() extended to all four
    (linear in the tabulated ratio, quadratic in Poisson's ratio)."""
    rows = [r for r in csv.reader(open(os.path.join(ROOT, "inputs/kalker/kalker_cij.csv")))
            if r and not r[0].startswith("#") and r[0] != "case"]
    case, ratio = ("a/b", a / b) if a <= b else ("b/a", b / a)
    table = sorted((float(r[1]), [float(x) for x in r[2:]]) for r in rows if r[0] == case)
    ratios = [t[0] for t in table]
    values = [np.interp(ratio, ratios, [t[1][i] for t in table]) for i in range(12)]
    nus = np.array([0, 0.25, 0.5])
    return tuple(np.polyval(np.polyfit(nus, values[3 * k:3 * k + 3], 2), NU) for k in range(4))


_KALKER_CACHE = {}


def kalker4_cached(a, b):
    key = round(a / b, 9)
    if key not in _KALKER_CACHE:
        _KALKER_CACHE[key] = kalker4(a, b)
    return _KALKER_CACHE[key]


def hertz_unit(A, B):
    """Semi-axes (a rolling, b lateral) and approach of Hertz's ellipse at N = 1 N (Johnson 4.2;
    a, b grow as N^(1/3), the approach as N^(2/3))."""
    small, large = min(A, B), max(A, B)

    def mismatch(g):
        m = 1 - g * g
        return (ellipe(m) / (g * g) - ellipk(m)) / (ellipk(m) - ellipe(m)) - large / small

    g = brentq(mismatch, 1e-3, 1 - 1e-12, xtol=1e-15, rtol=1e-15)
    m = 1 - g * g
    longer = (3 * (ellipk(m) - ellipe(m)) / m / (2 * np.pi * E_STAR * small)) ** (1 / 3)
    approach = 3 * ellipk(m) / (2 * np.pi * E_STAR * longer)
    a, b = (longer, g * longer) if A <= B else (g * longer, longer)
    return a, b, approach


def creep_coefficients(W):
    """f11, f22, f23, f33 of one wheel of a wheelset with vertical load W (N), at the static
    Hertz ellipse (A = cos(delta) / (2 r0), B = 1 / (2 R), as wickens_critical_speed)."""
    N = W / (2 * np.cos(DELTA))
    a, b = wk.hertz(np.cos(DELTA) / (2 * wk.R0), 1 / (2 * CROWN), N)
    C11, C22, C23, C33 = kalker4(a, b)
    ab = a * b
    return dict(a=a, b=b, N=N, f11=G_SHEAR * ab * C11, f22=G_SHEAR * ab * C22,
                f23=G_SHEAR * ab ** 1.5 * C23, f33=G_SHEAR * ab ** 2 * C33)


# ---------------------------------------------------------------- classical contact terms
def classical_contact(W, V, kappa_sign=1.0, spin=True):
    """(K, C) 6x6 of one wheelset's contact forces on [x, y, z, rx, ry, rz] in the Wickens form
    (rows and columns of z and rx empty: the constraint carries them)."""
    c = creep_coefficients(W)
    f11, f22, f23, f33 = c["f11"], c["f22"], c["f23"], c["f33"]
    if not spin:
        f23 = f33 = 0.0
    e, lam, r0 = wk.E_HALF, wk.CONICITY, wk.R0
    kappa = kappa_sign * r0 * wk.SIGMA
    K, C = np.zeros((6, 6)), np.zeros((6, 6))
    # forces on the wheelset f = -K q - C q'
    C[X, X] = 2 * f11 / V
    C[X, RY] = 2 * f11 * r0 / V
    C[RY, X] = 2 * f11 * r0 / V
    C[RY, RY] = 2 * f11 * r0 ** 2 / V
    C[Y, Y] = 2 * f22 * (1 + kappa) / V
    K[Y, RZ] = -2 * f22
    C[Y, RZ] = 2 * f23 / V
    K[Y, Y] = W * wk.SIGMA
    C[RZ, RZ] = 2 * f11 * e ** 2 / V + 2 * f33 / V
    K[RZ, Y] = 2 * f11 * e * lam / r0
    C[RZ, Y] = -2 * f23 * (1 + kappa) / V
    K[RZ, RZ] = 2 * f23
    return K, C


# ---------------------------------------------------------------- railfe's contact kinematics
def _rotation(phi):
    c, s = np.cos(phi), np.sin(phi)
    return np.array([[c, -s], [s, c]])


def _contact_geometry(side, y, z, phi, rail_top):
    """Cone wheel on crown, 2-D (yaw neglected as railfe's default search). side +1 right, -1
    left; the wheelset centre at (y, z) (z down) rolled by phi. Returns gap (m), the wheel's
    contact point relative to the centre (y, z), the normal from rail to wheel (y, z) and the
    wheel's rolling radius there."""
    R = _rotation(phi)
    outward = R @ np.array([side * np.sin(DELTA), np.cos(DELTA)])  # wheel surface -> rail
    on_line = np.array([y, z]) + R @ np.array([side * RAIL_Y, R_NOMINAL])
    centre = np.array([side * RAIL_Y, rail_top + CROWN])
    d = (centre - on_line) @ outward
    point = centre - d * outward - np.array([y, z])
    lateral_in_wheelset = (R.T @ point)[0]
    radius = R_NOMINAL + (RAIL_Y - side * lateral_in_wheelset) * np.tan(DELTA)
    return d - CROWN, point, -outward, radius


class RailfeContact:
    """One wheelset's contact forces as railfe forms them (see the file comment)."""

    def __init__(self, W, V, spin=True, kalker=None):
        self.V, self.spin = V, spin
        self.N0 = W / (2 * np.cos(DELTA))
        self.kalker = kalker or kalker4_cached
        r_centred = R_NOMINAL + CROWN * np.sin(DELTA) * np.tan(DELTA)
        approach = hertz_unit(np.cos(DELTA) / (2 * r_centred), 1 / (2 * CROWN))[2]
        gap0 = _contact_geometry(1, 0, 0, 0, 0)[0]
        self.rail_top = -(gap0 + approach * self.N0 ** (2 / 3)) / np.cos(DELTA)
        self.r_spin = _contact_geometry(1, 0, 0, 0, self.rail_top)[3]

    def forces(self, q, qd):
        """Generalised force on the wheelset [Fx, Fy, Fz, Mx, M_axle, Mz] at pose q and rates
        qd (relative to the rigid rails)."""
        _, y, z, phi, _, psi = q
        V = self.V
        axle = np.array([-np.sin(psi) * np.cos(phi), np.cos(psi) * np.cos(phi), np.sin(phi)])
        spin = -V / self.r_spin + qd[RY]
        omega = np.array([spin * axle[0] + qd[RX], spin * axle[1], spin * axle[2] + qd[RZ]])
        out = np.zeros(6)
        for side in (1, -1):
            gap, p2, n2, radius = _contact_geometry(side, y, z, phi, self.rail_top)
            au, bu, approach = hertz_unit(np.cos(DELTA) / (2 * radius), 1 / (2 * CROWN))
            N = (max(-gap, 0.0) / approach) ** 1.5
            a, b = au * np.cbrt(N), bu * np.cbrt(N)
            p = np.array([0.0, p2[0], p2[1]])
            n = np.array([0.0, n2[0], n2[1]])
            t = np.array([0.0, n[2], -n[1]])
            swept = np.cross(omega, p)
            slip = np.array([V + qd[X] + swept[0], qd[Y] + swept[1], qd[Z] + swept[2]])
            xi, eta, phis = slip[0] / V, slip @ t / V, (omega @ n) / V if self.spin else 0.0
            C11, C22, C23, C33 = self.kalker(a, b)
            ab = a * b
            root = np.sqrt(ab)
            Fx = -G_SHEAR * ab * C11 * xi
            Fy = -G_SHEAR * ab * (C22 * eta + root * C23 * phis)
            Mz = G_SHEAR * ab * root * (C23 * eta - root * C33 * phis) if self.spin else 0.0
            F = N * n + Fx * np.array([1.0, 0, 0]) + Fy * t
            M = np.cross(p, F) + Mz * n
            out += np.concatenate([F, [M[0], M @ axle, M[2]]])
        return out

    def matrices(self, h=1e-7, hv=1e-5):
        """(K, C) = -(df/dq, df/dq') at the static contact, central differences."""
        q0 = np.zeros(6)
        K, C = np.zeros((6, 6)), np.zeros((6, 6))
        for j in range(6):
            e = np.zeros(6)
            e[j] = h
            K[:, j] = -(self.forces(e, q0) - self.forces(-e, q0)) / (2 * h)
            e[j] = hv
            C[:, j] = -(self.forces(q0, e) - self.forces(q0, -e)) / (2 * hv)
        return K, C


# ---------------------------------------------------------------- the vehicle
def full_matrices(p):
    """vehicle_modes_fit.full_matrices(p) with the wheelset centres and axle boxes at R_NOMINAL
    (vehicle_modes_fit places them at its WHEEL_RADIUS, the test car's 0.43 m)."""
    saved = vm.WHEEL_RADIUS
    vm.WHEEL_RADIUS = R_NOMINAL
    try:
        return vm.full_matrices(p)
    finally:
        vm.WHEEL_RADIUS = saved


def parameters(**changes):
    p = vm.read_csv()
    p.update(changes)
    return p


def axle_load(p):
    total = p["car_body_mass"] + 2 * p["bogie_mass"] + 4 * p["wheelset_mass"]
    return total * GRAVITY / 4


def vehicle_system(p, V, model="railfe", yaw_damping=0.0, **options):
    """M, C, K of the vehicle on the rails at speed V, and the transformation T (q = T r) of the
    coordinates kept. yaw_damping: a rotational damper about z between car body and each bogie
    (N m s/rad), railfe's 'secondary_rotation' block."""
    M, K, C = full_matrices(p)
    for bogie in (1, 2):
        i, j = 6 * bogie + RZ, RZ
        C[i, i] += yaw_damping
        C[j, j] += yaw_damping
        C[i, j] -= yaw_damping
        C[j, i] -= yaw_damping
    W = axle_load(p)
    if model == "railfe":
        Kc, Cc = RailfeContact(W, V, **options).matrices()
    else:
        Kc, Cc = classical_contact(W, V, **options)
    for body in WHEELSET_BODIES:
        s = slice(6 * body, 6 * body + 6)
        K[s, s] += Kc
        C[s, s] += Cc
    n = 6 * N_BODIES
    if model == "railfe":
        return M, C, K, np.eye(n)
    keep = [i for i in range(n) if not (i // 6 in WHEELSET_BODIES and i % 6 in (Z, RX))]
    T = np.zeros((n, len(keep)))
    for col, i in enumerate(keep):
        T[i, col] = 1.0
        if i // 6 in WHEELSET_BODIES and i % 6 == Y:
            T[i - Y + RX, col] = -wk.SIGMA  # railfe's sign: y > 0 lifts the right wheel
    return T.T @ M @ T, T.T @ C @ T, T.T @ K @ T, T


def eigen(p, V, **kw):
    M, C, K, T = vehicle_system(p, V, **kw)
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    lam, vec = np.linalg.eig(A)
    return lam, T @ vec[:n, :], M


def lateral_modes(p, V, **kw):
    """Eigenvalues and modes of the oscillatory modes below 100 Hz whose kinetic energy is mostly
    in the lateral plane (y, roll, yaw): the longitudinal and vertical modes (the free-rolling
    wheelsets let the vehicle's longitudinal modes at 1.02 and 1.25 Hz go almost undamped) are
    left out."""
    lam, vec, _ = eigen(p, V, **kw)
    mass = np.diag(full_matrices(p)[0])
    ok = (lam.imag > 0.5) & (np.abs(lam) < 2 * np.pi * 100)
    keep = []
    for i in np.flatnonzero(ok):
        e = (np.abs(vec[:, i]) ** 2 * mass).reshape(N_BODIES, 6)
        if e[:, [Y, RX, RZ]].sum() > 0.5 * e.sum():
            keep.append(i)
    return lam[keep], vec[:, keep]


def hunting(p, V, **kw):
    """The lateral mode with the largest real part: eigenvalue (1/s), damping ratio, mode (the
    42 displacements, complex)."""
    lam, vec = lateral_modes(p, V, **kw)
    i = int(np.argmax(lam.real))
    return lam[i], -lam[i].real / abs(lam[i]), vec[:, i]


def least_damping(p, V, **kw):
    """The smallest damping ratio of the lateral modes."""
    lam, _ = lateral_modes(p, V, **kw)
    return float(np.min(-lam.real / np.abs(lam)))


def hunting_branch(p, speeds, start, **kw):
    """The hunting mode followed over the ascending grid \p speeds from \p start (one of them;
    there the lateral mode with the largest real part) up and down, taking at each speed the
    eigenvalue nearest the last (keep the grid fine: two lateral modes cross above V_cr).
    Returns the eigenvalues in the order of \p speeds."""
    speeds = np.asarray(speeds, float)
    i0 = int(np.argmin(abs(speeds - start)))
    lam = np.zeros(len(speeds), complex)
    for path in (range(i0, len(speeds)), range(i0, -1, -1)):
        last = None
        for i in path:
            values, _ = lateral_modes(p, speeds[i], **kw)
            j = int(np.argmax(values.real)) if last is None else int(np.argmin(abs(values - last)))
            lam[i] = last = values[j]
    return lam


def critical_speed(p, lo=20.0, hi=200.0, **kw):
    f = lambda V: hunting(p, V, **kw)[0].real  # noqa: E731
    speeds = np.arange(lo, hi + 0.5, 1.0)
    values = [f(V) for V in speeds]
    for i in range(len(speeds) - 1):
        if values[i] < 0 <= values[i + 1]:
            return brentq(f, speeds[i], speeds[i + 1], xtol=1e-4)
    return float("nan")


def describe_mode(p, vec):
    """Kinetic-energy shares of the lateral-plane motions (y, roll, yaw) per body, and the
    wheelsets' amplitude and phase of y relative to wheelset 1."""
    M = full_matrices(p)[0]
    e = np.abs(vec) ** 2 * np.diag(M)
    e = e / e.sum()
    shares = e.reshape(N_BODIES, 6)
    lines = []
    for b, name in enumerate(vm.BODY_NAMES):
        s = shares[b]
        if s.sum() > 0.01:
            lines.append("%-12s %4.0f%% (y %2.0f, roll %2.0f, yaw %2.0f, other %2.0f)" % (
                name, 100 * s.sum(), 100 * s[Y], 100 * s[RX], 100 * s[RZ],
                100 * (s.sum() - s[Y] - s[RX] - s[RZ])))
    ref = vec[6 * 3 + Y]
    rel = [vec[6 * b + Y] / ref for b in WHEELSET_BODIES]
    lines.append("wheelset y relative to wheelset 1: " + ", ".join(
        "%.2f@%+.0fdeg" % (abs(r), np.degrees(np.angle(r))) for r in rel))
    car = vec[Y] / ref, vec[RZ] * p["half_bogie_spacing"] / ref
    lines.append("car body y / w1 y = %.2f@%+.0fdeg, car body yaw x a / w1 y = %.2f@%+.0fdeg" % (
        abs(car[0]), np.degrees(np.angle(car[0])), abs(car[1]), np.degrees(np.angle(car[1]))))
    return lines


# ---------------------------------------------------------------- railfe runs
DECK = """<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="vehicle critical speed, V = {speed} m/s"/>
{vehicle}  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="vehicle dynamics"/>
      <ParameterList name="Profiles">
        <Parameter name="Rail" type="string" value="{root}/inputs/profiles/circ_r300.prr"/>
        <Parameter name="Wheel" type="string" value="{root}/inputs/verification/wheelset_cone_on_crown/cone_wheel.txt"/>
      </ParameterList>
      <ParameterList name="Track">
        <Parameter name="Gauge" type="double" value="{gauge}"/>
      </ParameterList>
      <ParameterList name="Contact">
        <Parameter name="Creep theory" type="string" value="linear"/>
      </ParameterList>
      <Parameter name="Speed" type="double" value="{speed}"/>
      <Parameter name="End time" type="double" value="{end}"/>
      <Parameter name="Time step" type="double" value="{step}"/>
      <Parameter name="History interval" type="double" value="0.005"/>
      <Parameter name="Lateral irregularity" type="string" value="{bump}*(x &gt; 12)*(x &lt; 14)*sin(3.14159265358979*(x-12)/2)^2"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""

def measure_growth(t, y, start, last_cycles=6):
    """Growth per cycle of y(t) after \p start: geometric mean ratio of successive positive
    peaks (one per cycle between upward zero crossings) over the last \p last_cycles cycles,
    its period (s) and the last peak (m)."""
    keep = t >= start
    t, y = t[keep], y[keep]
    up = np.flatnonzero((y[:-1] < 0) & (y[1:] >= 0))
    crossings = t[up] - y[up] * (t[up + 1] - t[up]) / (y[up + 1] - y[up])
    peaks = [y[up[i]:up[i + 1] + 1].max() for i in range(len(up) - 1)]
    if len(peaks) < 3:
        return float("nan"), float("nan"), float("nan")
    use = peaks[-(last_cycles + 1):]
    growth = (use[-1] / use[0]) ** (1.0 / (len(use) - 1))
    period = (crossings[-1] - crossings[-len(use)]) / (len(use) - 1)
    return growth, period, peaks[-1]


def matrix_pencil(t, y, order=8):
    """Poles s (1/s) and complex amplitudes of y(t) on a uniform t as a sum of \p order damped
    exponentials (Hua and Sarkar's matrix pencil): two modes of close frequency that both grow
    (above V_cr) beat, and the peak ratios then err by several per cent; the poles do not."""
    dt, n = t[1] - t[0], len(y)
    scale = np.max(np.abs(y))
    L = n // 3
    Y = np.array([y[i:i + L + 1] / scale for i in range(n - L)])
    V = np.linalg.svd(Y, full_matrices=False)[2][:order].conj().T
    z = np.linalg.eigvals(np.linalg.pinv(V[:-1]) @ V[1:])
    s = np.log(z) / dt
    s = s[np.abs(s.real) < 10]
    a = np.linalg.lstsq(np.exp(np.outer(t - t[0], s)), (y / scale).astype(complex),
                        rcond=None)[0]
    return s, a * scale


def dominant_poles(t, y, start, count=2):
    """The \p count oscillatory poles of y after \p start with the largest amplitude at the end of
    the record: [(frequency Hz, growth per cycle), ...]."""
    keep = t >= start
    t, y = t[keep][::2], y[keep][::2]
    s, a = matrix_pencil(t, y)
    weight = np.abs(a) * np.exp(s.real * (t[-1] - t[0]))
    out = []
    for i in np.argsort(-weight):
        if s[i].imag > 0.5 and len(out) < count:
            out.append((s[i].imag / 2 / np.pi, np.exp(2 * np.pi * s[i].real / s[i].imag)))
    return out


def simulate(railfe, p, V, work, yaw_damping=0.0, cycles=16, step=0.0005, bump=0.001,
             frequency=None):
    """Runs railfe at V (m/s); returns the growth per cycle of wheelset 1's lateral motion from
    its peaks, their frequency (Hz), the last peak (m), and the two dominant poles (matrix
    pencil, frequency and growth per cycle). Time step 0.5 ms: at 1 ms the Newton iteration of railfe's
    contact fails now and then on this case (e.g. V = 52.821 m/s, t = 1.506 s) although the
    motion is 0.1 mm; a run that fails is repeated at half the step."""
    frequency = frequency or 1.5
    passed = (14 + p["half_bogie_spacing"] + p["half_wheelbase"]) / V  # bump behind wheelset 4
    end = passed + cycles / frequency
    # The wheelset centres at the track's nominal radius R_NOMINAL, as railfe requires and as the
    # linear model (full_matrices) takes them.
    fields = dict(root=ROOT, speed="%.4f" % V, end="%.3f" % end, step=step, gauge=GAUGE,
                  bump=bump, vehicle=vm.vehicle_deck_xml(p, wheel_radius=R_NOMINAL,
                                                          yaw_damping=yaw_damping))
    tag = "v%.3f_c%.0f" % (V, yaw_damping)
    deck = os.path.join(work, tag + ".xml")
    with open(deck, "w") as f:
        f.write(DECK.format(**fields))
    out = os.path.join(work, tag)
    done = subprocess.run([railfe, deck, "--output", out, "--quiet"])
    if done.returncode != 0:
        if step < 0.0002:
            raise RuntimeError("railfe failed on " + deck)
        print("  railfe failed at time step %g s; again at %g s" % (step, step / 2))
        return simulate(railfe, p, V, work, yaw_damping, cycles, step / 2, bump, frequency)
    data = np.genfromtxt(os.path.join(out, "run_wheelsets.csv"), delimiter=",", names=True)
    start = passed + 1.0 / frequency
    growth, period, amplitude = measure_growth(data["time_s"], data["w1_y_m"], start)
    return dict(growth=growth, frequency=1 / period, amplitude=amplitude,
                poles=dominant_poles(data["time_s"], data["w1_y_m"], start))


def crossing(speeds, growth):
    """Speed where the growth per cycle crosses 1 (linear interpolation), nan if none."""
    for i in range(len(speeds) - 1):
        if growth[i] < 1 <= growth[i + 1]:
            return float(np.interp(1.0, growth[i:i + 2], speeds[i:i + 2]))
    return float("nan")


# ---------------------------------------------------------------- reports
def single_wheelset_check():
    """wickens_critical_speed's wheelset in the "railfe" contact model and its variants
    (railfe's simulation: 80.44 m/s, docs/img/wickens_critical_speed.csv)."""
    W = wk.MASS * GRAVITY + wk.AXLE_LOAD
    Ms = np.diag([wk.MASS] * 3 + [800.0, 100.0, wk.YAW_INERTIA])
    Ks = np.zeros((6, 6))
    Ks[X, X], Ks[Y, Y] = 2 * wk.KX_BOX, 2 * wk.KY_BOX
    Ks[RZ, RZ] = 2 * wk.KX_BOX * wk.HALF_SPACING ** 2

    def growth(V, spin):
        Kc, Cc = RailfeContact(W, V, spin=spin).matrices()
        A = np.block([[np.zeros((6, 6)), np.eye(6)],
                      [-np.linalg.solve(Ms, Ks + Kc), -np.linalg.solve(Ms, Cc)]])
        lam = np.linalg.eigvals(A)
        lam = lam[(lam.imag > 0.5) & (np.abs(lam) < 2 * np.pi * 100)]
        return lam.real.max()
    out = {}
    for spin in (True, False):
        out[spin] = brentq(lambda V: growth(V, spin), 50, 120, xtol=1e-4)
    return out


# The stabilising change: yaw dampers (longitudinal dampers between car body and bogie frame at a
# lateral arm l, n per bogie) give the bogie a yaw damping n c l^2 against the car body; railfe
# takes it as a rotational damper about z (Mesh/Vehicle 'Secondary rotation', Damping
# {0,0,0,0,0,c}), without the dampers' series stiffness. 4.0 MN m s/rad is e.g. 4 dampers (2 a
# side) of 550 kN s/m at l = 1.35 m. Typical values: 300 kN s/m first-stage damping, 10 MN/m series
# stiffness, 1.35 m half arm (Table 2 of "Numerical Investigation into the Critical Speed and
# Frequency of the Hunting Motion in Railway Vehicle System", Mathematical Problems in
# Engineering 2019, 7163732, hindawi.com/journals/mpe/2019/7163732/tab2/, a car with the same
# a = 8.75 m and b = 1.25 m). One pair of those (1.1 MN m s/rad) is not enough here.
FIX_YAW_DAMPING = 4.0e6      # N m s/rad per bogie
YAW_DAMPER_ARM = 1.35         # m


def equivalent_damping_ratio(growth):
    """Damping ratio of a mode that grows by \p growth per cycle (growth = exp(-2 pi zeta /
    sqrt(1 - zeta^2)))."""
    d = np.log(growth)
    return -d / np.sqrt(4 * np.pi ** 2 + d * d)


def linear_report(p):
    W = axle_load(p)
    c = creep_coefficients(W)
    print("axle load %.1f N; per wheel N %.1f N, a %.3f mm, b %.3f mm; f11 %.4g N, f22 %.4g N, "
          "f23 %.4g N m, f33 %.4g N m2" % (W, c["N"], 1e3 * c["a"], 1e3 * c["b"], c["f11"],
                                            c["f22"], c["f23"], c["f33"]))
    sw = single_wheelset_check()
    print("single wheelset of wickens_critical_speed: railfe-kinematics model %.3f m/s (%.3f "
          "without spin creep); that script's 2-DOF reference (yaw creep x %.4f) %.3f, classical "
          "Wickens %.3f; railfe's simulation 80.44" % (
              sw[True], sw[False], wk.YAW_CREEP, wk.reference_critical_speed(),
              wk.reference_critical_speed(yaw_creep=1.0)))
    Vc = {}
    for label, kw in (("railfe", dict(model="railfe")),
                      ("railfe, no spin creep", dict(model="railfe", spin=False)),
                      ("classical", dict(model="classical")),
                      ("classical, no spin creep", dict(model="classical", spin=False)),
                      ("classical, (1 - kappa)", dict(model="classical", kappa_sign=-1.0))):
        Vc[label] = critical_speed(p, **kw)
        lam, zeta, vec = hunting(p, Vc[label] + 1e-3, **kw)
        print("vehicle, %-26s V_cr %.3f m/s, hunting %.3f Hz, wavelength %.2f m" % (
            label, Vc[label], lam.imag / 2 / np.pi, 2 * np.pi * Vc[label] / lam.imag))
    for V in (Vc["railfe"] + 1e-3, 83.333):
        lam, zeta, vec = hunting(p, V, model="railfe")
        print("hunting mode at %.2f m/s (railfe model): %.3f Hz, damping ratio %.4f" % (
            V, lam.imag / 2 / np.pi, zeta))
        for line in describe_mode(p, vec):
            print("  " + line)
    return Vc


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("what", choices=["linear", "all"])
    parser.add_argument("railfe", nargs="?")
    parser.add_argument("--quick", action="store_true", help="fewer railfe runs")
    parser.add_argument("--out-csv", default=os.path.join(ROOT, "docs", "data",
                                                          "vehicle_critical_speed.csv"))
    parser.add_argument("--out-png", default=os.path.join(ROOT, "docs", "img",
                                                          "vehicle_critical_speed.png"))
    args = parser.parse_args()
    p = parameters()
    Vc = linear_report(p)
    fix = dict(yaw_damping=FIX_YAW_DAMPING)
    Vfix = critical_speed(p, model="railfe", **fix)
    lam, zeta, _ = hunting(p, 83.333, model="railfe", **fix)
    per_damper = FIX_YAW_DAMPING / (4 * YAW_DAMPER_ARM ** 2)
    print("fix: yaw dampers %.3g N m s/rad per bogie (4 dampers of %.0f kN s/m at +-%.2f m): "
          "V_cr %.2f m/s; at 83.33 m/s damping ratio %.4f (%.3f Hz)" % (
              FIX_YAW_DAMPING, per_damper / 1e3, YAW_DAMPER_ARM, Vfix, zeta, lam.imag / 2 / np.pi))
    if args.what == "linear":
        return 0
    if not args.railfe:
        parser.error("'all' needs the railfe binary")

    grid = np.arange(30.0, 130.01, 0.5)
    curves = {}
    for case, kw, q in (("base", {}, p), ("yaw dampers", fix, p),
                        ("c_sx 250 kN s/m", {}, parameters(secondary_damping_x=2.5e5))):
        start = critical_speed(q, model="railfe", **kw) + 1.0
        branch = hunting_branch(q, grid, start, model="railfe", **kw)
        least = [least_damping(q, V, model="railfe", **kw) for V in grid]
        curves[case] = (branch, np.array(least))

    factors = [0.9, 1.0, 1.1] if args.quick else [0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.2]
    runs = [("base", f * Vc["railfe"], {}) for f in factors] + [("base", 83.333, {})]
    runs += [("yaw dampers", 83.333, fix)]
    if not args.quick:
        runs += [("yaw dampers", f * Vfix, fix) for f in (0.95, 1.05)]
        runs += [("c_sx 250 kN s/m", 83.333, {"secondary_damping_x": 2.5e5})]
    sims = []
    with tempfile.TemporaryDirectory() as work:
        for case, V, kw in runs:
            q = parameters(**{k: v for k, v in kw.items() if k != "yaw_damping"})
            yd = kw.get("yaw_damping", 0.0)
            # the eigenvalue at V itself, on the branch that crosses at V_cr
            sub = np.sort(np.append(grid, V))
            start = critical_speed(q, model="railfe", yaw_damping=yd) + 1.0
            lam = hunting_branch(q, sub, start, model="railfe", yaw_damping=yd)[
                int(np.argmin(abs(sub - V)))]
            f_lin = lam.imag / 2 / np.pi
            g_lin = np.exp(2 * np.pi * lam.real / lam.imag)
            cycles = 16 if g_lin < 1.2 else max(7, int(np.log(20) / np.log(g_lin)) + 1)
            r = simulate(args.railfe, q, V, work, yaw_damping=yd, cycles=cycles,
                         bump=1e-3 if g_lin < 1 else 1e-4, frequency=f_lin)
            lateral, _ = lateral_modes(q, V, model="railfe", yaw_damping=yd)
            near = lateral[np.argmin(abs(lateral.imag / 2 / np.pi - r["poles"][0][0]))]
            r.update(case=case, V=V, g_branch=g_lin, f_branch=f_lin,
                     g_near=np.exp(2 * np.pi * near.real / near.imag), f_near=near.imag / 2 / np.pi)
            sims.append(r)
            print("railfe %-16s V %7.3f m/s: peaks %.4f/cycle at %.3f Hz; poles %s; linear: "
                  "hunting branch %.4f at %.3f Hz, mode nearest the first pole %.4f at %.3f Hz"
                  % (case, V, r["growth"], r["frequency"],
                     ", ".join("%.4f at %.3f Hz" % (g, f) for f, g in r["poles"]),
                     g_lin, f_lin, r["g_near"], r["f_near"]), flush=True)
    base = sorted([r for r in sims if r["case"] == "base"], key=lambda r: r["V"])
    Vsim = crossing([r["V"] for r in base], [r["growth"] for r in base])
    Vpole = crossing([r["V"] for r in base], [r["poles"][0][1] for r in base])
    print("railfe critical speed from the matrix-pencil poles: %.3f m/s" % Vpole)
    print("critical speed: linear (railfe kinematics) %.3f m/s, classical %.3f m/s, railfe "
          "simulations %.3f m/s (%+.2f %%)" % (Vc["railfe"], Vc["classical"], Vsim,
                                               100 * (Vsim / Vc["railfe"] - 1)))
    write_csv(args.out_csv, grid, curves, sims, Vc, Vsim, Vfix)
    chart(args.out_png, grid, curves, sims, Vc, Vsim, Vfix)
    return 0


def write_csv(path, grid, curves, sims, Vc, Vsim, Vfix):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("# Vehicle of vehicle_parameters.csv on 1:40 cones / 300 mm crowns, Kalker linear "
                "creep: regression/studies/vehicle_critical_speed.py\n")
        f.write("# critical speed: linear model (railfe kinematics) %.4f m/s, classical (Wickens) "
                "%.4f m/s, railfe time simulations (peak ratios of wheelset 1's y) %.4f m/s; with "
                "yaw dampers %.4g N m s/rad per bogie: linear %.4f m/s\n" % (
                    Vc["railfe"], Vc["classical"], Vsim, FIX_YAW_DAMPING, Vfix))
        f.write("# source linear: hunting_* = the hunting branch (the mode that crosses at V_cr, "
                "followed over speed), least_lateral_damping_ratio_1 = least damped lateral mode. "
                "source railfe: growth from peak ratios (damping ratio = the equivalent one), "
                "pole1/pole2 = dominant poles of a matrix-pencil fit, linear_* = the linear "
                "lateral mode nearest pole 1 in frequency\n")
        f.write("case,source,speed_m_per_s,hunting_frequency_Hz,hunting_damping_ratio_1,"
                "hunting_growth_per_cycle_1,least_lateral_damping_ratio_1,"
                "pole1_frequency_Hz,pole1_growth_per_cycle_1,pole2_frequency_Hz,"
                "pole2_growth_per_cycle_1,linear_frequency_Hz,linear_growth_per_cycle_1\n")
        for case, (branch, least) in curves.items():
            for V, lam, z in zip(grid, branch, least):
                g = np.exp(2 * np.pi * lam.real / lam.imag)
                f.write("%s,linear,%.4f,%.5f,%.6f,%.6f,%.6f,,,,,,\n" % (
                    case, V, lam.imag / 2 / np.pi, -lam.real / abs(lam), g, z))
        for r in sims:
            poles = list(r["poles"]) + [(float("nan"), float("nan"))] * 2
            f.write("%s,railfe,%.4f,%.5f,%.6f,%.6f,,%.5f,%.6f,%.5f,%.6f,%.5f,%.6f\n" % (
                r["case"], r["V"], r["frequency"], equivalent_damping_ratio(r["growth"]),
                r["growth"], poles[0][0], poles[0][1], poles[1][0], poles[1][1], r["f_near"],
                r["g_near"]))


def chart(path, grid, curves, sims, Vc, Vsim, Vfix):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8.5, 7.2))
    colours = {"base": "C0", "yaw dampers": "C2", "c_sx 250 kN s/m": "C3"}
    labels = {"base": "calibrated vehicle",
              "yaw dampers": "+ yaw dampers %.1f MN m s/rad per bogie" % (FIX_YAW_DAMPING / 1e6),
              "c_sx 250 kN s/m": "+ 250 kN s/m longitudinal damping per air spring"}
    for case, (branch, least) in curves.items():
        ax.plot(grid, -branch.real / abs(branch), "-", color=colours[case],
                label="%s: hunting mode, linear" % labels[case])
        if case != "c_sx 250 kN s/m":
            ax.plot(grid, least, ":", color=colours[case], lw=1.2,
                    label="%s: least damped lateral mode, linear" % labels[case])
    for case in colours:
        pts = [r for r in sims if r["case"] == case]
        if pts:
            ax.plot([r["V"] for r in pts], [equivalent_damping_ratio(r["poles"][0][1])
                                             for r in pts],
                    "o" if case == "base" else ("D" if case == "yaw dampers" else "s"),
                    color=colours[case], mfc="none", ms=7, mew=1.5,
                    label="railfe, %s (dominant pole of wheelset 1's y)" % labels[case])
    ax.axhline(0, color="gray", lw=0.8)
    ax.axvline(83.333, color="k", ls="--", lw=0.8)
    ax.text(84.2, 0.16, "300 km/h", fontsize=8)
    ax.set_xlabel("speed (m/s)")
    ax.set_ylabel("damping ratio")
    ax.set_ylim(-0.14, 0.18)
    ax.set_xlim(grid[0], grid[-1])

    def to_growth(z):
        z = np.clip(z, -0.95, 0.95)
        return np.exp(-2 * np.pi * z / np.sqrt(1 - z * z))

    sec = ax.secondary_yaxis("right", functions=(
        to_growth, lambda g: equivalent_damping_ratio(np.clip(g, 1e-6, None))))
    sec.set_ylabel("growth per cycle")
    sec.set_yticks([0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0])
    ax.set_title("Vehicle on 1:40 cones / 300 mm crowns, Kalker linear creep: critical speed "
                 "%.1f m/s linear, %.1f m/s railfe;\nwith yaw dampers %.1f m/s linear "
                 "(car-body hunting 1.36 Hz; classical Wickens terms: %.1f m/s)"
                 % (Vc["railfe"], Vsim, Vfix, Vc["classical"]), fontsize=9)
    ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=1)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
