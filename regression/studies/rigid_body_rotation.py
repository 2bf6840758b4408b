#!/usr/bin/python3
"""Rotation of a free rigid body: railfe's former and present explicit schemes against outside
references (docs/verification.md#explicit-rigid-body-rotation).

References, none of them railfe's:
  * the torque-free body (Landau & Lifshitz, Mechanics, §37): the body-frame angular velocity
    in Jacobi elliptic functions, period 4 K(k) / rate (scipy.special.ellipk); L and the kinetic
    energy constant;
  * a body under a constant spatial moment: L(t) = L0 + M t exactly; the angular velocity from
    SciPy's DOP853 on Euler's equations and the orientation (rtol 1e-12, atol 1e-14).

The two schemes are re-implemented here line for line from physics/explicit (the former from
discrete_parts.cpp before the momentum scheme, the present from rigid_rotation.cpp), so that
their drift can be charted side by side over long runs and many step sizes:
  former : ω += ½Δt ω̇;  R ← exp(Δt ω) R;  ω̇ = I_s⁻¹ (M − ω × I_s ω);  ω += ½Δt ω̇
  present: L += ½Δt M;  free rotation (implicit midpoint on the body-frame Euler equations,
           R ← R cay(Δt Ω̄), Austin, Krishnaprasad & Wang 1993);  L += ½Δt M

Writes docs/data/rigid_body_rotation.csv and docs/img/rigid_body_rotation.png, prints the
numbers quoted in docs/verification.md and the expected values of the verification decks.
  /usr/bin/python3 regression/studies/rigid_body_rotation.py [--deck-values]
"""
import argparse
import csv
import os

import numpy as np
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation
from scipy.special import ellipk

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# The tumbling deck: principal inertias 1, 2, 3 kg m², spin 10 rad/s about the intermediate axis
# with 0.1 rad/s about each of the others.
INERTIA = np.diag([1.0, 2.0, 3.0])
OMEGA0 = np.array([0.1, 10.0, 0.1])


def skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def expm_so3(w):
    return Rotation.from_rotvec(w).as_matrix()


def cayley(w):
    half = 0.5 * skew(w)
    return np.linalg.solve(np.eye(3) - half, np.eye(3) + half)


def free_period(inertia, omega):
    """Period of the body-frame angular velocity of a torque-free body (Landau & Lifshitz §37)."""
    i1, i2, i3 = np.diag(inertia)
    l2 = np.sum((np.diag(inertia) * omega) ** 2)
    e2 = np.sum(np.diag(inertia) * omega**2)
    if l2 < e2 * i2:  # the polhode circles axis 1: exchange 1 and 3
        i1, i3 = i3, i1
    rate = np.sqrt((i3 - i2) * (l2 - e2 * i1) / (i1 * i2 * i3))
    k2 = (i2 - i1) * (e2 * i3 - l2) / ((i3 - i2) * (l2 - e2 * i1))
    return 4 * ellipk(k2) / rate


def former_scheme(inertia, omega0, moment, dt, n, record=1):
    """discrete_parts.cpp before the momentum scheme (body without nodes, no locked axes)."""
    R = np.eye(3)
    w = omega0.copy()
    inv = np.linalg.inv
    Is = R @ inertia @ R.T
    alpha = inv(Is) @ (moment(0.0) - np.cross(w, Is @ w))
    work, m_prev = 0.0, moment(0.0)
    rows = [(0.0, R.copy(), w.copy(), work)]
    for step in range(1, n + 1):
        w = w + 0.5 * dt * alpha
        R = expm_so3(dt * w) @ R
        m = moment(step * dt)
        work += 0.5 * (m + m_prev) @ (dt * w)
        m_prev = m
        Is = R @ inertia @ R.T
        alpha = inv(Is) @ (m - np.cross(w, Is @ w))
        w = w + 0.5 * dt * alpha
        if step % record == 0:
            rows.append((step * dt, R.copy(), w.copy(), work))
    return rows


def free_rotation(inertia_inverse, dt, L, R):
    """rigid_rotation.cpp: implicit midpoint on Π' = Π × I⁻¹Π, R ← R cay(Δt I⁻¹Π̄)."""
    start = R.T @ L
    mid = start.copy()
    for _ in range(100):
        omega = inertia_inverse @ mid
        residual = mid - start - 0.5 * dt * np.cross(mid, omega)
        jacobian = np.eye(3) - 0.5 * dt * (skew(mid) @ inertia_inverse - skew(omega))
        correction = np.linalg.solve(jacobian, residual)
        mid -= correction
        if np.linalg.norm(correction) <= 1e-15 * np.linalg.norm(start):
            break
    R = R @ cayley(dt * inertia_inverse @ mid)
    return 0.5 * R @ (3 * np.eye(3) - R.T @ R)


def present_scheme(inertia, omega0, moment, dt, n, record=1):
    R = np.eye(3)
    inverse = np.linalg.inv(inertia)
    L = R @ inertia @ R.T @ omega0
    omega = lambda R, L: R @ inverse @ R.T @ L  # noqa: E731
    w = omega(R, L)
    m, work = moment(0.0), 0.0
    rows = [(0.0, R.copy(), w.copy(), work)]
    for step in range(1, n + 1):
        before = w
        L = L + 0.5 * dt * m
        work += 0.25 * dt * m @ (before + omega(R, L))
        R = free_rotation(inverse, dt, L, R)
        before = omega(R, L)
        m = moment(step * dt)
        L = L + 0.5 * dt * m
        w = omega(R, L)
        work += 0.25 * dt * m @ (before + w)
        if step % record == 0:
            rows.append((step * dt, R.copy(), w.copy(), work))
    return rows


def reference(inertia, omega0, moment, times):
    """DOP853 on Euler's equations in the body frame with the orientation (R row-major)."""
    inverse = np.linalg.inv(inertia)

    def rhs(t, y):
        w, R = y[:3], y[3:].reshape(3, 3)
        m = R.T @ moment(t)
        return np.concatenate([inverse @ (m - np.cross(w, inertia @ w)), (R @ skew(w)).ravel()])

    y0 = np.concatenate([omega0, np.eye(3).ravel()])
    sol = solve_ivp(rhs, (0, times[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=times)
    return [(t, y[3:].reshape(3, 3), y[3:].reshape(3, 3) @ y[:3]) for t, y in zip(sol.t, sol.y.T)]


def invariants(rows, inertia):
    out = []
    for t, R, w, work in rows:
        L = R @ inertia @ R.T @ w
        out.append((t, 0.5 * w @ L, L, np.abs(R.T @ R - np.eye(3)).max(), R.T @ w, work))
    return out


def measured_period(rows):
    """Mean period of upward zero crossings of the body-frame ω_y, as railfe measures it."""
    t = np.array([r[0] for r in rows])
    y = np.array([(r[1].T @ r[2])[1] for r in rows])
    up = np.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    crossings = t[up] + (0 - y[up]) / (y[up + 1] - y[up]) * (t[up + 1] - t[up])
    return (crossings[-1] - crossings[0]) / (len(crossings) - 1)


def no_moment(t):
    return np.zeros(3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--deck-values", action="store_true",
                        help="only print the expected values of the verification decks")
    args = parser.parse_args()
    period = free_period(INERTIA, OMEGA0)
    L0 = INERTIA @ OMEGA0
    E0 = 0.5 * OMEGA0 @ L0
    print(f"torque-free: period {period:.12g} s, |L| {np.linalg.norm(L0):.12g}, E {E0:.12g}")
    # Deck values: the tumbling deck (dt 1 ms, 12 s), the constant moment deck (1 s).
    for name, scheme in (("former", former_scheme), ("present", present_scheme)):
        rows = scheme(INERTIA, OMEGA0, no_moment, 1e-3, 12000)
        inv = invariants(rows, INERTIA)
        energy = max(abs(r[1] - E0) / E0 for r in inv)
        momentum = max(np.linalg.norm(r[2] - L0) / np.linalg.norm(L0) for r in inv)
        print(f"tumbling {name}: period {measured_period(rows):.10g} "
              f"({measured_period(rows) / period - 1:+.3e}), max energy error {energy:.3e}, "
              f"max |ΔL|/|L| {momentum:.3e}, end body ω {inv[-1][4]}, orthonormality "
              f"{max(r[3] for r in inv):.1e}")
    axis = np.array([1.0, 1.0, 1.0]) / np.sqrt(3)
    constant = lambda t: 2.0 * axis  # noqa: E731
    ref = reference(INERTIA, np.zeros(3), constant, np.array([0.0, 0.5, 1.0]))
    print(f"constant moment 2 N m about (1,1,1)/√3 on diag(1,2,3): DOP853 ω(1 s) = "
          f"{ref[-1][2]!r}, L(1 s) = {2 * axis!r}")
    for name, scheme in (("former", former_scheme), ("present", present_scheme)):
        rows = scheme(INERTIA, np.zeros(3), constant, 1e-3, 1000)
        t, R, w, work = rows[-1]
        L = R @ INERTIA @ R.T @ w
        print(f"constant moment {name}: ω(1 s) = {w!r} (error {np.linalg.norm(w - ref[-1][2]):.3e}"
              f"), L - M t = {L - 2 * axis!r}, KE - work = {0.5 * w @ L - work:.3e}")
    if args.deck_values:
        return

    # Drift over a long run at a coarse step (Ω Δt = 0.05), and the order over step sizes.
    long_dt, long_steps = 5e-3, 40000
    series = {}
    for name, scheme in (("former", former_scheme), ("present", present_scheme)):
        series[name] = invariants(scheme(INERTIA, OMEGA0, no_moment, long_dt, long_steps, 10),
                                  INERTIA)
    steps = [4e-2, 2e-2, 1e-2, 5e-3, 2.5e-3, 1.25e-3]
    order_rows = []
    for dt in steps:
        n = int(round(4 * period / dt))
        for name, scheme in (("former", former_scheme), ("present", present_scheme)):
            rows = scheme(INERTIA, OMEGA0, no_moment, dt, n)
            inv = invariants(rows, INERTIA)
            order_rows.append((name, dt, abs(measured_period(rows) / period - 1),
                               max(abs(r[1] - E0) / E0 for r in inv),
                               max(np.linalg.norm(r[2] - L0) / np.linalg.norm(L0) for r in inv)))
            print(f"dt {dt:g} {name}: period error {order_rows[-1][2]:.3e}, energy "
                  f"{order_rows[-1][3]:.3e}, momentum {order_rows[-1][4]:.3e}")
    for name in ("former", "present"):
        e = [r[2] for r in order_rows if r[0] == name]
        print(f"{name}: observed order of the period error "
              f"{np.polyfit(np.log(steps), np.log(e), 1)[0]:.2f}")

    os.makedirs(os.path.join(ROOT, "docs", "data"), exist_ok=True)
    with open(os.path.join(ROOT, "docs", "data", "rigid_body_rotation.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["series", "scheme", "time_s_or_step_s", "energy_error", "momentum_error",
                      "orthonormality_error", "period_error"])
        for name, inv in series.items():
            for t, e, L, ortho, _, _ in inv:
                out.writerow(["drift", name, f"{t:.6g}", f"{(e - E0) / E0:.6e}",
                              f"{np.linalg.norm(L - L0) / np.linalg.norm(L0):.6e}",
                              f"{ortho:.3e}", ""])
        for name, dt, p, e, m in order_rows:
            out.writerow(["order", name, f"{dt:g}", f"{e:.6e}", f"{m:.6e}", "", f"{p:.6e}"])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    colours = {"former": "tab:red", "present": "tab:blue"}
    for name, inv in series.items():
        t = [r[0] for r in inv]
        axes[0].semilogy(t, [max(abs(r[1] - E0) / E0, 1e-17) for r in inv], color=colours[name],
                         label=f"{name}: energy")
        axes[0].semilogy(t, [max(np.linalg.norm(r[2] - L0) / np.linalg.norm(L0), 1e-17)
                             for r in inv], color=colours[name], linestyle="--",
                         label=f"{name}: |ΔL| / |L|")
        axes[1].plot(t, [r[4][1] for r in inv], color=colours[name], label=name)
    axes[0].set(xlabel="time (s)", ylabel="relative error",
                title=f"Free tumbling near the intermediate axis, Ω Δt = {10 * long_dt:g}")
    axes[0].set_ylim(1e-17, 1e4)
    axes[0].legend(fontsize=8)
    axes[1].set(xlabel="time (s)", ylabel="body-frame ω_y (rad/s)",
                title="Dzhanibekov flips (reference period "
                      f"{period:.4f} s)")
    axes[1].set_xlim(0, 40)
    axes[1].set_ylim(-25, 25)
    axes[1].legend(fontsize=8)
    for name in ("former", "present"):
        rows = [r for r in order_rows if r[0] == name and np.isfinite(r[3])]
        axes[2].loglog([r[1] for r in rows], [r[2] for r in rows], "o-", color=colours[name],
                       label=f"{name}: flip period error")
        axes[2].loglog([r[1] for r in rows], [max(r[3], 1e-17) for r in rows], "s--",
                       color=colours[name], label=f"{name}: max energy error")
    ref_dt = np.array(steps)
    axes[2].loglog(ref_dt, 0.5 * order_rows[1][2] * (ref_dt / steps[0]) ** 2, "k:",
                   label="slope 2")
    axes[2].set(xlabel="time step (s)", ylabel="relative error",
                title="Error against step (4 flip periods)")
    axes[2].legend(fontsize=8, loc="center right")
    fig.tight_layout()
    os.makedirs(os.path.join(ROOT, "docs", "img"), exist_ok=True)
    fig.savefig(os.path.join(ROOT, "docs", "img", "rigid_body_rotation.png"), dpi=110)


if __name__ == "__main__":
    main()
