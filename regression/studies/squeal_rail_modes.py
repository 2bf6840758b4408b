#!/usr/bin/env python3
"""The full-scale rail's own modes near 1.35 kHz: where the rolling runs' line at 1327-1392 Hz,
which matches no wheel mode, comes from (issue 16, Table 4).

The full-scale case 1 rolls over x = 1.09-1.24 m, midway between the rail seats at 0.9 and 1.5 m.
A rail on discrete seats has the pinned-pinned mode: a bending wave whose half wavelength is the
seat spacing, with its nodes at the seats and its antinodes midway, so the seats' springs hardly
touch it. For an Euler beam (54E1: I = 2346 cm^4, 54.77 kg/m, 0.6 m) it lies at
(pi / L)^2 sqrt(EI / m) / (2 pi) = 1309 Hz.

The deck is case 1's (inputs/scenes/squeal_case1.xml) with one modal step of the rail block
alone, its ends held sideways and along as in the run, and its seats held vertically in one of
two ways, which bound the run's pads between them:
  pads     every foot node under the 150 mm pad held (the pad's rotation clamped);
  centres  only the foot nodes within 11 mm of each seat's centre (pinned).
For each mode the study takes the vertical and lateral motion of the head's top along the rail
(mean |u| in 50 mm bins) and calls a mode vertical pinned-pinned where the head moves mostly
vertically and, between the outer seats, at most a third as much at the seats as midway.

Beside them: the power spectral density (Welch) of the full-scale case 1's normal and creep forces
from 2 ms (docs/data/squeal_case1_full_forces.csv) and the rim sines fitted near the line
(docs/data/squeal_full_rim_poles.csv).

A second deck adds the run's own track: the rail on the preload's pads over the sleepers and
the ballast below (the modal step's Springs), alone ("track", 900-1800 Hz) and with the wheel
clamped at its axle end and its tread tied to the rail over the start's patch ("coupled",
1280-1460 Hz: the line's neighbourhood; over 900-1800 Hz its 367 modes' Krylov space did not fit
in 24 GB).

Writes docs/data/squeal_rail_modes.csv (every mode of the four steps) and
docs/img/squeal_rail_modes.png. The rail alone takes about 4.5 min and 8 GB a step on one core,
the track 7.6 min, the coupled step 37 min and 23.6 GB (of this machine's 24):

    /usr/bin/python3 regression/studies/squeal_rail_modes.py [build/bin/railfe] [--reuse]
        [--replot]
"""
import copy
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
from scipy.io import netcdf_file
from scipy.signal import butter, sosfiltfilt, welch

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE]
from railfe_runs import csv_rows, run_or_reuse, study_parser, typed_rows, write_rows  # noqa: E402
from squeal_pinned_modes import DATA, DECK, POLES, child, parameter  # noqa: E402

CSV = os.path.join(DATA, "squeal_rail_modes.csv")
FORCES = os.path.join(DATA, "squeal_case1_full_forces.csv")
PNG = os.path.join(ROOT, "docs", "img", "squeal_rail_modes.png")
BAND = (500.0, 2000.0)  # Hz
SEATS = (0.3, 0.9, 1.5, 2.1)  # m, case 1's seat centres (make_squeal_decks.sleeper_positions)
PAD_HALF = 0.075  # m, half the pad's length along the rail
PIN_HALF = 0.011  # m: a node row or two of the rail's 20 mm elements there
ZONE = (1.09, 1.24)  # m, case 1's solution zone, what the wheel rolls over
RAIL_Y = -0.0025  # m, the rail's centre
BIN = 0.05  # m
STEPS = {"pads": "the pad's footprint held vertically", "centres": "the seats' centres held"}
# The second deck: the rail on the run's pads, sleepers and ballast (the preload's Springs), alone
# and with the wheel, its tread tied to the rail over the start's patch (the run's stuck patch,
# whose penalty springs are about 25 times stiffer than the patch: r = 0.039).
TRACK_STEPS = {"track": "rail on the run's pads, sleepers and ballast",
               "coupled": "the same with the wheel, its patch tied to the rail"}
# Hz: the track's band, and the coupled step's about the line (900-1800 Hz held 367 coupled
# modes, whose Krylov space did not fit in this machine's 24 GB)
TRACK_BANDS = {"track": (900.0, 1800.0), "coupled": (1280.0, 1460.0)}
START_X = 0.7  # m, the wheel's lowest point at the start (case 1's)
PATCH_TIE = 5e10  # N/m in each direction, the tie's total
BANDS = ((950.0, 1150.0), (1250.0, 1450.0), (1500.0, 1700.0))  # Hz, the history panel's
EULER_HZ = (np.pi / 0.6) ** 2 * np.sqrt(210e9 * 2346e-8 / 54.77) / (2 * np.pi)


def deck_text():
    """Case 1's mesh and materials with a modal step of the rail per entry of STEPS."""
    tree = ET.parse(DECK)
    root = tree.getroot()
    node_sets = child(child(root, "Mesh"), "Node sets")
    for k, x in enumerate(SEATS):
        centre = ET.SubElement(node_sets, "ParameterList", {"name": f"seat {k + 1} centre"})
        parameter(centre, "Box", "Array(double)",
                  f"{{{x - PIN_HALF!r}, {x + PIN_HALF!r}, -1, 1, -1, 1}}")
        parameter(centre, "Within", "string", "rail.foot_bottom")
    steps = child(root, "Steps")
    for step in list(steps):
        steps.remove(step)
    for name in STEPS:
        step = ET.SubElement(steps, "ParameterList", {"name": name})
        parameter(step, "Module", "string", "modal")
        parameter(step, "Blocks", "Array(string)", "{rail.rail}")
        parameter(step, "Frequency band", "Array(double)", f"{{{BAND[0]:g}, {BAND[1]:g}}}")
        supports = ET.SubElement(step, "ParameterList", {"name": "Supports"})
        for k in range(len(SEATS)):
            held = ET.SubElement(supports, "ParameterList", {"name": f"seat {k + 1}"})
            parameter(held, "Node set", "string",
                      f"seat {k + 1}" + (" centre" if name == "centres" else ""))
            parameter(held, "Components", "string", "z")
        for end, node_set in (("rail start", "rail.start_face"), ("rail end", "rail.end_face")):
            held = ET.SubElement(supports, "ParameterList", {"name": end})
            parameter(held, "Node set", "string", node_set)
            parameter(held, "Components", "string", "xy")
    return ET.tostring(root, encoding="unicode")


def track_deck_text():
    """Case 1's mesh and materials with the TRACK_STEPS: the preload's springs (pads over the
    sleepers, ballast below), the sleepers' bottoms and the rail's ends held sideways and along,
    and for the coupled step the wheel clamped at the axle end and tied to the rail at the
    patch."""
    tree = ET.parse(DECK)
    root = tree.getroot()
    steps = child(root, "Steps")
    springs = copy.deepcopy(child(child(steps, "preload"), "Springs"))
    node_sets = child(child(root, "Mesh"), "Node sets")
    for name, box, within in (
            ("patch wheel", (START_X - 0.007, START_X + 0.007, -0.0085, 0.0115, -0.004, 0.004),
             "wheel.tread"),
            ("patch rail", (START_X - 0.03, START_X + 0.03, -0.015, 0.018, -0.004, 0.002),
             "rail.running_surface")):
        entry = ET.SubElement(node_sets, "ParameterList", {"name": name})
        parameter(entry, "Box", "Array(double)", "{" + ", ".join(repr(v) for v in box) + "}")
        parameter(entry, "Within", "string", within)
    for step in list(steps):
        steps.remove(step)
    sleepers = [f"sleeper {k + 1}" for k in range(len(SEATS))]
    for name in TRACK_STEPS:
        step = ET.SubElement(steps, "ParameterList", {"name": name})
        parameter(step, "Module", "string", "modal")
        blocks = ["rail.rail"] + [f"{s}.sleeper" for s in sleepers]
        if name == "coupled":
            blocks += ["wheel.wheel", "wheel.axle"]
        parameter(step, "Blocks", "Array(string)", "{" + ", ".join(blocks) + "}")
        band = TRACK_BANDS[name]
        parameter(step, "Frequency band", "Array(double)", f"{{{band[0]:g}, {band[1]:g}}}")
        supports = ET.SubElement(step, "ParameterList", {"name": "Supports"})
        held = [("rail start", "rail.start_face", "xy"), ("rail end", "rail.end_face", "xy")]
        held += [(s, f"{s}.zmin", "xy") for s in sleepers]
        if name == "coupled":
            held.append(("axle box", "wheel.axle_end", "xyz"))
        for label, node_set, components in held:
            entry = ET.SubElement(supports, "ParameterList", {"name": label})
            parameter(entry, "Node set", "string", node_set)
            parameter(entry, "Components", "string", components)
        step_springs = copy.deepcopy(springs)
        if name == "coupled":
            tie = ET.SubElement(step_springs, "ParameterList", {"name": "patch"})
            parameter(tie, "Node set", "string", "patch wheel")
            parameter(tie, "To node set", "string", "patch rail")
            parameter(tie, "Stiffness", "Array(double)", f"{{{PATCH_TIE:g}, {PATCH_TIE:g}, "
                      f"{PATCH_TIE:g}}}")
        step.append(step_springs)
    return ET.tostring(root, encoding="unicode")


class HeadBins:
    """The head's top nodes (among `mask`'s) binned every BIN along the rail."""

    def __init__(self, x, y, z, mask=True):
        self.top = mask & (z > -0.004) & (np.abs(y - RAIL_Y) < 0.006)
        edges = np.arange(0.0, 2.4 + 1e-9, BIN)
        self.which = np.digitize(x[self.top], edges) - 1
        self.centres = 0.5 * (edges[:-1] + edges[1:])

    def mean_abs(self, u):
        """Mean |u| over the head's top nodes in each bin."""
        values = np.abs(u[self.top])
        return np.array([values[self.which == k].mean() for k in range(len(self.centres))])


def displacement_fields(variables):
    """The Exodus variable names of the displacements along x, y and z."""
    names = exo_names(variables, "name_nod_var")
    return [f"vals_nod_var{names.index(f'displacement_{c}') + 1}" for c in "xyz"]


def head_profiles(exo):
    """Per mode of `exo`: bin centres x (m) and mean |u_z|, |u_y| of the head's top nodes."""
    with netcdf_file(exo, "r", mmap=False) as f:
        v = f.variables
        head = HeadBins(*(v[k][:].copy() for k in ("coordx", "coordy", "coordz")))
        _, uy_var, uz_var = displacement_fields(v)
        profiles = [(head.mean_abs(v[uz_var][t]), head.mean_abs(v[uy_var][t]))
                    for t in range(v["time_whole"].shape[0])]
    return head.centres, profiles


def exo_names(variables, key):
    return ["".join(c.decode() for c in row if c) for row in variables[key][:]]


def coupled_rows(exo, step, modes):
    """Per mode of a TRACK_STEPS step: the rail's head profile and kind (as head_profiles and
    describe), the wheel's share of the squared displacements, and how much the patch's tie
    stretches vertically against the patch's own vertical motion."""
    with netcdf_file(exo, "r", mmap=False) as f:
        v = f.variables
        x, y, z = (v[k][:].copy() for k in ("coordx", "coordy", "coordz"))
        blocks = exo_names(v, "eb_names")
        rail = np.zeros(len(x), bool)
        wheel = np.zeros(len(x), bool)
        for k, name in enumerate(blocks):
            nodes = np.unique(v[f"connect{k + 1}"][:]) - 1
            if name == "rail.rail":
                rail[nodes] = True
            elif name.startswith("wheel."):
                wheel[nodes] = True
        sets = exo_names(v, "ns_names")
        patch = {name: v[f"node_ns{sets.index(name) + 1}"][:] - 1 for name in
                 ("patch wheel", "patch rail") if name in sets}
        fields = displacement_fields(v)
        head = HeadBins(x, y, z, rail)
        rows = []
        for t, mode in enumerate(modes):
            u = [v[field][t].copy() for field in fields]
            share, ratio, kind = describe(head.centres, head.mean_abs(u[2]), head.mean_abs(u[1]))
            squared = u[0] ** 2 + u[1] ** 2 + u[2] ** 2
            row = {"supports": TRACK_STEPS[step], "mode": int(mode["mode"]),
                   "frequency_hz": float(mode["frequency_hz"]), "vertical_share": share,
                   "seat_over_midspan_vertical": ratio, "kind": kind,
                   "wheel_share": float(squared[wheel].sum() / squared.sum())}
            if patch:
                w, r = (float(u[2][patch[n]].mean()) for n in ("patch wheel", "patch rail"))
                row["patch_stretch_over_motion"] = abs(w - r) / max(abs(w), abs(r))
                # The tie is the wheel's only link to the track, so its force is the contact's:
                # per unit modal mass (the shape's own modal mass from the modes table), and
                # that squared over omega^2, the share a normal impulse at the patch puts there.
                force = PATCH_TIE * abs(w - r) / np.sqrt(float(mode["modal_mass_kg"]))
                row["patch_normal_force_per_unit_modal_mass_N"] = force
                row["patch_normal_weight"] = (force / (2 * np.pi * row["frequency_hz"])) ** 2
            rows.append(row)
    return rows


def describe(centres, uz, uy):
    """(vertical share, u_z at the seats over u_z midway between them, kind)."""
    inner = (centres > SEATS[0]) & (centres < SEATS[-1])
    share = float(np.sum(uz[inner] ** 2) / np.sum(uz[inner] ** 2 + uy[inner] ** 2))

    def near(points):
        return float(np.mean([np.interp(p, centres, uz) for p in points]))
    middles = [0.5 * (a + b) for a, b in zip(SEATS, SEATS[1:])]
    ratio = near(SEATS[1:-1]) / near(middles)
    kind = ("vertical pinned-pinned" if share > 0.5 and ratio < 1 / 3 else
            "vertical" if share > 0.5 else "lateral")
    return share, ratio, kind


def run(railfe, work, reuse):
    results, _ = run_or_reuse(railfe, deck_text(), work, "rail_modes", reuse)
    rows = []
    for step, label in STEPS.items():
        modes = csv_rows(os.path.join(results, f"{step}_modes.csv"))
        centres, profiles = head_profiles(os.path.join(results, f"{step}.exo"))
        for mode, (uz, uy) in zip(modes, profiles):
            share, ratio, kind = describe(centres, uz, uy)
            row = {"supports": label, "mode": int(mode["mode"]),
                   "frequency_hz": float(mode["frequency_hz"]), "vertical_share": share,
                   "seat_over_midspan_vertical": ratio, "kind": kind,
                   "zone_vertical_over_max": float(
                       np.max(uz[(centres > ZONE[0]) & (centres < ZONE[1])]) / np.max(uz))}
            row.update({f"head_uz_{100 * c:.0f}cm": float(u / np.max(uz))
                        for c, u in zip(centres, uz)})
            rows.append(row)
    results, _ = run_or_reuse(railfe, track_deck_text(), work, "track_modes", reuse)
    for step in TRACK_STEPS:
        rows += coupled_rows(os.path.join(results, f"{step}.exo"), step,
                             csv_rows(os.path.join(results, f"{step}_modes.csv")))
    columns = list(dict.fromkeys(k for row in rows for k in row))  # one table: NaN where none
    rows = [{k: row.get(k, float("nan")) for k in columns} for row in rows]
    write_rows(CSV, rows)
    return rows


def forces(start=0.0):
    """Case 1's normal and creep forces from `start` (s) on a uniform grid: (t, step, N, Fx)."""
    rows = [r for r in csv_rows(FORCES) if float(r["time_s"]) >= start]
    t = np.array([float(r["time_s"]) for r in rows])
    step = np.median(np.diff(t))
    grid = np.arange(t[0], t[-1], step)
    return (grid, step) + tuple(np.interp(grid, t, [float(r[c]) for r in rows])
                                for c in ("normal_force_N", "tangential_1_N"))


def spectra():
    """Welch PSDs of case 1's normal and creep forces from 2 ms: (f, normal, creep)."""
    grid, step, *values = forces(0.002)
    out = []
    for v in values:
        f, p = welch(v - v.mean(), fs=1 / step, nperseg=min(len(grid), 8192))
        out.append(p)
    return f, out[0], out[1]


def band_history(band):
    """RMS of the normal force band-passed to `band` (Hz) in 1 ms blocks: (block starts, kN)."""
    grid, step, normal, _ = forces()
    sos = butter(4, band, btype="band", fs=1 / step, output="sos")
    passed = sosfiltfilt(sos, normal - normal.mean())
    starts = np.arange(0.0, grid[-1] - 1e-3 + 1e-9, 1e-3)
    return starts, [1e-3 * np.sqrt(np.mean(passed[(grid >= a) & (grid < a + 1e-3)] ** 2))
                    for a in starts]


def coupled_panel(axis, rows):
    """The coupled modes' share of a normal impulse at the patch against their frequency."""
    if not rows:
        axis.set_visible(False)
        return
    weights = np.array([r["patch_normal_weight"] for r in rows])
    weights /= weights.sum()
    freq = [r["frequency_hz"] for r in rows]
    axis.bar(freq, weights, width=6, color=["C3" if r["wheel_share"] > 0.2 else "C2"
                                            for r in rows])
    from matplotlib.patches import Patch
    for f, w in zip(freq, weights):
        if w > 0.08:
            axis.annotate(f"{f:.0f} Hz", (f, w), textcoords="offset points", xytext=(3, 3),
                          fontsize=8)
    axis.axvspan(1327, 1392, color="grey", alpha=0.2)
    axis.set_xlim(*TRACK_BANDS["coupled"])
    decorate(axis, "frequency (Hz)", "share of a normal impulse at the patch",
             "wheel and track coupled through the start's patch (tied):\n"
             "every mode from {:g} to {:g} Hz".format(*TRACK_BANDS["coupled"]))
    axis.legend(handles=[Patch(color="C3", label="the wheel carries > 20 % of the motion"),
                         Patch(color="C2", label="mostly the track"),
                         Patch(color="grey", alpha=0.2, label="the line in the run: rim sines, "
                               "creep and normal force")], fontsize=8, loc="upper left")


def decorate(axis, xlabel, ylabel, title):
    """Labels, title, legend and grid of one panel."""
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)
    axis.set_title(title)
    axis.legend(fontsize=8)
    axis.grid(alpha=0.3)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, grid = plt.subplots(2, 2, figsize=(17, 12))
    (shapes, freqs), (history, coupled) = grid
    alone = [r for r in rows if r["supports"] in STEPS.values()]
    pinned = [r for r in alone if r["kind"] == "vertical pinned-pinned"]
    keys = sorted((k for k in rows[0] if k.startswith("head_uz_")),
                  key=lambda k: float(k[8:-2]))
    centres = [float(k[8:-2]) / 100 for k in keys]
    for r in pinned:
        style = "-" if r["supports"] == STEPS["pads"] else "--"
        shapes.plot(centres, [r[k] for k in keys], style,
                    label=f"{r['frequency_hz']:.0f} Hz, {r['supports']}")
    for x in SEATS:
        shapes.axvline(x, color="k", lw=0.8)
    shapes.axvspan(*ZONE, color="orange", alpha=0.25, label="where case 1's wheel rolls")
    decorate(shapes, "x along the rail (m; black: the seats' centres)",
             "head's vertical motion, mean |u_z| per 50 mm (of its largest)",
             "the rail's vertical pinned-pinned modes: nodes at the seats,\n"
             "antinodes midway, where the wheel rolls (the ends overhang, free)")

    f, normal, creep = spectra()
    keep = (f > 900) & (f < 1900)
    freqs.semilogy(f[keep], normal[keep], label="case 1's normal force from 2 ms (Welch)")
    freqs.semilogy(f[keep], creep[keep], label="its creep force")
    for r in alone:
        if r["kind"] == "lateral":
            continue
        colour = "C3" if r["kind"] == "vertical pinned-pinned" else "C7"
        freqs.axvline(r["frequency_hz"], color=colour,
                      linestyle="-" if r["supports"] == STEPS["pads"] else "--", lw=1)
    freqs.plot([], [], color="C3", label="rail's vertical pinned-pinned modes (solid: pads held, "
               "dashed: centres)")
    freqs.plot([], [], color="C7", label="its other vertical modes")
    for r in rows:
        if r["supports"] == TRACK_STEPS["track"] and r["kind"] != "lateral":
            freqs.axvline(r["frequency_hz"], color="C2", linestyle=":", lw=1.5)
    freqs.plot([], [], color="C2", linestyle=":", label="its vertical modes on the run's pads "
               "and sleepers")
    for r in rows:
        if r["supports"] == TRACK_STEPS["coupled"]:
            freqs.axvline(r["frequency_hz"], color="C4", lw=2.5, alpha=0.7)
    freqs.plot([], [], color="C4", lw=2.5, alpha=0.7, label="wheel and track coupled at the "
               "patch (only 1280-1460 Hz computed)")
    poles = [r for r in typed_rows(POLES, ["component", "family"])
             if 1300 < r["frequency_hz"] < 1400]
    top = freqs.get_ylim()[1]
    for r in poles:
        freqs.plot(r["frequency_hz"], top * 0.5, "kv")
    freqs.plot([], [], "kv", label="rim sines fitted near the line (every record)")
    freqs.axvline(EULER_HZ, color="k", linestyle=":", label=f"Euler beam, 0.6 m: {EULER_HZ:.0f} Hz")
    freqs.set_xlabel("frequency (Hz)")
    freqs.set_ylabel("PSD (N²/Hz)")
    freqs.set_title("the 1.33-1.39 kHz line in the forces and at the rim against the modes")
    freqs.legend(fontsize=8, loc="lower left")
    freqs.grid(alpha=0.3, which="both")
    for band in BANDS:
        starts, rms = band_history(band)
        history.plot(1e3 * (starts + 5e-4), rms, "o-", label=f"{band[0]:g}-{band[1]:g} Hz")
    history.axvline(1e3 * (SEATS[1] - 0.7) / (100 / 3.6), color="k", lw=0.8,
                    label="the wheel over seat 2")
    decorate(history, "time (ms; the wheel at x = 0.7 m + V t)",
             "normal force band-passed, RMS per 1 ms (kN)",
             "case 1: the line rings from the start and decays;\nit is no steady forcing")
    coupled_panel(coupled, [r for r in rows if r["supports"] == TRACK_STEPS["coupled"]])
    fig.tight_layout()
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=100)
    print(PNG)


def main():
    args = study_parser(__doc__.split("\n")[0], "/tmp/railfe_squeal_rail_modes", ROOT,
                        reuse=True).parse_args()
    rows = (typed_rows(CSV, ["supports", "kind"]) if args.replot
            else run(args.railfe, args.work, args.reuse))
    for r in rows:
        if r["kind"] != "lateral":
            print(f"{r['supports']:40s} {r['frequency_hz']:8.1f} Hz  {r['kind']:24s} "
                  f"vertical share {r['vertical_share']:.2f}, seats/midway "
                  f"{r['seat_over_midspan_vertical']:.2f}, in the zone "
                  f"{r['zone_vertical_over_max']:.2f}")
    plot(rows)


if __name__ == "__main__":
    main()
