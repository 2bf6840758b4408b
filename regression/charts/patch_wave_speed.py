#!/usr/bin/env python3
"""The speed of the waves seen in a contact patch (the squeal scene; the seed compares it with the
Rayleigh speed, 2975 m/s for its steel), from a burst of patch files a fraction of a microsecond
apart (<step>_contact_<pair>_patch_<k>.csv, in time order).

For each signal (pressure; shear traction magnitude; micro-slip speed), every node seen at every
instant gives a series less its mean. For every pair of nodes 2 to 6 mm apart, the delay at a
peak of their series' correlation (Pearson over the overlap, within 12 samples, a parabola
through the peak, above 0.8) is (r_j - r_i) . p for one slowness vector p, fitted by least
squares: the speed is 1 / |p| and its direction p / |p| in the patch plane (s1 along the rolling
direction, s2 across). A periodic signal correlates at several lags, one period apart: the pairs
up to 3 mm apart are fitted first at the peak nearest zero lag, then every pair at the peak
nearest the delay that first fit predicts. Writes a CSV row per signal (speed, direction, pairs, residual) and
a space-time chart of the shear along the patch's centre line with the fitted and the Rayleigh
slopes.

    /usr/bin/python3 regression/charts/patch_wave_speed.py --csv waves.csv --png waves.png \\
        roll_contact_wheel-rail_patch_24.csv ... roll_contact_wheel-rail_patch_55.csv
"""
import argparse
import csv
import math
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from patch_centre_line import read_patch  # noqa: E402

RAYLEIGH_SPEED = 2975.0  # m/s, steel (E 210 GPa, nu 0.3, 7850 kg/m3)
SIGNALS = {"pressure": ("pressure_Pa",), "shear": ("shear_1_Pa", "shear_2_Pa"),
           "micro-slip": ("slip_velocity_1_m/s", "slip_velocity_2_m/s")}
PAIR_DISTANCE = (0.002, 0.006)  # m
NEAR_PAIR = 0.003  # m, the first fit's pairs
LEAST_CORRELATION = 0.8
MOST_LAG = 12  # samples


def correlation_peaks(a, b, dt, most=MOST_LAG):
    """Delays (s) of b behind a at the local peaks of the Pearson correlation of their
    overlapping parts over lags up to `most` samples either way (a parabola through the three
    values around each; over the overlap only, as a plain correlation of a short record is
    biased towards zero lag), with the correlation there: [(delay, correlation)], none for a
    series of zeros."""
    if not (np.any(a) and np.any(b)):
        return []

    def pearson(k):
        x, y = (a[:len(a) - k], b[k:]) if k >= 0 else (a[-k:], b[:len(b) + k])
        x, y = x - x.mean(), y - y.mean()
        norm = math.sqrt(float(np.dot(x, x) * np.dot(y, y)))
        return float(np.dot(x, y)) / norm if norm > 0 else 0.0
    values = [pearson(k) for k in range(-most, most + 1)]
    peaks = []
    for k in range(1, len(values) - 1):
        y0, y1, y2 = values[k - 1], values[k], values[k + 1]
        if y1 >= y0 and y1 > y2:
            curvature = y0 - 2 * y1 + y2
            shift = 0.5 * (y0 - y2) / curvature if curvature != 0 else 0.0
            peaks.append(((k - most + shift) * dt, y1))
    return peaks


def slowness_fit(pairs, choose):
    """Least-squares slowness p (s/m) of delay = d . p over `pairs` [(d, peaks)], each pair's
    delay the peak `choose(d, peaks)` picks if it correlates above LEAST_CORRELATION; p, the
    offsets d and the delays used."""
    design, delays = [], []
    for d, peaks in pairs:
        picked = choose(d, peaks)
        if picked is not None and picked[1] > LEAST_CORRELATION:
            design.append(d)
            delays.append(picked[0])
    if len(delays) < 10:
        return None, design, delays
    return np.linalg.lstsq(np.array(design), np.array(delays), rcond=None)[0], design, delays


def node_series(patches, nodes, columns):
    """Each node's series of the magnitude of `columns` over the instants, less its mean (all
    zeros for a constant series)."""
    index = [{int(n): i for i, n in enumerate(p["node"])} for p in patches]
    series = {}
    for n in nodes:
        values = np.array([math.hypot(*[p[c][index[j][n]] for c in columns])
                           for j, p in enumerate(patches)])
        constant = np.ptp(values) <= 1e-9 * np.max(np.abs(values))
        series[n] = np.zeros_like(values) if constant else values - values.mean()
    return series


def fit(patches):
    """Rows (signal, speed, direction, pairs, ...) of the fitted slowness; the patches and the
    nodes seen at every instant (with their first position), for the chart."""
    if any("node" not in p for p in patches):
        raise SystemExit("the patch files have no node column: write them with a newer railfe")
    times = np.array([float(p["time_s"][0]) for p in patches])
    if len(times) < 2 * MOST_LAG or not np.all(np.diff(times) > 0):
        raise SystemExit(f"need at least {2 * MOST_LAG} patch files in time order")
    dt = float(np.median(np.diff(times)))
    nodes = sorted(set.intersection(*[set(p["node"].astype(int)) for p in patches]))
    first = {int(n): i for i, n in enumerate(patches[0]["node"])}
    where = {n: np.array([patches[0]["s1_m"][first[n]], patches[0]["s2_m"][first[n]]])
             for n in nodes}
    rows = []
    for signal, columns in SIGNALS.items():
        series = node_series(patches, nodes, columns)
        pairs = []
        for i, m in enumerate(nodes):
            for n in nodes[i + 1:]:
                d = where[n] - where[m]
                if PAIR_DISTANCE[0] <= math.hypot(*d) <= PAIR_DISTANCE[1]:
                    pairs.append((d, correlation_peaks(series[m], series[n], dt)))
        # The nearest pairs first, at the peak nearest zero lag (their delay is below half a
        # period for any wave this sampling resolves); then every pair at the peak nearest the
        # delay that fit predicts, so that no pair locks onto the next period.
        near = [(d, peaks) for d, peaks in pairs if math.hypot(*d) <= NEAR_PAIR]
        first, _, _ = slowness_fit(
            near, lambda d, peaks: min(peaks, key=lambda q: abs(q[0]), default=None))
        slowness, design, delays = (None, [], []) if first is None else slowness_fit(
            pairs, lambda d, peaks: min(peaks, key=lambda q: abs(q[0] - d @ first), default=None))
        row = {"signal": signal, "nodes": len(nodes), "instants": len(times),
               "interval_s": dt, "pairs": len(delays)}
        if slowness is not None:
            speed = 1 / float(np.hypot(*slowness))
            residual = np.array(design) @ slowness - np.array(delays)
            row.update({"speed_m_per_s": speed,
                        "direction_deg_from_s1": math.degrees(math.atan2(*slowness[::-1])),
                        "delay_rms_residual_s": float(np.sqrt(np.mean(residual ** 2))),
                        "rayleigh_m_per_s": RAYLEIGH_SPEED,
                        "over_rayleigh": speed / RAYLEIGH_SPEED})
        rows.append(row)
    return rows, patches, where


def chart(png, patches, where, rows, title):
    """The shear traction less its mean along the row of nodes nearest s2 = 0, against time,
    with the fitted slope (along s1) and the Rayleigh speed's."""
    line = sorted((n for n in where if abs(where[n][1]) <= 0.6e-3), key=lambda n: where[n][0])
    if len(line) < 2:
        return
    shear = np.array(list(node_series(patches, line, SIGNALS["shear"]).values())).T
    shear -= shear.mean(axis=0)
    times = np.array([float(p["time_s"][0]) for p in patches])
    s1 = [1e3 * where[n][0] for n in line]
    t = 1e6 * (times - times[0])
    fig, ax = plt.subplots(figsize=(8, 5.5))
    image = ax.pcolormesh(s1, t, 1e-6 * shear, cmap="RdBu_r", shading="nearest")
    fig.colorbar(image, ax=ax, label="shear traction less its mean (MPa)")
    span = np.array([s1[0], s1[-1]])
    fitted = next((r for r in rows if r["signal"] == "shear" and "speed_m_per_s" in r), None)
    if fitted is not None:
        along = fitted["speed_m_per_s"] / math.cos(math.radians(fitted["direction_deg_from_s1"]))
        ax.plot(span, t[0] + (span - span[0]) * 1e3 / along, "k--",
                label=f"fitted: {fitted['speed_m_per_s']:.0f} m/s, "
                      f"{fitted['direction_deg_from_s1']:.0f} deg from s1")
    ax.plot(span, t[0] + (span - span[0]) * 1e3 / RAYLEIGH_SPEED, "g:",
            label=f"Rayleigh {RAYLEIGH_SPEED:.0f} m/s along s1")
    ax.set_ylim(t[0], t[-1])
    ax.legend(loc="upper right", fontsize=8)
    ax.set_xlabel("s1 along the rolling direction (mm), centre line")
    ax.set_ylabel(f"time after {1e3 * times[0]:.5f} ms (us)")
    ax.set_title(f"{title + ': ' if title else ''}waves in the patch (shear on the centre line)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("patches", nargs="+", help="patch CSV files, in time order")
    parser.add_argument("--csv", required=True)
    parser.add_argument("--png", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args(argv)
    rows, patches, where = fit([read_patch(p) for p in args.patches])
    columns = ["signal", "nodes", "instants", "interval_s", "pairs", "speed_m_per_s",
               "direction_deg_from_s1", "delay_rms_residual_s", "rayleigh_m_per_s",
               "over_rayleigh"]
    with open(args.csv, "w", newline="") as f:
        out = csv.DictWriter(f, columns)
        out.writeheader()
        out.writerows(rows)
    chart(args.png, patches, where, rows, args.title)
    for row in rows:
        print(row)


if __name__ == "__main__":
    main()
