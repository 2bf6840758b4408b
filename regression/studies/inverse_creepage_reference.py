#!/usr/bin/env python3
"""Reference creepages for the verification case contact_patch_inverse: Carter's 2-D rolling
cylinder applied strip by strip to a long Hertz ellipse (Kalker's strip theory, exact as
b/a -> infinity), inverted for given forces.

Each strip y of the ellipse (semi-axes a along the rolling direction, b across) is a 2-D Hertz
contact of half-width a s and peak pressure p0 s, s = sqrt(1 - y^2/b^2). Carter (Johnson 1985,
section 8.4) for identical bodies: creepage xi = 2 mu p0 s (1 - a'/a_s) / E* with adhesion over
the leading 2a', and force per unit length mu (pi/2) p0 s a s (1 - (a'/a_s)^2); strips with
s <= u slide entirely. With u = xi E* / (2 mu p0) the total is

    F / (mu N) = (3/4) int_{-1}^{1} s^2 (1 - (1 - u/s)_+^2) dt,    s = sqrt(1 - t^2),

which grows as (3 pi / 4) u for small u: C11 = pi^2 / (4 (1 - nu)), Kalker's limit for a/b -> 0.
Prints, for the case's b/a = 9.98 patch (10 is the edge of Kalker's table), the creepage that carries F = -f mu N for each f.

    /usr/bin/python3 regression/studies/inverse_creepage_reference.py
"""
import math

from scipy.integrate import quad
from scipy.optimize import brentq

E, NU, LOAD, MU, A, B = 210e9, 0.3, 1e5, 0.3, 5e-3, 49.9e-3


def force_share(u):
    """F / (mu N) of the strip theory at normalized creepage u = xi E* / (2 mu p0)."""
    def integrand(t):
        s = math.sqrt(max(0.0, 1 - t * t))
        return s * s * (1 - (1 - u / s) ** 2) if s > u else s * s
    edge = math.sqrt(max(0.0, 1 - u * u))
    return 0.75 * quad(integrand, -1, 1, points=[-edge, edge], limit=200, epsabs=1e-13,
                       epsrel=1e-12)[0]


def main():
    p0 = 3 * LOAD / (2 * math.pi * A * B)
    modulus = E / (2 * (1 - NU * NU))  # E* of two equal bodies
    print(f"a {A} m, b {B} m, N {LOAD} N, mu {MU}: p0 {p0:.6g} Pa, E* {modulus:.6g} Pa")
    print("f = -Fx/(mu N), Fx (N), xi (strip theory)")
    for share in (0.25, 0.5, 0.75):
        u = brentq(lambda v: force_share(v) - share, 1e-12, 1 - 1e-12, xtol=1e-15)
        print(f"{share}, {-share * MU * LOAD:.10g}, {2 * MU * p0 * u / modulus:.10g}")


if __name__ == "__main__":
    main()
