#!/usr/bin/env python3
"""The wheel's modes with its tread held where the patch is, beside its modes with the tread
free (issue 16, Table 4): the bound the rolling wheel's modes lie between.

The modal step of the squeal decks computes the wheel and half axle clamped at the axle end,
tread free. In the rolling run the tread sticks to the rail over the patch's stick zone, so each
mode is stiffened by the patch and the rail behind it; held rigidly is the stiff bound. A mode
with n >= 1 nodal diameters is a pair; with the tread held, the member with its nodal line
through the patch keeps its free frequency, and cannot be excited by a force there either (its
shape is zero there); the other member, with its antinode at the patch, is stiffened away. A mode
with n = 0 has no such twin. Which modes the held wheel has is what this study computes; where
the rolling wheel's lie between the bounds, squeal_rim_visibility.py measures (the (0,3) member:
+7 % rolling, +35 % held rigidly).

The deck is case 1's (inputs/scenes/squeal_case1.xml), its modal step kept, two more beside it:
  modes           the scene's: tread free;
  held_lateral    the tread's nodes in the patch held across the rail (y) only;
  held            the same nodes held in x, y and z (stuck to a rigid rail).
The patch is a box PATCH about the wheel's lowest running point, the size of case 1's patch
(semi-axes 6.8 x 9.9 mm). The held steps are not axisymmetric, so their pairs have no partner:
their doublet check warns instead of failing.

For each held mode the study gives its frequency, lateral effective mass and dominant
harmonic (railfe's classification), and which free mode it comes from: the mass-weighted
projection of its shape on each free mode's (lumped steel mass from the element volumes), the
largest and the share it has in the (0,3) pair. Each damped sine fitted to the full-scale rim
records (docs/data/squeal_full_rim_poles.csv, squeal_full_scale_results.py) then gets the
nearest free and the nearest held mode.

Writes docs/data/squeal_pinned_modes.csv (every mode of the three steps),
docs/data/squeal_pinned_modes_matches.csv (every fitted sine) and docs/img/squeal_pinned_modes.png.
The three modal steps take about 9 min on one core:

    /usr/bin/python3 regression/studies/squeal_pinned_modes.py [build/bin/railfe] [--reuse]
        [--replot]
"""
import copy
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
from scipy.io import netcdf_file

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path[:0] = [HERE]
from railfe_runs import csv_rows, run_or_reuse, study_parser, typed_rows, write_rows  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "scenes", "squeal_case1.xml")
DATA = os.path.join(ROOT, "docs", "data")
CSV = os.path.join(DATA, "squeal_pinned_modes.csv")
MATCHES = os.path.join(DATA, "squeal_pinned_modes_matches.csv")
POLES = os.path.join(DATA, "squeal_full_rim_poles.csv")
PNG = os.path.join(ROOT, "docs", "img", "squeal_pinned_modes.png")
# Case 1's patch at full scale (the pulse run's: 6.77 x 9.91 mm, its pressure centre about
# 1.5 mm towards the flange): semi-axes along and across the rail and the centre's y (m).
PATCH = (0.007, 0.010, 0.0015)
STEPS = {"modes": "", "held_lateral": "y", "held": "xyz"}
LABELS = {"modes": "tread free (the scene's modal step)",
          "held_lateral": "tread held across the rail",
          "held": "tread held in x, y, z"}
BAND = (20.0, 2500.0)  # Hz, the scene's modal step's


def child(node, name):
    """The sublist or parameter `name` of `node` (None if absent)."""
    return next((c for c in node if c.get("name") == name), None)


def parameter(node, name, kind, value):
    ET.SubElement(node, "Parameter", {"name": name, "type": kind, "value": value})


def deck_text():
    """Case 1's deck with only its modal step, and the two held steps beside it."""
    tree = ET.parse(DECK)
    root = tree.getroot()
    steps = child(root, "Steps")
    modes = child(steps, "modes")
    for step in list(steps):
        if step is not modes:
            steps.remove(step)
    origin = [float(v) for v in child(child(modes, "Classification"), "Axis origin")
              .get("value").strip("{}").split(",")]
    a, b, y0 = PATCH
    node_sets = child(child(root, "Mesh"), "Node sets")
    patch = ET.SubElement(node_sets, "ParameterList", {"name": "patch"})
    # z from below the tread's lowest point to the height the tread rises to at x = +-a
    box = [origin[0] - a, origin[0] + a, y0 - b, y0 + b, -0.003, 0.003]
    parameter(patch, "Box", "Array(double)", "{" + ", ".join(f"{v:.6g}" for v in box) + "}")
    parameter(patch, "Within", "string", "wheel.tread")
    for name, components in STEPS.items():
        if not components:
            continue
        held = copy.deepcopy(modes)
        held.set("name", name)
        parameter(held, "On failed check", "string", "warn")
        support = ET.SubElement(child(held, "Supports"), "ParameterList", {"name": "patch"})
        parameter(support, "Node set", "string", "patch")
        parameter(support, "Components", "string", components)
        steps.append(held)
    title = child(root, "Title")
    title.set("value", "Squeal scene's wheel (full scale): modes with the tread free and held "
                       "at the patch (regression/studies/squeal_pinned_modes.py)")
    return ET.tostring(root, encoding="unicode") + "\n"


def lumped_masses(data, blocks):
    """Each node's share of the steel volume of the element blocks `blocks` (1-based ids):
    a hex8's volume (its centre Jacobian) split equally among its nodes."""
    v = data.variables
    xyz = np.stack([np.array(v[f"coord{c}"][:]) for c in "xyz"], axis=1)
    weights = np.zeros(len(xyz))
    signs = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                      [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)
    for block in blocks:
        connect = np.array(v[f"connect{block}"][:], dtype=int) - 1
        corners = xyz[connect]  # elements x 8 x 3
        jacobian = np.einsum("ka,ekc->eac", signs, corners) / 8.0
        volume = 8.0 * np.abs(np.linalg.det(jacobian))
        np.add.at(weights, connect.ravel(), np.repeat(volume / 8.0, 8))
    return weights


def block_ids(data, names):
    """The 1-based ids of the element blocks named `names`."""
    stored = ["".join(c.decode() for c in row if c != b"").strip()
              for row in data.variables["eb_names"][:]]
    return [stored.index(name) + 1 for name in names]


def shapes(exodus):
    """The mode shapes in `exodus` (modes x nodes x 3) and the open file."""
    data = netcdf_file(exodus, "r", mmap=False)
    v = data.variables
    return np.stack([np.array(v[f"vals_nod_var{c}"][:]) for c in (1, 2, 3)], axis=2), data


def projections(results):
    """For every step: its mode shapes projected (mass-weighted) on the free step's, each row
    normalised to the mode's own mass-weighted norm: the share of each free mode in it."""
    free, data = shapes(os.path.join(results, "modes.exo"))
    weights = lumped_masses(data, block_ids(data, ["wheel.wheel", "wheel.axle"]))
    data.close()

    def inner(p, q):
        return (p * weights[None, :, None]).reshape(len(p), -1) @ q.reshape(len(q), -1).T
    free_norm = np.diag(inner(free, free))
    out = {}
    for step in STEPS:
        shape, data = shapes(os.path.join(results, f"{step}.exo"))
        data.close()
        cross = inner(shape, free)
        own = np.diag(inner(shape, shape))
        out[step] = cross ** 2 / np.outer(own, free_norm)
    return out


def mode_rows(results):
    """Every mode of the three steps with its nearest free mode by shape."""
    tables = {step: csv_rows(os.path.join(results, f"{step}_modes.csv")) for step in STEPS}
    free = tables["modes"]
    pair03 = [i for i, r in enumerate(free)
              if r["family"] == "axial" and r["nodal_diameters"] == "3"]
    shares = projections(results)
    rows = []
    for step, table in tables.items():
        for k, row in enumerate(table):
            share = shares[step][k]
            best = int(np.argmax(share))
            rows.append({
                "step": step, "mode": int(row["mode"]),
                "frequency_hz": float(row["frequency_hz"]), "family": row["family"],
                "nodal_diameters": int(row["nodal_diameters"]),
                "nodal_circles": int(row["nodal_circles"]),
                "effective_mass_y_kg": float(row["effective_mass_y_kg"]),
                "note": row["note"],
                "nearest_free_mode": int(free[best]["mode"]),
                "nearest_free_hz": float(free[best]["frequency_hz"]),
                "nearest_free_share": float(share[best]),
                "share_in_03_pair": float(share[pair03].sum()),
                "frequency_over_nearest_free": float(row["frequency_hz"]) /
                float(free[best]["frequency_hz"])})
    return rows


def match_rows(rows):
    """Each fitted sine of the full-scale rim records with the nearest free and held mode."""
    out = []
    for pole in typed_rows(POLES, ["component", "family"]):
        f = pole["frequency_hz"]
        entry = {"component": pole["component"], "case": int(pole["case"]),
                 "record_start_s": pole["record_start_s"], "frequency_hz": f,
                 "damping_ratio": pole["damping_ratio"], "rms_m_per_s": pole["rms"]}
        for step in STEPS:
            modes = [r for r in rows if r["step"] == step]
            near = min(modes, key=lambda r: abs(r["frequency_hz"] - f))
            entry[f"{step}_mode"] = near["mode"]
            entry[f"{step}_hz"] = near["frequency_hz"]
            entry[f"{step}_difference_percent"] = 100 * (f / near["frequency_hz"] - 1)
        out.append(entry)
    return out


def plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = typed_rows(CSV, ["step", "family", "note"])
    poles = typed_rows(MATCHES, ["component"])
    fig, axis = plt.subplots(figsize=(11, 7))
    columns = list(STEPS)
    for x, step in enumerate(columns):
        labelled = []  # one label for a pair's two members
        for r in (r for r in rows if r["step"] == step and r["frequency_hz"] <= BAND[1]):
            in03 = r["share_in_03_pair"] > 0.2
            colour = "C3" if in03 else ("C0" if r["effective_mass_y_kg"] > 1 else "grey")
            axis.plot([x - 0.3, x + 0.3], [r["frequency_hz"]] * 2, color=colour,
                      lw=2.5 if in03 or r["effective_mass_y_kg"] > 1 else 1)
            if in03 and all(abs(r["frequency_hz"] - f) > 30 for f in labelled):
                labelled.append(r["frequency_hz"])
                axis.annotate(f"{r['frequency_hz']:.0f} Hz: {100 * r['share_in_03_pair']:.0f} % "
                              f"(0,3)", (x + 0.3, r["frequency_hz"]), fontsize=7,
                              xytext=(3, -3), textcoords="offset points", color="C3")
    markers = {"lateral": "o", "radial": "s", "circumferential": "^"}
    seen = set()
    for p in poles:
        x = len(columns) + 0.1 * ("lateral", "radial", "circumferential").index(p["component"])
        label = None if p["component"] in seen else f"fitted sine, rim {p['component']}"
        seen.add(p["component"])
        axis.plot(x, p["frequency_hz"], markers[p["component"]], color="k", mfc="none",
                  label=label)
        axis.axhline(p["frequency_hz"], color="k", lw=0.3, ls=":")
    axis.set_xticks(range(len(columns) + 1))
    axis.set_xticklabels([LABELS[s] for s in columns] + ["rolling records\n(cases 1, 5)"],
                         fontsize=8)
    axis.set_ylim(0, BAND[1])
    axis.set_ylabel("frequency (Hz)")
    axis.plot([], [], color="C3", lw=2.5, label="(0,3) pair's share > 20 %")
    axis.plot([], [], color="C0", lw=2.5, label="lateral effective mass > 1 kg")
    axis.plot([], [], color="grey", lw=1, label="other modes")
    axis.legend(fontsize=8, loc="lower right")
    axis.set_title("Squeal scene's wheel at full scale: modes with the tread free and held at "
                   "the patch,\nagainst the damped sines fitted to the rolling rim records",
                   fontsize=10)
    fig.tight_layout()
    fig.savefig(PNG, dpi=100)


def main():
    args = study_parser(__doc__.split("\n")[0], "/tmp/railfe_squeal_pinned_modes", ROOT,
                        reuse=True).parse_args()
    if not args.replot:
        rows = mode_rows(run_or_reuse(args.railfe, deck_text(), args.work, "held_modes",
                                      args.reuse)[0])
        write_rows(CSV, rows)
        write_rows(MATCHES, match_rows(rows))
    plot()


if __name__ == "__main__":
    main()
