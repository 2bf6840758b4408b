#!/usr/bin/env python3
"""Where the squeal scene's wheel touches its rail: the height of the wheel's axis above the rail's
crown (before loading) and the lateral position of the contact point, for the S1002 wheel of the
wheel generator (running circle at radius R, flange on +y) over the 54E1 rail of the rail
generator inclined 1:40 towards +y and shifted laterally by --rail-offset.

The rail's head is the EN 13674-1 drawing's crown (R300 to +-10.012 mm, R80 to +-24.8635 mm, R13
corners), as contact/geometry/rail_drawing.cpp builds it; the wheel's tread is the profile file's
points. Prints the Translation z of the wheel part (m) for a first touch at the given depth.

  squeal_placement.py [--radius 0.46] [--rail-offset -0.0025] [--depth 2e-5]
"""
import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
PROFILE = os.path.join(HERE, "..", "..", "inputs", "profiles", "MBench_S1002_v3.prw")


def wheel_profile(profile=PROFILE):
    """(y, z) in metres of a wheel profile file (the S1002 file unless named), z radially
    outwards."""
    points, inside = [], False
    for line in open(profile):
        text = line.split("!")[0].strip()
        if text.startswith("point.begin"):
            inside = True
            continue
        if text.startswith("point.end"):
            break
        if inside and text:
            y, z = text.split()[:2]
            points.append((float(y) / 1000, float(z) / 1000))
    return sorted(points)


def interpolate(points, y):
    for (y0, z0), (y1, z1) in zip(points, points[1:]):
        if y0 <= y <= y1:
            return z0 + (z1 - z0) * (y - y0) / (y1 - y0)
    return None


def rail_head_top(u):
    """Height v (m, up) of the 54E1 head at lateral u (m), |u| <= 35 mm."""
    a = abs(u) * 1000
    w1, w2 = 20.024 / 2, 49.727 / 2
    t1 = (w1, -300 + math.sqrt(300**2 - w1**2))
    c80 = (t1[0] + 80 * (0 - t1[0]) / 300, t1[1] + 80 * (-300 - t1[1]) / 300)
    t2 = (w2, c80[1] + math.sqrt(80**2 - (w2 - c80[0]) ** 2))
    c13 = (t2[0] + 13 * (c80[0] - t2[0]) / 80, t2[1] + 13 * (c80[1] - t2[1]) / 80)
    if a <= w1:
        v = -300 + math.sqrt(300**2 - a**2)
    elif a <= w2:
        v = c80[1] + math.sqrt(80**2 - (a - c80[0]) ** 2)
    elif a <= c13[0] + 13:
        v = c13[1] + math.sqrt(max(13**2 - (a - c13[0]) ** 2, 0))
    else:
        return None
    return v / 1000


def inclined_head(rail_offset, inclination):
    """The 54E1 head's top as points (y, z) every 0.01 mm, inclined 1:`inclination` about +x
    (the head tilts towards +y; math.inf: upright) and shifted by `rail_offset` (m), in
    increasing y."""
    alpha = -math.atan(1 / inclination)
    head = []
    for k in range(-3500, 3501):
        u = k * 1e-5
        v = rail_head_top(u)
        if v is None:
            continue
        head.append((u * math.cos(alpha) - v * math.sin(alpha) + rail_offset,
                     u * math.sin(alpha) + v * math.cos(alpha)))
    return head


def separation_rows(angle, radius=0.46, rail_offset=-0.0025, inclination=40, wheel_shift=0.0,
                    profile=PROFILE):
    """Rows (y, s, R) every 0.05 mm over +-25 mm: the gap between the wheel's lowest circle and
    the inclined rail's head, measured normal to a contact plane at `angle` (rad), and the
    wheel's radius at y. `wheel_shift` (m) moves the wheel along +y (the axle's lateral
    displacement); y stays the track's. `profile`: the wheel's profile file."""
    wheel = wheel_profile(profile)
    z0 = interpolate(wheel, 0.0)
    head = sorted(inclined_head(rail_offset, inclination))
    rows = []
    for k in range(-500, 501):
        y = k * 5e-5
        rail = interpolate(head, y)
        r = radius + interpolate(wheel, y - wheel_shift) - z0
        rows.append((y, -r - rail, r))  # the wheel's bottom less the rail, + a constant
    least = min(s for _, s, _ in rows)
    return [(y / math.cos(angle), (s - least) * math.cos(angle), r) for y, s, r in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--radius", type=float, default=0.46)
    parser.add_argument("--rail-offset", type=float, default=-0.0025)
    parser.add_argument("--depth", type=float, default=2e-5)
    parser.add_argument("--inclination", type=float, default=40)
    args = parser.parse_args()
    wheel = wheel_profile()
    z0 = interpolate(wheel, 0.0)
    # The inclined head as points (y, z), then the wheel's lowest circle over it.
    head = inclined_head(args.rail_offset, args.inclination)
    best, where = -1e9, None
    for y, z in head:
        zw = interpolate(wheel, y)
        if zw is None:
            continue
        needed = z + args.radius + (zw - z0)  # axis height at which this point touches
        if needed > best:
            best, where = needed, y
    print(f"wheel axis height for a first touch: {best:.9f} m (contact at y = {where * 1000:.3f} mm)")
    print(f"wheel part Translation z with {args.depth * 1e6:.1f} um of initial penetration: "
          f"{best - args.depth:.9f}")


if __name__ == "__main__":
    main()
