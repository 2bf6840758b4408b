#!/usr/bin/env python3
"""The expected values of wheelset_jis60_cone (expected.xml), computed apart from railfe.

The JIS 60 kg head from its drawing (crown R600 to half-width 10 mm, R80 and R13 touching it,
head 65 mm wide where the corner meets the 1:20 side), canted 1:40 with its gauge point 16 mm
below the top at 533.5 mm from the track centre: that places the crown's centre c from the
track centre. A rigid wheelset of 1:40 cones (r0 = 430 mm at a = 560 mm) on two such crowns:
    sin(phi) (lam H - c) = lam y cos(phi)
    cos(phi) (lam c + H) + y sin(phi) = r0 + lam a + R sqrt(1 + lam^2)
    dr = 2 lam (y cos(phi) - H sin(phi))
(both cone lines R from the crown centres; phi the roll, H the centres' depth below the axle),
and for small amplitudes the equivalent conicity lam c / (c - lam (r0 + R)).
    /usr/bin/python3 closed_form.py
"""
import math

LAM, R0, A, R = 1 / 40, 430.0, 560.0, 600.0  # mm
GAUGE, DEPTH = 1067.0, 16.0


def gauge_side_half(v):
    """u (< 0) of the upright head's gauge side at height v (mm below the top: v < 0)."""
    t1 = (-10.0, -R + math.sqrt(R * R - 100.0))
    d = (0 - t1[0], -R - t1[1])
    n = math.hypot(*d)
    c80 = (t1[0] + 80 * d[0] / n, t1[1] + 80 * d[1] / n)
    out = (-20 / math.hypot(1, 20), 1 / math.hypot(1, 20))  # the side's outward normal
    c13u = -32.5 - 13 * out[0]
    c13 = (c13u, c80[1] + math.sqrt(67**2 - (c13u - c80[0]) ** 2))
    t2 = (c80[0] + 80 * (c13[0] - c80[0]) / 67, c80[1] + 80 * (c13[1] - c80[1]) / 67)
    corner_end = (c13[0] + 13 * out[0], c13[1] + 13 * out[1])
    if v >= t1[1]:
        return -math.sqrt(R * R - (v + R) ** 2)
    if v >= t2[1]:
        return c80[0] - math.sqrt(80**2 - (v - c80[1]) ** 2)
    if v >= corner_end[1]:
        return c13[0] - math.sqrt(13**2 - (v - c13[1]) ** 2)
    return corner_end[0] + (v - corner_end[1]) / 20  # the 1:20 side, widening downwards


def crown_centre():
    """c: the crown centre's distance from the track centre (mm), the rail canted 1:40."""
    alpha = math.atan(LAM)
    rot = lambda u, v: (u * math.cos(alpha) - v * math.sin(alpha), u * math.sin(alpha) + v * math.cos(alpha))
    centre = rot(0.0, -R)
    top = centre[1] + R
    # The gauge point: on the gauge side, DEPTH below the top after canting (bisection on v).
    lo, hi = -40.0, -1.0
    f = lambda v: rot(gauge_side_half(v), v)[1] - (top - DEPTH)
    for _ in range(200):
        mid = (lo + hi) / 2
        if (f(mid) > 0) == (f(hi) > 0):
            hi = mid
        else:
            lo = mid
    gauge_u = rot(gauge_side_half(lo), lo)[0]
    return GAUGE / 2 + centre[0] - gauge_u


def delta_r(y, c):
    m = R0 + LAM * A + R * math.sqrt(1 + LAM**2)
    phi, h = 0.0, m - LAM * c
    for _ in range(200):
        phi = math.atan(LAM * y / (LAM * h - c))
        h = (m - y * math.sin(phi)) / math.cos(phi) - LAM * c
    return 2 * LAM * (y * math.cos(phi) - h * math.sin(phi))


if __name__ == "__main__":
    c = crown_centre()
    print(f"crown centre c = {c:.9f} mm")
    for y in (1.0, 2.0, 3.0, 4.0, 5.0):
        print(f"dr({y:.0f} mm) = {delta_r(y, c) * 1e-3:.15e} m")
    print(f"small-amplitude conicity = {LAM * c / (c - LAM * (R0 + R)):.15f}")
