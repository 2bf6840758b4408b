#!/usr/bin/env python3
"""Wheel vibration at a rim point (the squeal scene's Figs. 9, 10 and Table 4): the lateral,
radial and circumferential histories of a rim node relative to the rolling wheel, their Welch
PSD and Morlet wavelet power, and the PSD peaks matched to the wheel's own modes.

    /usr/bin/python3 regression/charts/rim_vibration.py roll_histories.csv wheel_modes.csv out \\
        --history rim --quantity displacement --rim 0.5 -0.065 0.9 --centre 0.5 0 0.46 \\
        --centre-history axle --spin-history "axle spin" --start 0.002

Reads an explicit step's <step>_histories.csv: the node-set history --history of one rim node
(columns <name>_<quantity>_<x|y|z>_<unit>; or one history per component, named "<name> x",
"<name> y", "<name> z") and, to take out the wheel's rigid motion, the axle centre's history of
the same quantity (--centre-history, e.g. the axle box body; or a constant --speed along x) and
its spin about y (--spin-history, the body's angular velocity y; or a constant --omega, rad/s).
The axle is along y and the track along x (railfe's wheel and rail generators). Components:
lateral = y, radial = along the centre-to-rim line as it turns, circumferential = y x radial
(the direction of travel of the rim for positive spin). Accelerations so projected include the
Coriolis coupling 2 Omega / omega of the other in-plane component (a few % at 1 kHz, 60 rad/s);
displacements do not. Writes out_histories.png, out_psd.png, out_wavelet.png and out_peaks.csv
(component, peak frequency, PSD, and the nearest mode of the modal step's <step>_modes.csv: its
number, frequency, family, nodal circles and diameters, difference %); with --poles, also
out_poles.csv: the damped sines ESPRIT fits to each component (damped_sines.py), which a short
run resolves far finer than its Welch PSD, each beside its nearest mode.
"""
import argparse
import csv
import math
import re
import subprocess

import matplotlib
import numpy as np
from scipy import ndimage, signal

import damped_sines

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COMPONENTS = ("lateral", "radial", "circumferential")
UNITS = {"displacement": "m", "velocity": "m_per_s", "acceleration": "m_per_s2"}


def history(columns, name, quantity, axis):
    """The column of history name (or "name <anything>", one history per component),
    quantity, component axis (x, y or z)."""
    pattern = re.escape(name) + r"( [^_]*)?_" + quantity.replace(" ", "_") + f"_{axis}_[a-z0-9_]+"
    found = [c for c in columns if re.fullmatch(pattern, c)]
    if len(found) != 1:
        raise SystemExit(f"not one column {pattern} in the histories: {', '.join(columns)}")
    return np.array(columns[found[0]], dtype=float)


def read_columns(path):
    """The CSV's columns by name."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if len(rows) < 16:
        raise SystemExit(f"{path}: {len(rows)} rows, too short for a spectrum")
    return {name: [float(r[name]) for r in rows] for name in rows[0]}


def node_set_positions(exodus, name):
    """Positions (k, 3) of the nodes of node set name in an Exodus file, read with ncdump."""
    def data(variables):
        command = ["ncdump", "-v", variables, exodus]
        return subprocess.run(command, capture_output=True, text=True, check=True).stdout

    def values(text, variable):
        body = re.search(variable + r" =([^;]*);", text.split("data:", 1)[1]).group(1)
        return np.array(body.replace(",", " ").split(), dtype=float)

    names = re.findall(r'"([^"]*)"', data("ns_names").split("data:", 1)[1])
    if name not in names:
        raise SystemExit(f"{exodus}: no node set '{name}' (have: {', '.join(names)})")
    k = names.index(name) + 1
    nodes = values(data(f"node_ns{k}"), f"node_ns{k}").astype(int) - 1
    text = data("coordx,coordy,coordz")
    return np.stack([values(text, f"coord{c}")[nodes] for c in "xyz"], 1)


def rim_components(t, rim, centre, centre_motion, spin, rim_ref, centre_ref, quantity):
    """Lateral, radial and circumferential components of the rim's motion relative to the
    rigid wheel. rim, centre_motion: (n, 3) histories of quantity; spin: (n,) rad/s."""
    theta = np.concatenate(([0.0], np.cumsum(0.5 * (spin[1:] + spin[:-1]) * np.diff(t))))
    c, s = np.cos(theta), np.sin(theta)
    d0 = np.asarray(rim_ref, float) - np.asarray(centre_ref, float)
    # Rotation about y by theta: z turns towards x.
    d = np.stack([c * d0[0] + s * d0[2], np.full_like(t, d0[1]), -s * d0[0] + c * d0[2]], 1)
    y = np.array([0.0, 1.0, 0.0])
    spin_x_d = np.cross(np.outer(spin, y), d)
    if quantity == "displacement":
        rigid = centre_motion + d - d0
    elif quantity == "velocity":
        rigid = centre_motion + spin_x_d
    else:
        spin_rate = np.gradient(spin, t)
        rigid = (centre_motion + np.cross(np.outer(spin_rate, y), d) +
                 np.cross(np.outer(spin, y), spin_x_d))
    elastic = rim - rigid
    radial = d.copy()
    radial[:, 1] = 0
    radial /= np.linalg.norm(radial, axis=1)[:, None]
    circumferential = np.cross(y, radial)
    return {"lateral": elastic[:, 1], "radial": np.sum(elastic * radial, 1),
            "circumferential": np.sum(elastic * circumferential, 1)}


def uniform(t, values):
    """Resamples onto a uniform grid of the median sample spacing."""
    dt = float(np.median(np.diff(t)))
    grid = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    return grid, {k: np.interp(grid, t, v) for k, v in values.items()}


def welch(x, dt, segments):
    """Welch PSD (Hann windows, half overlap, about segments segments)."""
    nperseg = max(16, int(2 * len(x) / (segments + 1)))
    return signal.welch(x - np.mean(x), fs=1 / dt, nperseg=min(nperseg, len(x)), detrend="linear")


def morlet_power(x, dt, frequencies, w0=6.0):
    """Continuous wavelet transform power |W(f, t)|^2 with the Morlet wavelet (omega0 = w0),
    computed in Fourier space (Torrence and Compo 1998), at frequencies (Hz)."""
    n = len(x)
    size = 1 << int(math.ceil(math.log2(2 * n)))  # zero padding against wrap-around
    spectrum = np.fft.fft(signal.detrend(x), size)  # a trend would ring at both ends
    omega = 2 * np.pi * np.fft.fftfreq(size, dt)
    power = np.empty((len(frequencies), n))
    for i, f in enumerate(frequencies):
        scale = (w0 + math.sqrt(2 + w0 * w0)) / (4 * np.pi * f)  # Fourier period 1/f
        psi = np.pi**-0.25 * np.exp(-0.5 * (scale * omega - w0) ** 2) * (omega > 0)
        psi *= math.sqrt(2 * np.pi * scale / dt)
        power[i] = np.abs(np.fft.ifft(spectrum * psi)[:n]) ** 2
    return power


def psd_peaks(f, p, count, band, decades):
    """The count highest local maxima of PSD p within band (Hz) that stand at least decades
    above the PSD's running median over 21 bins (the floor around them), by frequency."""
    level = np.log10(p + 1e-300)
    floor = ndimage.median_filter(level, size=21, mode="nearest")
    index, _ = signal.find_peaks(level)
    index = [i for i in index if band[0] < f[i] <= band[1] and level[i] - floor[i] >= decades]
    index = sorted(sorted(index, key=lambda i: -p[i])[:count])
    return [(f[i], p[i]) for i in index]


def read_modes(path):
    """The elastic modes of a modal step's <step>_modes.csv (rigid-body modes left out)."""
    with open(path, newline="") as handle:
        return [r for r in csv.DictReader(handle)
                if float(r["frequency_hz"]) > 0 and r["family"] != "rigid-body"]


def nearest_mode(modes, frequency):
    """The mode nearest frequency, or None."""
    return min(modes, key=lambda r: abs(float(r["frequency_hz"]) - frequency), default=None)


def mode_columns(modes, frequency):
    """The columns of the mode nearest frequency: number, frequency, family, nodal circles and
    diameters, difference % (empty without modes)."""
    mode = nearest_mode(modes, frequency)
    if mode is None:
        return [""] * 6
    hz = float(mode["frequency_hz"])
    return [mode["mode"], f"{hz:.6g}", mode["family"], mode["nodal_circles"],
            mode["nodal_diameters"], f"{100 * (frequency - hz) / hz:.4g}"]


def peak_rows(spectra, modes, count, band, decades):
    """Rows of the peaks table: each component's peaks and their nearest modes."""
    rows = []
    for name in COMPONENTS:
        f, p = spectra[name]
        for peak, value in psd_peaks(f, p, count, band, decades):
            rows.append([name, f"{peak:.6g}", f"{value:.6g}"] + mode_columns(modes, peak))
    return rows


def pole_rows(t, values, modes, order, band):
    """Rows of the poles table: each component's damped sines (damped_sines.stable_poles at
    model order `order`) and their nearest modes."""
    rows = []
    for name in COMPONENTS:
        try:
            sines = damped_sines.stable_poles(values[name], t[1] - t[0], band, order)
        except ValueError as error:
            raise SystemExit(f"--poles {order}: {error}; a smaller order or a longer record")
        for sine in sines:
            f = sine["frequency_hz"]
            rows.append([name, f"{f:.6g}", f"{sine['damping_ratio']:.4g}",
                         f"{sine['rms']:.6g}"] + mode_columns(modes, f))
    return rows


def draw(prefix, t, values, spectra, wavelet_f, unit, rows):
    """The three PNGs."""
    fig, axes = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    for ax, name in zip(axes, COMPONENTS):
        ax.plot(1e3 * t, values[name], lw=0.7)
        ax.set_ylabel(f"{name} ({unit})")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time (ms)")
    fig.tight_layout()
    fig.savefig(prefix + "_histories.png", dpi=110)
    fig, axes = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    for ax, name in zip(axes, COMPONENTS):
        f, p = spectra[name]
        shown = p[(f > 0) & (f <= wavelet_f[-1])]
        ax.semilogy(f, p, lw=0.8)
        ax.set_ylim(0.5 * shown.min(), 5 * shown.max())
        for row in (r for r in rows if r[0] == name):
            ax.axvline(float(row[1]), color="red", lw=0.5, ls="--")
            label = f"{float(row[1]):.0f} Hz" + (f"\n({row[6]},{row[7]}) {row[5]}" if row[4] else "")
            ax.annotate(label, (float(row[1]), float(row[2])), fontsize=7)
        ax.set_ylabel(f"{name} PSD")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("frequency (Hz)")
    axes[-1].set_xlim(0, wavelet_f[-1])
    fig.tight_layout()
    fig.savefig(prefix + "_psd.png", dpi=110)
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    dt = t[1] - t[0]
    for ax, name in zip(axes, COMPONENTS):
        power = morlet_power(values[name], dt, wavelet_f)
        mesh = ax.pcolormesh(1e3 * t, wavelet_f, np.log10(power + 1e-30 * power.max()),
                             shading="auto", vmin=np.log10(power.max()) - 3)
        fig.colorbar(mesh, ax=ax, label="log10 power")
        ax.set_ylabel(f"{name}\nfrequency (Hz)")
    axes[-1].set_xlabel("time (ms)")
    fig.tight_layout()
    fig.savefig(prefix + "_wavelet.png", dpi=110)
    plt.close("all")


def main(argv=None):
    """Runs the chart on the command line argv; returns the peak rows and the spectra."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("histories_csv")
    parser.add_argument("modes_csv", help="a modal step's <step>_modes.csv ('' = none)")
    parser.add_argument("prefix", help="output path prefix")
    parser.add_argument("--history", required=True, help="the rim node's history name")
    parser.add_argument("--quantity", default="acceleration", choices=sorted(UNITS))
    parser.add_argument("--rim", type=float, nargs=3, default=None, help="rim node at rest (m)")
    parser.add_argument("--centre", type=float, nargs=3, default=None, help="axle centre (m)")
    parser.add_argument("--exodus", help="an Exodus file of the mesh, for the two sets below")
    parser.add_argument("--rim-set", help="node set of the rim node in --exodus (for --rim)")
    parser.add_argument("--centre-set",
                        help="node set centred on the axle, e.g. wheel.axle_end (for --centre: "
                        "the middle of its bounding box)")
    parser.add_argument("--centre-history", help="axle centre's history name (same quantity)")
    parser.add_argument("--speed", type=float, default=0.0, help="constant centre speed along x")
    parser.add_argument("--spin-history", help="history of the spin about y (angular velocity)")
    parser.add_argument("--omega", type=float, default=0.0, help="constant spin about y (rad/s)")
    parser.add_argument("--start", type=float, default=0.0, help="leave out t < start (s)")
    parser.add_argument("--segments", type=int, default=4, help="Welch segments")
    parser.add_argument("--peaks", type=int, default=5, help="peaks per component")
    parser.add_argument("--prominence", type=float, default=1.0,
                        help="how far a peak stands above the PSD around it (decades)")
    parser.add_argument("--max-hz", type=float, default=None,
                        help="top of the charts and of the peak search (default Nyquist)")
    parser.add_argument("--poles", type=int, default=0,
                        help="also fit damped sines (ESPRIT, this model order; 0 = no) and "
                        "write PREFIX_poles.csv: finer than the Welch resolution on short runs")
    a = parser.parse_args(argv)
    if a.exodus and a.rim_set:
        points = node_set_positions(a.exodus, a.rim_set)
        if len(points) != 1:
            raise SystemExit(f"--rim-set '{a.rim_set}' holds {len(points)} nodes, not one")
        a.rim = list(points[0])
    if a.exodus and a.centre_set:
        points = node_set_positions(a.exodus, a.centre_set)
        a.centre = list(0.5 * (points.min(0) + points.max(0)))
    columns = read_columns(a.histories_csv)
    t = np.array(columns["time_s"])
    keep = t >= a.start
    t = t[keep]
    rim = np.stack([history(columns, a.history, a.quantity, c)[keep] for c in "xyz"], 1)
    if a.centre_history:
        centre = np.stack([history(columns, a.centre_history, a.quantity, c)[keep]
                           for c in "xyz"], 1)
    else:
        motion = {"displacement": a.speed * (t - t[0]), "velocity": a.speed, "acceleration": 0}
        centre = np.zeros((len(t), 3))
        centre[:, 0] = motion[a.quantity]
    spin = (history(columns, a.spin_history, "angular velocity", "y")[keep] if a.spin_history
            else np.full_like(t, a.omega))
    if a.rim is None or a.centre is None:
        if a.centre_history or a.spin_history or a.omega or a.speed:
            raise SystemExit("--rim and --centre are needed to take out the wheel's motion")
        values = {"lateral": rim[:, 1], "radial": rim[:, 2], "circumferential": rim[:, 0]}
    else:
        values = rim_components(t, rim, a.centre, centre, spin, a.rim, a.centre, a.quantity)
    t, values = uniform(t, values)
    dt = t[1] - t[0]
    spectra = {k: welch(v, dt, a.segments) for k, v in values.items()}
    df = spectra["lateral"][0][1]
    modes = read_modes(a.modes_csv) if a.modes_csv else []
    top = a.max_hz or 0.5 / dt
    rows = peak_rows(spectra, modes, a.peaks, (2 * df, top), a.prominence)
    with open(a.prefix + "_peaks.csv", "w", newline="") as handle:
        out = csv.writer(handle)
        out.writerow(["component", "peak_hz", "psd", "mode", "mode_hz", "family",
                      "nodal_circles", "nodal_diameters", "difference_percent"])
        out.writerows(rows)
    if a.poles < 0:
        raise SystemExit(f"--poles {a.poles}: a model order is 0 (none) or more")
    if a.poles:
        # A sine needs a period and a half in the record to be told from its trend.
        poles = pole_rows(t, values, modes, a.poles, (1.5 / (t[-1] - t[0]), top))
        with open(a.prefix + "_poles.csv", "w", newline="") as handle:
            out = csv.writer(handle)
            out.writerow(["component", "frequency_hz", "damping_ratio", "rms", "mode", "mode_hz",
                          "family", "nodal_circles", "nodal_diameters", "difference_percent"])
            out.writerows(poles)
        print(f"{a.prefix}_poles.csv: {len(poles)} damped sines (model order {a.poles})")
    draw(a.prefix, t, values, spectra, np.linspace(max(df, top / 200), top, 160),
         UNITS[a.quantity], rows)
    print(f"{a.prefix}_peaks.csv: {len(rows)} peaks; frequency resolution {df:.4g} Hz")
    return rows, spectra


if __name__ == "__main__":
    main()
