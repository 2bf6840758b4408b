#!/usr/bin/env python3
"""Which of the wheel's modes a lateral kick at the patch makes ring, seen from rim points all
around the wheel (issue 16, Table 4: the full-scale records at the scene's one rim point never
show the (0,3) axial mode).

A lateral force at the patch excites, of each pair of modes with n nodal diameters, the member
whose antinode lies at the patch: about the wheel its shape goes as cos(n theta), theta measured
from the patch; by symmetry about the patch the sin(n theta) members stay still. A rim point at
theta sees the excited member in proportion to cos(n theta). The scene's rim point is at axle
height ahead, theta = 90 degrees at t = 0, where cos(3 theta) = 0, and it descends towards the
patch as the wheel rolls (3.46 degrees per ms): cos(3 theta) is 0 again at 30 degrees, at 17.4 ms,
in the middle of the full-scale cases' lateral motion (16-19 ms).

The check: the demo deck (--full: the full-scale case, its solution zone moved to the start) in
free rolling with Coulomb friction, its axle box given a short lateral pulse (a raised cosine of
AMPLITUDE over DURATION from START: broadband to 5 kHz), with rim points at ANGLES degrees from
the patch at the pulse's centre, at the scene's rim point's radius and lateral place (the scene's
rim point is the 90 degree one). Each point's angle is taken from the node railfe picked (the
mesh's nearest), at the pulse's centre. After the pulse the vibration stays fixed in the wheel,
so the points' lateral velocities are split, by least squares at every instant, into the
patterns cos(n theta), n = 0 to 4 (SPATIAL). ESPRIT (charts/damped_sines.py, sines kept across
model orders) then fits damped sines to each pattern's amplitude, and the strongest sine within
NEAR of each named mode of the deck's modal step (clamped axle, tread free) gives that mode's
frequency in rolling contact, its damping and its amplitude. Beside them, each rim point's own
spectrum: the peak between PEAK_BAND, where the one-circle n = 0 mode and the (0,3) pair are.

Writes docs/data/squeal_rim_visibility.csv (a row per rim point: its angle, the predicted
visibility of n = 3 and the spectrum's peak), docs/data/squeal_rim_visibility_modes.csv (a row per
named mode: its free frequency and the sine fitted to its pattern), their _full twins with
--full, and docs/img/squeal_rim_visibility.png. The demo takes about 8 min on one core, the full
scale about 50 min on two (49 min here):

    /usr/bin/python3 regression/studies/squeal_rim_visibility.py [build/bin/railfe] [--full]
        [--reuse] [--replot]
"""
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE, os.path.join(ROOT, "regression", "charts"),
                os.path.join(ROOT, "regression", "scenes")]
import damped_sines  # noqa: E402
from railfe_runs import csv_rows, run_or_reuse, study_parser, typed_rows, write_rows  # noqa: E402
from rim_vibration import node_set_positions  # noqa: E402
from make_squeal_decks import ROLLING_RADIUS, SPEED  # noqa: E402
from squeal_creep_damping import DECK_OPTIONS, pulse_deck  # noqa: E402

DATA = os.path.join(ROOT, "docs", "data")
PNG = os.path.join(ROOT, "docs", "img", "squeal_rim_visibility.png")
START, DURATION, AMPLITUDE = 1.0e-3, 4.0e-4, 1.0e-5  # s, s, m: broadband to 2 / DURATION
END_TIME = 0.010  # s: about 9 periods of a 1 kHz mode after the pulse
# --full: case 3's full-scale deck in free rolling to FULL_END_TIME, its solution zone (and the
# wheel's refined arc) moved to where the wheel rolls in that time; two ranks, about 50 min.
FULL_END_TIME = 0.006  # s
FULL_OPTIONS = ["--case", "3", "--torque", "0", "--end-time", f"{FULL_END_TIME:g}",
                "--approach-size", "0", "--zone-start", "-0.01", "--zone-end", "0.18",
                "--patch-times", "0.0005", "0.003", "0.0055"]
# Degrees from the patch at the pulse's centre, ahead of the axle and over the top: wide enough
# for the five patterns to be told apart (the least squares' condition number is in the CSV).
ANGLES = (20, 30, 40, 50, 60, 70, 80, 90, 105, 120, 135, 150, 165, 180)
SPATIAL = (0, 1, 2, 3, 4)  # the patterns cos(n theta) the rim's velocities are split into
RIM = (0.43038, -0.06)  # m: the scene's rim point's radius and lateral place (wheel frame)
FIT_BAND = (150.0, 3000.0)  # Hz
FIT_ORDER = 24
NEAR = 0.12  # a fitted sine names a mode within this share of its free frequency
PEAK_BAND = (900.0, 1300.0)  # Hz
# The modes looked for: key, label, family, nodal diameters, and which of those (0: the lowest).
# The nodal circles railfe counts are left aside: on these meshes the count of the same mode
# comes out as -1, 0 or 1. The one-circle n = 0 mode is the second axial n = 0 mode.
MODES = (("n0_0", "(0,0) axial", "axial", 0, 0),
         ("n0_1", "one-circle n = 0 axial", "axial", 0, 1),
         ("n2", "(0,2) axial", "axial", 2, 0),
         ("n3", "(0,3) axial", "axial", 3, 0),
         ("n4", "(0,4) axial", "axial", 4, 0))


def outputs(full):
    """The per-point, per-mode, spectra and shape CSV of the demo or (full) the full-scale run."""
    suffix = "_full" if full else ""
    return tuple(os.path.join(DATA, f"squeal_rim_visibility{kind}{suffix}.csv")
                 for kind in ("", "_modes", "_spectra", "_shape"))


def rotation_at_centre():
    """The wheel's rotation from t = 0 to the pulse's centre (degrees)."""
    return math.degrees(SPEED / ROLLING_RADIUS * (START + DURATION / 2))


def deck_text(full=False):
    """The demo (or, `full`, the full-scale case) in free rolling with the short pulse, and one
    rim point per angle."""
    options = list(DECK_OPTIONS)
    options[options.index("--end-time") + 1] = f"{END_TIME:g}"
    scene = "wheel in free rolling, rim points about the wheel"
    text = pulse_deck("coulomb", FULL_OPTIONS if full else options, START,
                      ("full-scale " if full else "demo ") + scene, DURATION, AMPLITUDE)
    radius, lateral = RIM
    sets, histories = [], []
    for angle in ANGLES:
        at = math.radians(angle + rotation_at_centre())
        point = (radius * math.sin(at), lateral, -radius * math.cos(at))
        sets.append(f'<ParameterList name="rim {angle}"><Parameter name="Point" '
                    f'type="Array(double)" value="{{{point[0]:.6g}, {point[1]:g}, '
                    f'{point[2]:.6g}}}"/></ParameterList>')
        histories.append(f'<ParameterList name="rim {angle} vy"><Parameter name="Node set" '
                         f'type="string" value="wheel.rim {angle}"/><Parameter name="Quantity" '
                         f'type="string" value="velocity"/><Parameter name="Component" '
                         f'type="string" value="y"/></ParameterList>')
    text, count = re.subn(r'(<ParameterList name="rim point">.*?</ParameterList>)',
                          lambda m: m.group(1) + "".join(sets), text, count=1, flags=re.S)
    assert count == 1, "the deck's rim point was not found"
    text, count = re.subn(r'(<ParameterList name="Histories">)',
                          lambda m: m.group(1) + "".join(histories), text, count=1)
    assert count == 1, "the deck's histories were not found"
    return text


def named_modes(results):
    """{key: frequency (Hz)} of MODES in the deck's modal step."""
    rows = csv_rows(os.path.join(results, "modes_modes.csv"))
    out = {}
    for key, _, family, diameters, rank in MODES:
        found = sorted(float(r["frequency_hz"]) for r in rows if r["family"] == family and
                       int(r["nodal_diameters"]) == diameters)
        out[key] = found[rank] if len(found) > rank else float("nan")
    return out


def rim_angles(results, deck):
    """Each rim point's angle from the patch at the pulse's centre (degrees), from the node
    railfe picked for it (preload.exo) and the wheel's axis (the modal step's Axis origin)."""
    origin = [float(v) for v in re.search(r'name="Axis origin" type="Array\(double\)" '
                                          r'value="\{([^}]*)\}"', deck).group(1).split(",")]
    angles = []
    for angle in ANGLES:
        x, _, z = node_set_positions(os.path.join(results, "preload.exo"), f"wheel.rim {angle}")[0]
        turned = math.degrees(math.atan2(x - origin[0], origin[2] - z)) - rotation_at_centre()
        angles.append((turned + 180) % 360 - 180)
    return np.array(angles)


def spectrum(v, dt):
    """The Hann-windowed complex spectrum of `v` (trend removed, zero-padded 16 times), scaled so
    that its magnitude is the amplitude of a sine there (the units of v): frequencies (Hz) and
    the spectrum."""
    n = len(v)
    s = np.arange(n) * dt
    v = v - np.polyval(np.polyfit(s, v, 1), s)
    return np.fft.rfftfreq(16 * n, dt), np.fft.rfft(v * np.hanning(n), 16 * n) * 4 / n


def peak_within(f, amplitude, band):
    """The index of the largest of `amplitude` with f within `band`."""
    return int(np.argmax(np.where((f >= band[0]) & (f <= band[1]), amplitude, 0)))


def fits(results, deck):
    """What the run shows, as four tables: per rim point (angle, visibility of n = 3, its own
    spectral peak in PEAK_BAND and its complex amplitude at the (0,3) pattern's peak); per named
    mode (the ESPRIT sine fitted to its pattern cos(n theta) and that pattern's spectral peak
    within NEAR of the free mode); the patterns' spectra to FIT_BAND's top; and the patterns'
    complex amplitudes at the (0,3) pattern's peak (the shape about the wheel there)."""
    modes = named_modes(results)
    rows = csv_rows(os.path.join(results, "roll_histories.csv"))
    t = np.array([float(r["time_s"]) for r in rows])
    keep = t >= START + DURATION
    dt = float(np.median(np.diff(t[keep])))
    velocity = np.array([[float(r[f"rim {angle} vy_velocity_y_m_per_s"]) for r in rows]
                         for angle in ANGLES])[:, keep]
    theta = np.radians(rim_angles(results, deck))
    basis = np.stack([np.cos(n * theta) for n in SPATIAL], axis=1)
    condition = float(np.linalg.cond(basis))
    patterns = np.linalg.lstsq(basis, velocity, rcond=None)[0]  # SPATIAL x time
    spectra_of = [spectrum(p, dt) for p in patterns]
    f, pattern_spectra = spectra_of[0][0], np.array([values for _, values in spectra_of])
    table = []
    for key, label, _, diameters, _ in MODES:
        pattern = SPATIAL.index(diameters)
        # A short record (the full scale's 4.6 ms) holds too few samples for FIT_ORDER + 8.
        samples = len(damped_sines.decimated(patterns[pattern], dt, FIT_BAND[1])[0])
        sines = damped_sines.stable_poles(patterns[pattern], dt, FIT_BAND,
                                          order=min(FIT_ORDER, samples // 2 - 9), floor=0.0)
        near = [s for s in sines if abs(s["frequency_hz"] / modes[key] - 1) <= NEAR]
        best = max(near, key=lambda s: s["rms"], default=None)
        k = peak_within(f, np.abs(pattern_spectra[pattern]),
                        (modes[key] * (1 - NEAR), modes[key] * (1 + NEAR)))
        row = {"mode": label, "pattern_n": diameters, "free_frequency_hz": modes[key],
               "pattern_condition_number": condition,
               "spectrum_peak_hz": float(f[k]),
               "spectrum_peak_amplitude_m_per_s": float(abs(pattern_spectra[pattern][k])),
               "spectrum_peak_over_free": float(f[k]) / modes[key]}
        for name in ("frequency_hz", "damping_ratio", "rms"):
            row[f"esprit_{name}"] = best[name] if best else float("nan")
        table.append(row)
    # The shape about the wheel at the (0,3) pattern's peak: each point's complex amplitude
    # there, and the patterns' (the least squares of the former, the same as the spectra's).
    at = peak_within(f, np.abs(pattern_spectra[SPATIAL.index(3)]), PEAK_BAND)
    points = []
    for k, angle in enumerate(ANGLES):
        own_f, own = spectrum(velocity[k], dt)
        peak = peak_within(own_f, np.abs(own), PEAK_BAND)
        points.append({"nominal_angle_deg": float(angle),
                       "angle_from_patch_deg": float(np.degrees(theta[k])),
                       "visibility_n3": abs(math.cos(3 * theta[k])),
                       "peak_frequency_hz": float(own_f[peak]),
                       "peak_amplitude_m_per_s": float(abs(own[peak])),
                       "amplitude_at_n3_peak_m_per_s": float(abs(own[at])),
                       "lateral_velocity_rms_m_per_s": float(np.std(velocity[k]))})
    shape = [{"pattern_n": n, "frequency_hz": float(f[at]),
              "amplitude_real_m_per_s": float(pattern_spectra[i][at].real),
              "amplitude_imag_m_per_s": float(pattern_spectra[i][at].imag)}
             for i, n in enumerate(SPATIAL)]
    inside = f <= FIT_BAND[1]
    spectra = {"frequency_hz": f[inside]}
    for n, values in zip(SPATIAL, pattern_spectra):
        spectra[f"pattern_n{n}_amplitude_m_per_s"] = np.abs(values[inside])
    return (points, table, [dict(zip(spectra, v)) for v in zip(*spectra.values())], shape)


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [(False, "demo wheel")] + ([(True, "full-scale wheel")]
                                        if os.path.exists(outputs(True)[0]) else [])
    fig, axes = plt.subplots(2, len(panels), figsize=(9 * len(panels), 10), squeeze=False)
    fine = np.radians(np.linspace(0, 180, 361))
    for column, (full, scale) in enumerate(panels):
        points_csv, modes_csv, spectra_csv, shape_csv = outputs(full)
        points = typed_rows(points_csv, [])
        table = {r["mode"]: r for r in typed_rows(modes_csv, ["mode"])}
        shape = {int(r["pattern_n"]): complex(r["amplitude_real_m_per_s"],
                                              r["amplitude_imag_m_per_s"]) * 1e3
                 for r in typed_rows(shape_csv, [])}
        at = typed_rows(shape_csv, [])[0]["frequency_hz"]
        top, bottom = axes[0][column], axes[1][column]
        top.plot([abs(p["angle_from_patch_deg"]) for p in points],
                 [1e3 * p["amplitude_at_n3_peak_m_per_s"] for p in points], "o", color="k",
                 label=f"each rim point's amplitude at {at:.0f} Hz")
        whole = sum(c * np.cos(n * fine) for n, c in shape.items())
        top.plot(np.degrees(fine), np.abs(whole), color="k", lw=1,
                 label="the patterns n = 0-4 fitted to them, summed")
        top.plot(np.degrees(fine), np.abs(shape[3] * np.cos(3 * fine)), color="C3", ls="--",
                 label="its cos(3 θ) term: the (0,3) member the patch excites")
        top.plot(np.degrees(fine), np.full(fine.shape, abs(shape[0])), color="C0", ls="--",
                 label="its n = 0 term")
        top.axvline(90, color="grey", lw=0.8, ls=":")
        top.annotate("the scene's rim point", (90, 0), xytext=(93, 1), fontsize=8, color="grey")
        top.set_xlim(0, 185)
        top.set_xlabel("rim point's angle from the patch at the pulse's centre θ (degrees)")
        top.set_ylabel("lateral velocity amplitude (mm/s)")
        top.legend(fontsize=8, loc="upper left")
        top.set_title(f"{scale} in free rolling, a {DURATION * 1e3:g} ms lateral pulse on the "
                      f"axle box: the rim about the wheel at {at:.0f} Hz", fontsize=10)
        spectra = typed_rows(spectra_csv, [])
        f = np.array([r["frequency_hz"] for r in spectra])
        for n, colour in zip(SPATIAL, ("C0", "C7", "C1", "C3", "C4")):
            bottom.plot(f, [1e3 * r[f"pattern_n{n}_amplitude_m_per_s"] for r in spectra],
                        color=colour, lw=1.6 if n in (0, 3) else 0.7, label=f"pattern cos({n} θ)")
        for (key, label, _, n, *_), height in zip(MODES, (0.9, 0.6, 0.8, 0.75, 0.7)):
            row = table[label]
            if n not in (0, 3) or row["free_frequency_hz"] < PEAK_BAND[0]:
                continue
            colour = "C0" if n == 0 else "C3"
            bottom.axvline(row["free_frequency_hz"], color=colour, ls=":", lw=1)
            bottom.annotate(f"{label}: free {row['free_frequency_hz']:.0f} Hz, its pattern's "
                            f"peak {row['spectrum_peak_hz']:.0f} Hz "
                            f"({100 * (row['spectrum_peak_over_free'] - 1):+.1f} %)",
                            (row["spectrum_peak_hz"], 1e3 * row["spectrum_peak_amplitude_m_per_s"]),
                            xytext=(0.42, height), textcoords="axes fraction", fontsize=8,
                            color=colour, arrowprops={"arrowstyle": "-", "color": colour,
                                                      "lw": 0.5})
        bottom.set_xlim(0, FIT_BAND[1])
        bottom.set_xlabel("frequency (Hz)")
        bottom.set_ylabel("amplitude (mm/s)")
        bottom.legend(fontsize=8, loc="upper right")
        bottom.set_title("the rim's lateral velocity split into the patterns cos(n θ) (least "
                         f"squares over the {len(points)} points), their spectra;\ndotted: the "
                         "modal step's free modes", fontsize=10)
    fig.tight_layout()
    fig.savefig(PNG, dpi=100)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_squeal_rim_visibility", ROOT,
                          reuse=True)
    parser.add_argument("--full", action="store_true",
                        help="the full-scale case instead of the demo (two ranks, about 50 min)")
    args = parser.parse_args()
    if not args.replot:
        text = deck_text(args.full)
        results = run_or_reuse(args.railfe, text, args.work, "pulse_full" if args.full else
                               "pulse", args.reuse, ranks=2 if args.full else 1)[0]
        for path, rows in zip(outputs(args.full), fits(results, text)):
            write_rows(path, rows)
    plot()


if __name__ == "__main__":
    main()
