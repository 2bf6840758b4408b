#!/usr/bin/python3
"""Recomputes a vehicle dynamics run's running-safety table from its wheel-force history: for
every wheel the peak |Y|, the peak |Y|/Q, its peak sliding mean over the Y/Q window (UIC 518:
2 m of track, round(window / (V dt)) samples, numpy's convolution here) and the peak unloading
min(1, (Q0 - Q) / Q0), against <step>_safety.csv as railfe wrote it. Runs railfe on the BS 20 m
scene deck (both contact models; histories every step) and fails on a difference above 1e-9.

Usage: check_vehicle_safety.py RAILFE DECK
"""
import csv
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np


def step_values(deck, step):
    root = ET.parse(deck).getroot()
    for steps in root.iter("ParameterList"):
        if steps.get("name") == "Steps":
            for s in steps:
                if s.get("name") == step:
                    return {p.get("name"): p.get("value") for p in s if p.tag == "Parameter"}
    raise SystemExit("no step " + step)


def main():
    railfe, deck = sys.argv[1], sys.argv[2]
    failures = 0
    with tempfile.TemporaryDirectory() as out:
        if subprocess.run([railfe, deck, "--output", out, "--quiet"]).returncode != 0:
            raise SystemExit("railfe failed on " + deck)
        for step in ("online", "offline"):
            values = step_values(deck, step)
            V, dt = float(values["Speed"]), float(values["Time step"])
            window = round(float(values.get("Y/Q window", 2)) / (V * dt))
            rows = list(csv.DictReader(open(os.path.join(out, step + "_wheels.csv"))))
            wheels = list(csv.DictReader(open(os.path.join(out, step + "_safety.csv"))))
            for s in wheels:
                key = "w%s_%s_" % (s["wheelset"], s["wheel"])
                Q = np.array([float(r[key + "Q_N"]) for r in rows])
                Y = np.abs([float(r[key + "Y_N"]) for r in rows])
                quotient = np.where(Q > 0, Y / np.where(Q > 0, Q, 1), 0.0)
                Q0 = float(s["static_Q_N"])
                expected = {
                    "peak_Y_N": Y.max(),
                    "peak_Y_over_Q": quotient.max(),
                    "peak_Y_over_Q_sliding_mean":
                        np.convolve(quotient, np.ones(window) / window, "valid").max(),
                    "peak_unloading_dQ_over_Q": np.minimum(1.0, (Q0 - Q) / Q0).max(),
                }
                for column, value in expected.items():
                    got = float(s[column])
                    ok = abs(got - value) <= 1e-9 * max(abs(value), 1e-12)
                    failures += not ok
                    if not ok:
                        print("%s %s%s: railfe %.12g, recomputed %.12g" % (step, key, column, got,
                                                                          value))
            print("%s: %d wheels checked, window %d samples" % (step, len(wheels), window))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
