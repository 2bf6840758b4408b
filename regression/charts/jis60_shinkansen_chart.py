#!/usr/bin/env python3
"""Chart of inputs/scenes/jis60_shinkansen_on_track.xml (docs/img/jis60_shinkansen_on_track.png):
the drawn wheel and rail placed on the track with the table's contact points, the rolling radius
difference against the shift with the cone-on-crowns closed form, and the equivalent conicity
against the amplitude, from the CSV files the run writes.

    /usr/bin/python3 regression/charts/jis60_shinkansen_chart.py RESULTS_DIR OUT.png

RESULTS_DIR holds jis60_profiles.csv, jis60_contact_table.csv and jis60_conicity.csv.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The cone-on-crowns closed form (contact/tests/wheel_drawing_tests.cpp): 1:40 cones of radius
# r0 at a from the axle's middle on R600 crowns whose centres lie c either side.
LAMBDA, R0, A, CROWN = 1 / 40, 0.43, 0.56, 0.6


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def cone_on_crowns(y, c):
    m = R0 + LAMBDA * A + CROWN * math.sqrt(1 + LAMBDA**2)
    phi, h = 0.0, m - LAMBDA * c
    for _ in range(100):
        phi = math.atan(LAMBDA * y / (LAMBDA * h - c))
        h = (m - y * math.sin(phi)) / math.cos(phi) - LAMBDA * c
    return 2 * LAMBDA * (y * math.cos(phi) - h * math.sin(phi))


def main():
    results, png = sys.argv[1], sys.argv[2]
    profiles = rows(os.path.join(results, "jis60_profiles.csv"))
    table = [r for r in rows(os.path.join(results, "jis60_contact_table.csv")) if r["converged"] == "1"]
    conicity = rows(os.path.join(results, "jis60_conicity.csv"))
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))

    # The right rail and the centred right wheel, with the rail's contact points of the table.
    ax = axes[0, 0]
    rail = [p for p in profiles if p["body"] == "rail" and p["side"] == "right"]
    wheel = [p for p in profiles if p["body"] == "wheel" and p["side"] == "right" and p["pose"] == "centred"]
    ax.plot([1e3 * float(p["y_m"]) for p in rail], [1e3 * float(p["z_m"]) for p in rail], "k", lw=1.3,
            label="JIS 60 kg rail (R600, R80, R13, 1:20 side), 1:40")
    ax.plot([1e3 * float(p["y_m"]) for p in wheel], [1e3 * float(p["z_m"]) for p in wheel], "tab:blue",
            lw=1.3, label="Shinkansen 860 wheel, centred")
    rail_y = [float(p["y_m"]) for p in rail]
    rail_z = [float(p["z_m"]) for p in rail]

    def rail_height(y):
        for k in range(len(rail_y) - 1):
            if (rail_y[k] - y) * (rail_y[k + 1] - y) <= 0 and rail_y[k] != rail_y[k + 1]:
                return rail_z[k] + (y - rail_y[k]) / (rail_y[k + 1] - rail_y[k]) * (rail_z[k + 1] - rail_z[k])
        return float("nan")

    shown = [r for k, r in enumerate(table)
             if float(r["lateral_m"]) >= -1e-12 and (k % 25 == 0 or r["right_part"] == "flange")]
    scatter = ax.scatter([1e3 * float(r["right_y_m"]) for r in shown],
                         [1e3 * rail_height(float(r["right_y_m"])) for r in shown],
                         c=[1e3 * float(r["lateral_m"]) for r in shown], cmap="viridis", s=18, zorder=3,
                         edgecolors="k", linewidths=0.3)
    fig.colorbar(scatter, ax=ax, label="lateral shift (mm)")
    ax.set_xlim(500, 605)
    ax.set_ylim(40, -35)  # z down: the wheel above the rail
    ax.set_aspect("equal")
    ax.set_xlabel("track y (mm, to the right)")
    ax.set_ylabel("z (mm, down)")
    ax.set_title("right wheel and rail; rail contact points of the table", fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    ax.grid(alpha=0.3)

    # The right wheel's rolling radius and contact angle against the shift.
    ax = axes[0, 1]
    right = [r for r in table if float(r["lateral_m"]) >= -1e-12]
    shift = [1e3 * float(r["lateral_m"]) for r in right]
    ax.plot(shift, [1e3 * (float(r["right_rolling_radius_m"]) - R0) for r in right], "tab:green", lw=1.2,
            label="rolling radius - 430 mm")
    ax.set_xlabel("lateral shift (mm)")
    ax.set_ylabel("right wheel's rolling radius - 430 mm (mm)")
    ax.set_ylim(-0.3, 1.0)
    twin = ax.twinx()
    twin.plot(shift, [math.degrees(float(r["right_contact_angle_rad"])) for r in right], "tab:red", lw=1,
              label="contact angle")
    twin.set_ylabel("right contact angle (degree)")
    twin.set_ylim(0, 70)
    ax.set_title("right wheel: cone to 5.5 mm, tread arc, flange root from 7.27 mm", fontsize=10)
    ax.grid(alpha=0.3)
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [line.get_label() for line in lines], fontsize=8, loc="upper left")

    # Δr against the shift, with the closed form of the cone on the crowns.
    ax = axes[1, 0]
    centred = min(table, key=lambda r: abs(float(r["lateral_m"])))
    c = float(centred["right_y_m"]) + CROWN * math.sin(math.atan(LAMBDA))
    shift = [1e3 * float(r["lateral_m"]) for r in table]
    ax.plot(shift, [1e3 * float(r["delta_r_m"]) for r in table], "tab:blue", lw=3, alpha=0.5,
            label="railfe, drawn profiles")
    cone_shifts = [s for s in shift if abs(s) <= 5.5]
    ax.plot(cone_shifts, [1e3 * cone_on_crowns(1e-3 * s, c) for s in cone_shifts], "k--", lw=1,
            label="1:40 cone on R600 crowns, closed form")
    ax.plot(cone_shifts, [2 * s / 40 for s in cone_shifts], ":", color="gray", lw=1, label="2 y / 40 (knife edge)")
    ax.set_xlabel("lateral shift (mm)")
    ax.set_ylabel("rolling radius difference right - left (mm)")
    ax.set_ylim(-2, 2)
    ax.set_title("rigid wheelset; the table ends where the flange folds it (7.33 mm)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)

    # Equivalent conicity against the amplitude.
    ax = axes[1, 1]
    amplitude = [1e3 * float(r["amplitude_m"]) for r in conicity]
    ax.plot(amplitude, [float(r["kinematic_conicity"]) for r in conicity], "o-", label="EN 15302 Annex B (wavelength)")
    ax.plot(amplitude, [float(r["regression_conicity"]) for r in conicity], "s--", ms=4,
            label="EN 15302 Annex C (regression)")
    ax.axhline(1 / 40, color="gray", ls=":", lw=1, label="1/40")
    small = LAMBDA * c / (c - LAMBDA * (R0 + CROWN))
    ax.axhline(small, color="k", ls="--", lw=0.8, label=f"cone on R600 crowns: {small:.5f}")
    ax.set_xlabel("amplitude of the wheelset's motion (mm)")
    ax.set_ylabel("equivalent conicity")
    ax.set_title("equivalent conicity", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)

    fig.suptitle("Shinkansen-type 860 mm conic-and-arc wheel on JIS 60 kg rail, 1:40, gauge 1067 mm, "
                 "back faces 990 mm apart", fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
