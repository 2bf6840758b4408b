#!/usr/bin/env python3
"""Stability where the method fails, at full scale (issue 16): case 5 of the squeal scene
(inputs/scenes/squeal_case5.xml: falling friction mu = 0.32 + 0.18 exp(-6 s/m |v_slip|), the axle
moved sideways from 16 ms) at two time steps and two penalty factors, as
squeal_case5_stability.py does at demo scale. Each run takes hours on two cores, so this script
does not run them: it writes their decks and measures their results directories.

    deck VARIANT OUTPUT_DIR [--reference DIR] [--checkpoint DIR]
        Writes OUTPUT_DIR/case5_VARIANT.xml, a variant of the shipped deck:
        - "f1": penalty factor 1 (a quarter of the decks' 4) in the preload and the roll, so that
          the run starts in balance; from t = 0 (about 1.8 h on two cores).
        - "dt2" (the shipped deck) and "f1_dt2" (the "f1" deck) at half of the step the
          reference run (--reference: the shipped deck's or f1's results) took at its
          checkpoint, fixed ("Time step"), resumed from that checkpoint (--checkpoint: the
          directory holding roll.checkpoint.<rank> of step 200,000, t = 15.74 ms: before the
          lateral motion and the measures' window). Without the modes and preload steps, which the
          checkpoint replaces; the checkpoint and the reference's modes files are copied into
          OUTPUT_DIR. The contact history every 20 steps, so that its rows fall at the
          reference's instants (every 10 of its steps) and alias alike.
        Then run `mpirun --allow-run-as-root -np 2 railfe OUTPUT_DIR/case5_VARIANT.xml --output
        OUTPUT_DIR` on the same number of ranks as the checkpoint's.

    measure NAME DIR [NAME DIR ...]
        Each run's measures over 16.5-19 ms (the lateral motion under way) into
        docs/data/squeal_case5_full_stability.csv (rows of runs not given are kept, those given
        replaced), and docs/img/squeal_case5_full_stability.png: the force histories of the runs
        given, and from the CSV the creep force's RMS per half-octave band and where in the patch
        the slip lies. NAME is one of ref, dt2, f1, f1_dt2.

The measures: mean and spread (also about a quadratic trend) of the normal, longitudinal and
lateral forces; the detrended longitudinal creep force's RMS below 5 kHz (the wheel's modes and
the 1.25 kHz creep-force oscillation), 5-40 kHz (the 1 mm mesh's passing frequency V / h = 27.8
kHz) and above 40 kHz (the penalty-friction chatter of the demo-scale study), and per half
octave; the nodes in contact and slipping, and how much the slipping count changes from one
history row to the next (the flicker); the friction coefficient the patch uses (bound / N); from
the patch files after 16.5 ms (the 0.25 us burst at 18.55 ms counted once): the share of
node-instants slipping in the leading and trailing thirds and rows of the patch, and the slip
speeds.
"""
import argparse
import json
import os
import shutil
import sys
import xml.etree.ElementTree as ET

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "regression", "charts"))
from railfe_runs import kept_rows, step_section, write_rows  # noqa: E402
import squeal_case5_stability as demo  # noqa: E402
from patch_centre_line import read_patch  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "scenes", "squeal_case5.xml")
CSV = os.path.join(ROOT, "docs", "data", "squeal_case5_full_stability.csv")
PNG = os.path.join(ROOT, "docs", "img", "squeal_case5_full_stability.png")
PAIR = "roll_contact_wheel-rail"
VARIANTS = ("f1", "dt2", "f1_dt2")
RUN_NAMES = ("ref",) + VARIANTS
SHIPPED_PENALTY = 4.0
SOFT_PENALTY = 1.0
CHECKPOINT_TIME = 15.74e-3  # s: step 200,000 of the shipped deck
WINDOW = (16.5e-3, 19e-3)  # s
BURST = (18.5502e-3, 18.558e-3)  # s: the decks' burst of patch files, but for its first
BANDS = {"below_5kHz": (3e2, 5e3), "5_40kHz": (5e3, 4e4), "above_40kHz": (4e4, np.inf)}
HALF_OCTAVES = 1e3 * 2.0 ** (np.arange(19) / 2)  # Hz: 1 to 512 kHz (each band holds a line of the
# window's 0.4 kHz resolution), below the histories' Nyquist frequency (635 kHz at 0.79 us)
ROW_DEPTH = 0.5e-3  # m: half the 1 mm contact elements, one row of nodes
S1_BINS = np.arange(-6.0, 6.01, 1.0)  # mm, along the rolling direction


def steps_list(tree):
    return tree.getroot().find("ParameterList[@name='Steps']")


def parameter(node, name):
    found = node.find(f"Parameter[@name='{name}']")
    if found is None:
        raise SystemExit(f"{DECK}: no {name!r} under {node.get('name')!r}: the deck generator "
                         "changed, and this study must change with it")
    return found


def set_penalty(tree, factor):
    """The contact pair's penalty factor, in the preload and the roll alike."""
    found = [p for p in steps_list(tree).iter("Parameter") if p.get("name") == "Penalty factor"]
    if len(found) != 2:
        raise SystemExit(f"{DECK}: expected the penalty factor in two steps, found {len(found)}")
    for p in found:
        p.set("value", f"{factor:g}")


def reference_step(reference):
    """The step (s) the reference run took at the checkpoint, from its energy history."""
    path = os.path.join(reference, "roll_energy.csv")
    if not os.path.isfile(path):
        raise SystemExit(f"--reference {reference}: no roll_energy.csv (not a run of case 5)")
    rows = np.genfromtxt(path, delimiter=",", names=True)
    near = np.abs(rows["time_s"] - CHECKPOINT_TIME) < 2e-4
    if not near.any():
        raise SystemExit(f"{path}: no rows near the checkpoint's {CHECKPOINT_TIME} s")
    return float(np.median(rows["time_step_s"][near]))


def branch(tree, step):
    """The deck resumed from a checkpoint at a fixed step: without the steps the checkpoint
    replaces (and the roll's settings that only a start from the preload takes), its contact
    history every 20 steps."""
    steps = steps_list(tree)
    roll = steps.find("ParameterList[@name='roll']")
    for name in ("modes", "preload"):
        steps.remove(steps.find(f"ParameterList[@name='{name}']"))
    for name in ("Start from", "Preload frame velocity"):
        roll.remove(parameter(roll, name))
    end = parameter(roll, "End time")
    fixed = ET.Element("Parameter", {"name": "Time step", "type": "double",
                                     "value": f"{step:.10g}"})
    roll.insert(list(roll).index(end) + 1, fixed)
    output = roll.find("ParameterList[@name='Output']")
    parameter(output, "History interval").set("value", "20")


def write_deck(variant, output, reference, checkpoint):
    tree = ET.parse(DECK)
    title = parameter(tree.getroot(), "Title")
    title.set("value", f"{title.get('value')}: stability study variant {variant}")
    if variant.startswith("f1"):
        set_penalty(tree, SOFT_PENALTY)
    if variant.endswith("dt2"):
        if reference is None or checkpoint is None:
            raise SystemExit(f"{variant}: give --reference (the run at the full step) and "
                             "--checkpoint (the directory of its roll.checkpoint.<rank>)")
        ranks = sorted(f for f in os.listdir(checkpoint) if f.startswith("roll.checkpoint."))
        if not ranks:
            raise SystemExit(f"--checkpoint {checkpoint}: no roll.checkpoint.<rank> files")
        step = 0.5 * reference_step(reference)
        branch(tree, step)
        os.makedirs(output, exist_ok=True)
        for name in ranks:
            shutil.copy(os.path.join(checkpoint, name), output)
        for name in ("modes_modes.csv", "modes.exo"):
            if os.path.isfile(os.path.join(reference, name)):
                shutil.copy(os.path.join(reference, name), output)
        print(f"{variant}: fixed step {step:.6g} s, resumed from {len(ranks)} rank files")
    os.makedirs(output, exist_ok=True)
    path = os.path.join(output, f"case5_{variant}.xml")
    with open(path, "w") as f:
        f.write(f"<!--\n  Squeal case 5, stability study variant {variant!r}, written by "
                f"regression/studies/squeal_case5_full_stability.py from "
                f"inputs/scenes/squeal_case5.xml.\n-->\n")
        tree.write(f, encoding="unicode")
    print(path)


def window_patches(results):
    """The patch files inside the window, the burst counted once, in time order."""
    patches = []
    for name in os.listdir(results):
        if name.startswith(f"{PAIR}_patch_") and name.endswith(".csv"):
            patch = read_patch(os.path.join(results, name))
            t = float(patch["time_s"][0])
            if WINDOW[0] - 1e-9 <= t <= WINDOW[1] + 1e-9 and not BURST[0] <= t <= BURST[1]:
                patches.append((t, patch))
    return [p for _, p in sorted(patches, key=lambda item: item[0])]


def thirds_and_bins(patches):
    """Share of node-instants slipping in the leading and trailing thirds of each patch's length,
    and per S1_BINS bin about the patch's middle (mm)."""
    lead, trail, rel, slip = [], [], [], []
    for p in patches:
        s1, slipping = p["s1_m"], p["slipping"] > 0.5
        lo, hi = s1.min(), s1.max()
        third = (hi - lo) / 3
        lead += list(slipping[s1 >= hi - third])
        trail += list(slipping[s1 <= lo + third])
        rel += list(1e3 * (s1 - 0.5 * (lo + hi)))
        slip += list(slipping)
    rel, slip = np.array(rel), np.array(slip)
    row = {"leading_third_slip_fraction": float(np.mean(lead)),
           "trailing_third_slip_fraction": float(np.mean(trail))}
    for lo, hi in zip(S1_BINS[:-1], S1_BINS[1:]):
        inside = (rel >= lo) & (rel < hi)
        row[f"slip_share_s1_{0.5 * (lo + hi):+.1f}mm"] = (
            float(slip[inside].mean()) if inside.sum() >= 5 else float("nan"))
    return row


def measures(name, results):
    """One run's row of the study's table."""
    with open(os.path.join(results, "summary.json")) as f:
        roll = step_section(json.load(f), "roll")
    h = demo.history(results)
    t = h["time_s"]
    m = (t >= WINDOW[0] - 1e-12) & (t <= WINDOW[1] + 1e-12)
    row = {"run": name, "penalty_factor": SOFT_PENALTY if name.startswith("f1") else
           SHIPPED_PENALTY, "history_interval_s": float(np.median(np.diff(t[m]))),
           "steps": float(roll["steps"]),
           "contact_critical_step_s": float(roll["contact critical step [s]"]),
           "roll_stepping_s": float(roll["time: stepping [s]"]),
           "energy_error_at_end": float(roll["energy error at end"])}
    for key, column in demo.FORCES.items():
        y = h[column][m]
        _, res = demo.detrended(t[m], y)
        row[f"{key}_mean_N"] = float(y.mean())
        row[f"{key}_std_N"] = float(y.std())
        row[f"{key}_detrended_std_N"] = float(res.std())
    dt, res = demo.detrended(t[m], h["tangential_1_N"][m])
    for label, (lo, hi) in BANDS.items():
        row[f"creep_rms_{label}_N"] = demo.band_rms(res, dt, lo, hi)
    f, a, _, _ = demo.spectrum(t[m], h["tangential_1_N"][m])
    row["creep_peak_below_5kHz_Hz"], row["creep_peak_below_5kHz_amplitude_N"] = demo.peak(
        f, a, *BANDS["below_5kHz"])
    for lo, hi in zip(HALF_OCTAVES[:-1], HALF_OCTAVES[1:]):
        row[f"creep_rms_band_{np.sqrt(lo * hi):.0f}Hz_N"] = demo.band_rms(res, dt, lo, hi)
    dt, res = demo.detrended(t[m], h["normal_force_N"][m])
    row["normal_rms_above_40kHz_N"] = demo.band_rms(res, dt, *BANDS["above_40kHz"])
    row["active_nodes_mean"] = float(h["active_nodes"][m].mean())
    row["slipping_nodes_mean"] = float(h["slipping_nodes"][m].mean())
    row["slipping_nodes_min"] = float(h["slipping_nodes"][m].min())
    row["slipping_nodes_max"] = float(h["slipping_nodes"][m].max())
    row["slipping_nodes_row_change_mean"] = float(np.abs(np.diff(h["slipping_nodes"][m])).mean())
    row["friction_coefficient_in_use_mean"] = float(
        (h["friction_bound_N"][m] / h["normal_force_N"][m]).mean())
    row["max_penetration_mean_m"] = float(h["max_penetration_m"][m].mean())
    patches = window_patches(results)
    if not patches:
        raise SystemExit(f"{results}: no patch files over {WINDOW[0]}-{WINDOW[1]} s")
    row.update(demo.patch_measures(patches, row_depth=ROW_DEPTH))
    row.update(thirds_and_bins(patches))
    return row


STYLE = {"ref": dict(color="C0", linestyle="-"), "dt2": dict(color="C0", linestyle=":"),
         "f1": dict(color="C3", linestyle="-"), "f1_dt2": dict(color="C3", linestyle=":")}


def label(row):
    step = "half step" if row["run"].endswith("dt2") else "shipped step"
    return f"penalty {float(row['penalty_factor']):g}, {step}"


def plot(rows, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 2, figsize=(13, 12))
    (fx, zoom), (fy, nodes), (sp, slipax) = axes
    for row in rows:
        name, style = row["run"], STYLE[row["run"]]
        lw = 1.6 if style["linestyle"] == ":" else 0.8
        if name in results:
            h = demo.history(results[name])
            late = h["time_s"] >= 15.5e-3
            t = 1e3 * h["time_s"][late]
            fx.plot(t, 1e-3 * h["tangential_1_N"][late], linewidth=lw, label=label(row), **style)
            fy.plot(t, 1e-3 * h["tangential_2_N"][late], linewidth=lw, **style)
            last = h["time_s"] >= 18.8e-3
            zoom.plot(1e3 * h["time_s"][last], 1e-3 * h["tangential_1_N"][last], linewidth=lw,
                      **style)
            width = max(1, int(round(2e-5 / np.median(np.diff(h["time_s"])))))  # 20 us
            running = np.convolve(h["slipping_nodes"][late], np.ones(width) / width, "valid")
            nodes.plot(t[width - 1:], running, linewidth=lw, **style)
        bands = sorted((float(k.split("_")[3][:-2]), float(v)) for k, v in row.items()
                       if k.startswith("creep_rms_band_"))
        sp.loglog([1e-3 * b for b, _ in bands], [v for _, v in bands], marker="o", markersize=3,
                  linewidth=lw, label=label(row), **style)
        bins = sorted((float(k.split("_")[3][:-2]), float(v)) for k, v in row.items()
                      if k.startswith("slip_share_s1_"))
        slipax.plot([b for b, _ in bins], [100 * v for _, v in bins], marker="o", markersize=4,
                    linewidth=lw, **style)
    for axis in (fx, fy, nodes):
        axis.axvspan(1e3 * WINDOW[0], 1e3 * WINDOW[1], color="0.92", zorder=0)
    sp.axvspan(5, 40, color="0.92", zorder=0)
    s1_label = "s1 from the patch's middle (mm; + = leading edge)"
    texts = {  # axis: (x label, y label, title)
        fx: ("time (ms)", "longitudinal creep force (kN)", ""),
        zoom: ("time (ms)", "longitudinal creep force (kN)", "the last 0.2 ms"),
        fy: ("time (ms)", "lateral creep force (kN)", ""),
        nodes: ("time (ms)", "slipping nodes (20 us running mean)", ""),
        sp: ("frequency (kHz)", "RMS in the half-octave band (N)",
             "detrended longitudinal creep force, 16.5-19 ms\n(shaded: 5-40 kHz, the 1 mm mesh "
             "passing at 27.8 kHz)"),
        slipax: (s1_label, "node-instants slipping (%)",
                 "slip along the patch, patch files 16.5-19 ms (1 mm bins)")}
    for axis, (x_label, y_label, title) in texts.items():
        axis.set(xlabel=x_label, ylabel=y_label)
        axis.set_title(title, fontsize=10)
    fx.legend(fontsize=8, loc="lower right")
    sp.legend(fontsize=8)
    demo.finish_chart(fig, sp, "Squeal scene, case 5 (falling friction) at full scale: two steps, "
                      "two penalty factors\n(shaded: the 16.5-19 ms window of the measures)", PNG)


def measure(pairs):
    if len(pairs) % 2:
        raise SystemExit("measure takes pairs NAME DIR")
    results = dict(zip(pairs[::2], pairs[1::2]))
    for name, directory in results.items():
        if name not in RUN_NAMES:
            raise SystemExit(f"measure: run name {name!r}: one of {', '.join(RUN_NAMES)}")
        if not os.path.isfile(os.path.join(directory, "summary.json")):
            raise SystemExit(f"measure {name} {directory}: no summary.json (not a finished run)")
    rows = kept_rows(CSV, "run", results)
    for name, directory in results.items():
        rows.append(measures(name, directory))
        print(f"{name}: measured {directory}", flush=True)
    rows.sort(key=lambda r: RUN_NAMES.index(r["run"]))
    write_rows(CSV, rows)
    plot(rows, results)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    deck = sub.add_parser("deck", help="write a variant's deck")
    deck.add_argument("variant", choices=VARIANTS)
    deck.add_argument("output", help="the variant's results directory")
    deck.add_argument("--reference", help="results of the run at the full step")
    deck.add_argument("--checkpoint", help="directory of that run's roll.checkpoint.<rank>")
    run = sub.add_parser("measure", help="measure runs: NAME DIR pairs")
    run.add_argument("pairs", nargs="+")
    args = parser.parse_args()
    if args.command == "deck":
        write_deck(args.variant, args.output, args.reference, args.checkpoint)
    else:
        measure(args.pairs)


if __name__ == "__main__":
    main()
