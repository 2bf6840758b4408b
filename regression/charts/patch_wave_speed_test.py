#!/usr/bin/env python3
"""Test of patch_wave_speed.py on synthetic patches: plane waves of known speed and direction
(one slower than the Rayleigh speed along +s1 and to the side, one faster travelling back across
the patch) in the pressure and shear of a 1 mm node grid, sampled every 0.25 us over 32
instants with noise, as the squeal decks' burst writes them; the micro-slip is constant. The fit
must find each speed within 1 % and its direction within 2 degrees, fit nothing to the constant
signal, and draw its chart.

    /usr/bin/python3 regression/charts/patch_wave_speed_test.py WORK_DIR
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import patch_wave_speed  # noqa: E402

HEADER = ("time_s,node,x_m,y_m,z_m,s1_m,s2_m,pressure_Pa,shear_1_Pa,shear_2_Pa,"
          "slip_velocity_1_m/s,slip_velocity_2_m/s,slipping,gap_m,area_m2")
WAVES = [(2677.5, 20.0, 150e3), (3300.0, -150.0, 210e3)]  # speed m/s, direction deg, frequency Hz


def write_patches(work, speed, direction, frequency, seed):
    """32 patch files of a plane wave; returns their paths."""
    rng = np.random.default_rng(seed)
    unit = (math.cos(math.radians(direction)), math.sin(math.radians(direction)))
    paths = []
    for k in range(32):
        t = 0.01855 + 2.5e-7 * k
        lines, node = [HEADER], 0
        for i in range(-6, 7):
            for j in range(-9, 6):
                s1, s2 = 1e-3 * i, 1e-3 * j
                node += 1
                phase = math.sin(2 * math.pi * frequency * (t - (s1 * unit[0] + s2 * unit[1]) / speed))
                pressure = 5e8 + 2e7 * phase + 5e5 * rng.standard_normal()
                shear = 2e8 + 1e7 * phase + 2e5 * rng.standard_normal()
                lines.append(f"{t!r},{node},0,0,0,{s1!r},{s2!r},{pressure!r},{shear!r},0,0.01,0,1,0,"
                             "1e-6")
        path = os.path.join(work, f"patch_{speed:.0f}_{k + 1}.csv")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        paths.append(path)
    return paths


def main(work):
    os.makedirs(work, exist_ok=True)
    for n, (speed, direction, frequency) in enumerate(WAVES):
        paths = write_patches(work, speed, direction, frequency, n)
        csv_path, png = (os.path.join(work, f"waves_{n}.{x}") for x in ("csv", "png"))
        patch_wave_speed.main(["--csv", csv_path, "--png", png] + paths)
        rows = {r["signal"]: r for r in
                patch_wave_speed.csv.DictReader(open(csv_path))}
        for signal in ("pressure", "shear"):
            found = float(rows[signal]["speed_m_per_s"])
            angle = float(rows[signal]["direction_deg_from_s1"])
            assert abs(found / speed - 1) < 0.01, f"{signal}: {found} m/s, expected {speed}"
            turn = (angle - direction + 180) % 360 - 180
            assert abs(turn) < 2, f"{signal}: direction {angle} deg, expected {direction}"
        assert rows["micro-slip"]["speed_m_per_s"] == "", "a speed fitted to a constant signal"
        assert os.path.getsize(png) > 10000, "no chart"
    print("patch wave speed: both waves found within 1 % and 2 degrees")


if __name__ == "__main__":
    main(sys.argv[1])
