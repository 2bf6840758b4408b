#!/usr/bin/python3
"""Critical speed of a single suspended wheelset: railfe's time simulation against the
eigenvalues of Wickens' linearised equations with railfe's contact kinematics (Wickens 1965;
Knothe & Boehm 1999).

The wheelset (1:40 cones on 300 mm crowns, 100 kN axle load, lateral and longitudinal axle-box
springs, Kalker's linear creep) runs at several speeds from a 1 mm lateral shift; the growth of
its lateral oscillation per cycle is measured from each run (wheelset dynamics module). The
reference is the two-degree-of-freedom model

  m y'' + 2 f22 ((1 + kappa) y'/V - gamma psi) + (k_y + k_g) y = 0
  I psi'' + 2 f11 e (e psi'/V + lambda y / r0) + k_psi psi = 0

with f11 = G a b C11 and f22 = G a b C22 at the static contact (Hertz ellipse and Kalker's
coefficients computed here, independently of railfe), lambda the cones' equivalent conicity and
e, r0, the roll per shift sigma from the rigid contact table of the same profiles
(wheelset_cone_on_crown). k_g = W |sigma| is the gravitational stiffness of the cones' normal
forces. kappa = r0 |sigma| is the lateral slip the wheelset's roll gives the contact point: it
lies r0 below the axle and moves with the roll (roll = -sigma y, railfe's sign: y > 0 lifts the
right wheel), so it slides sideways at y' - r0 roll' = y' (1 + kappa).

gamma weights the lateral creepage of the yaw against that of the shift. Wickens has gamma = 1
("classical" below). railfe's contact search neglects the yaw (Contact/Yaw "neglected", its
default), so the contact point stays in the axle's vertical plane, e beside and r0 below the
centre. There the yawed wheel's rolling gives it a vertical velocity V psi e / r0 as well as the
lateral -V psi. Along the contact's lateral direction, tilted by the cone angle delta, that makes
gamma = 1 + e tan(delta) / r0 = 1.0403 (YAW_CREEP; the yaw term of the "railfe" contact model of
vehicle_critical_speed.py, which differentiates railfe's creepage formulas). gamma = YAW_CREEP is
the reference ("railfe's kinematics"). Critical speeds: 80.43 m/s with gamma = YAW_CREEP,
82.04 m/s with the classical gamma = 1; railfe's simulated 80.44 m/s. The 6-DOF "railfe" model
of vehicle_critical_speed.py (loads' changes and spin creep included) gives 80.46 m/s. Spin creep
is left out of this reference (its terms are ~1e-3 of the others here).

static_response() keeps gamma = 1 by default: inputs/verification/wheelset_wickens_critical_speed
cites its classical values. railfe's canted-track yaw (-0.6276 mrad) agrees with those (-0.6268
mrad) and not with gamma = YAW_CREEP (-0.6029 mrad), which is not explained yet (the 6-DOF
"railfe" model gives -0.6005 mrad). The yaw of the pushed case (-0.0745 mrad) agrees with
YAW_CREEP (-0.0744) rather than with gamma = 1 (-0.0773).

Usage: wickens_critical_speed.py RAILFE [--out DIR] [--quick]
Writes DIR/wickens_critical_speed.csv and DIR/wickens_critical_speed.png (default DIR: docs/img
for the chart, the CSV beside it). The CSV's *_eigenvalues columns are the reference (gamma =
YAW_CREEP), *_wickens the classical model (gamma = 1).
"""
import argparse
import csv
import os
import subprocess
import tempfile

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))

# The wheelset and its suspension (as the deck below).
MASS, YAW_INERTIA, AXLE_LOAD, GRAVITY = 1500.0, 800.0, 100e3, 9.81
KX_BOX, KY_BOX, HALF_SPACING = 0.3e6, 0.2e6, 1.0
E, NU = 210e9, 0.3
# Geometry of 1:40 cones on 300 mm crowns (wheelset_cone_on_crown's table and conicity).
E_HALF = 0.742502342651939     # half the distance between the contact points (m)
R0 = 0.46 + 0.3 * np.sin(np.arctan(1 / 40)) / 40  # centred rolling radius (m)
CONICITY = 0.025652248765968468  # equivalent conicity at 1 mm (EN 15302)
SIGMA = 0.00034199833222627892 / 0.01  # |roll| per lateral shift (rad/m)
DELTA = np.arctan(1 / 40)
# Lateral creepage per yaw of railfe's yaw-neglected contact search, relative to the shift's
# (module docstring); 1 in Wickens' classical equations.
YAW_CREEP = 1 + E_HALF * np.tan(DELTA) / R0


def hertz(A, B, N):
    """Semi-axes (a along the rolling direction, b across) of Hertz's ellipse (Johnson 4.2)."""
    Es = E / (2 * (1 - NU ** 2))
    small, large = min(A, B), max(A, B)

    def mismatch(g):
        m = 1 - g * g
        return (ellipe(m) / (g * g) - ellipk(m)) / (ellipk(m) - ellipe(m)) - large / small

    g = brentq(mismatch, 1e-3, 1 - 1e-12)
    m = 1 - g * g
    longer = (3 * N * (ellipk(m) - ellipe(m)) / m / (2 * np.pi * Es * small)) ** (1 / 3)
    return (longer, g * longer) if A <= B else (g * longer, longer)


def kalker(a, b):
    """C11, C22 at a/b for NU: linear in the tabulated ratio, quadratic in Poisson's ratio."""
    rows = [r for r in csv.reader(open(os.path.join(ROOT, "inputs/kalker/kalker_cij.csv")))
            if r and not r[0].startswith("#") and r[0] != "case"]
    case, ratio = ("a/b", a / b) if a <= b else ("b/a", b / a)
    table = sorted((float(r[1]), [float(x) for x in r[2:]]) for r in rows if r[0] == case)
    ratios = [t[0] for t in table]
    values = [np.interp(ratio, ratios, [t[1][i] for t in table]) for i in range(12)]
    nus = np.array([0, 0.25, 0.5])

    def at(first):
        return np.polyval(np.polyfit(nus, values[first:first + 3], 2), NU)
    return at(0), at(3)


def creep_coefficients():
    W = MASS * GRAVITY + AXLE_LOAD
    N = W / (2 * np.cos(DELTA))
    a, b = hertz(np.cos(DELTA) / (2 * R0), 1 / (2 * 0.3), N)
    C11, C22 = kalker(a, b)
    G = E / (2 * (1 + NU))
    return G * a * b * C11, G * a * b * C22, W


def eigen_growth(V, yaw_creep=YAW_CREEP):
    """Largest real part (1/s), its frequency (rad/s) and the growth per cycle of the hunting
    mode at speed V; \p yaw_creep is gamma (1: the classical equations)."""
    f11, f22, W = creep_coefficients()
    kappa, kg = R0 * SIGMA, W * SIGMA
    ky, kpsi = 2 * KY_BOX, 2 * KX_BOX * HALF_SPACING ** 2
    M = np.diag([MASS, YAW_INERTIA])
    C = np.array([[2 * f22 * (1 + kappa) / V, 0], [0, 2 * f11 * E_HALF ** 2 / V]])
    K = np.array([[ky + kg, -2 * f22 * yaw_creep], [2 * f11 * E_HALF * CONICITY / R0, kpsi]])
    A = np.block([[np.zeros((2, 2)), np.eye(2)],
                  [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    lam = np.linalg.eigvals(A)
    lam = lam[np.imag(lam) > 1e-9]
    top = lam[np.argmax(np.real(lam))]
    return np.real(top), np.imag(top), np.exp(2 * np.pi * np.real(top) / np.imag(top))


def static_response(force, frame_yaw, yaw_creep=1.0):
    """Lateral shift and yaw (rad) at rest under a lateral force on the centre (N) with the
    springs' rest yaw \p frame_yaw: the stiffness part of the same linear equations, whose creep
    terms (the conicity's yaw moment, the yaw's lateral creep force) hold at any speed. The
    classical gamma = 1 by default (the verification deck's values; see the module docstring)."""
    f11, f22, W = creep_coefficients()
    kg = W * SIGMA
    ky, kpsi = 2 * KY_BOX, 2 * KX_BOX * HALF_SPACING ** 2
    K = np.array([[ky + kg, -2 * f22 * yaw_creep], [2 * f11 * E_HALF * CONICITY / R0, kpsi]])
    return np.linalg.solve(K, [force, kpsi * frame_yaw])


def reference_critical_speed(yaw_creep=YAW_CREEP):
    return brentq(lambda V: eigen_growth(V, yaw_creep)[0], 5, 500)


DECK = """<ParameterList name="railfe">
  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="wheelset dynamics"/>
      <ParameterList name="Profiles">
        <Parameter name="Rail" type="string" value="{root}/inputs/profiles/circ_r300.prr"/>
        <Parameter name="Wheel" type="string"
                   value="{root}/inputs/verification/wheelset_cone_on_crown/cone_wheel.txt"/>
      </ParameterList>
      <ParameterList name="Track">
        <Parameter name="Gauge" type="double" value="1.31884813001241"/>
      </ParameterList>
      <ParameterList name="Wheelset">
        <Parameter name="Axle load" type="double" value="100e3"/>
      </ParameterList>
      <ParameterList name="Suspension">
        <Parameter name="Stiffness" type="Array(double)" value="{{0.3e6, 0.2e6, 0}}"/>
        <Parameter name="Half spacing" type="double" value="1.0"/>
      </ParameterList>
      <ParameterList name="Contact">
        <Parameter name="Creep theory" type="string" value="linear"/>
      </ParameterList>
      <Parameter name="Alpha" type="double" value="0"/>
      <Parameter name="Speed" type="double" value="{speed}"/>
      <Parameter name="Initial lateral shift" type="double" value="0.001"/>
      <Parameter name="End time" type="double" value="{end}"/>
      <Parameter name="Time step" type="double" value="{step}"/>
      <Parameter name="Chart" type="bool" value="false"/>
      <Parameter name="History interval" type="double" value="0.01"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def simulate(railfe, speed, work, step=0.002):
    frequency = eigen_growth(speed)[1] / (2 * np.pi)
    deck = os.path.join(work, "v%.3f.xml" % speed)
    with open(deck, "w") as f:
        f.write(DECK.format(root=ROOT, speed=speed, end=8 / frequency, step=step))
    out = os.path.join(work, "v%.3f" % speed)
    subprocess.run([railfe, deck, "--output", out, "--quiet"], check=True)
    row = next(csv.DictReader(open(os.path.join(out, "run_measurements.csv"))))
    return float(row["growth_per_cycle"]), float(row["wavelength_m"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("railfe")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "img"))
    parser.add_argument("--quick", action="store_true", help="three speeds only")
    args = parser.parse_args()
    critical = reference_critical_speed()
    classical = reference_critical_speed(yaw_creep=1.0)
    f11, f22, W = creep_coefficients()
    print("f11 %.4g N, f22 %.4g N; critical speed %.3f m/s (railfe's kinematics, yaw creep x "
          "%.4f), %.3f m/s (classical Wickens)" % (f11, f22, critical, YAW_CREEP, classical))
    factors = [0.9, 1.0, 1.1] if args.quick else [0.7, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.2, 1.3]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for factor in factors:
            V = factor * critical
            growth, wavelength = simulate(args.railfe, V, work)
            sigma, omega, reference = eigen_growth(V)
            _, omega_w, wickens = eigen_growth(V, yaw_creep=1.0)
            rows.append((V, growth, reference, wavelength, 2 * np.pi * V / omega, wickens,
                         2 * np.pi * V / omega_w))
            print("V %.2f m/s: growth per cycle %.5f (eigenvalues %.5f), wavelength %.3f m "
                  "(%.3f m); classical Wickens %.5f, %.3f m" % rows[-1])
    speeds = np.array([r[0] for r in rows])
    growth = np.array([r[1] for r in rows])
    i = np.where((growth[:-1] < 1) & (growth[1:] >= 1))[0]
    simulated = float("nan")
    if len(i):
        j = i[0]
        simulated = np.interp(1.0, growth[j:j + 2], speeds[j:j + 2])
    print("simulated critical speed %.3f m/s (%+.2f %% from the eigenvalues, %+.2f %% from the "
          "classical Wickens equations)" % (simulated, 100 * (simulated / critical - 1),
                                            100 * (simulated / classical - 1)))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "wickens_critical_speed.csv"), "w") as f:
        f.write("speed_m_per_s,growth_per_cycle_simulated,growth_per_cycle_eigenvalues,"
                "wavelength_simulated_m,wavelength_eigenvalues_m,growth_per_cycle_wickens,"
                "wavelength_wickens_m\n")
        for r in rows:
            f.write(",".join("%.10g" % x for x in r) + "\n")
        f.write("# eigenvalues: railfe's kinematics, (1 + kappa) and the yaw-neglected search's "
                "yaw creep x %.6g; wickens: the classical equations, (1 + kappa) and yaw creep "
                "x 1\n" % YAW_CREEP)
        f.write("# critical speed: eigenvalues %.6g m/s, classical Wickens %.6g m/s, simulation "
                "%.6g m/s\n" % (critical, classical, simulated))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fine = np.linspace(speeds.min(), speeds.max(), 200)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(fine, [eigen_growth(V)[2] for V in fine], "-", color="C0",
            label="eigenvalues, railfe's kinematics (yaw creep x %.3f)" % YAW_CREEP)
    ax.plot(fine, [eigen_growth(V, yaw_creep=1.0)[2] for V in fine], "--", color="C2",
            label="eigenvalues, classical Wickens equations")
    ax.plot(speeds, growth, "o", color="C1", label="railfe time simulation (HHT, contact element)")
    ax.axhline(1, color="gray", lw=0.8)
    ax.axvline(critical, color="C0", ls=":", lw=0.8)
    ax.axvline(classical, color="C2", ls=":", lw=0.8)
    ax.set_xlabel("speed (m/s)")
    ax.set_ylabel("lateral amplitude ratio per cycle")
    ax.set_title("Suspended conical wheelset: critical speed %.2f m/s simulated;\neigenvalues "
                 "%.2f m/s (railfe's kinematics), %.2f m/s (classical Wickens)"
                 % (simulated, critical, classical), fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "wickens_critical_speed.png"), dpi=120)

if __name__ == "__main__":
    main()
