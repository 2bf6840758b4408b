#!/usr/bin/env python3
"""Shear stress and traction bound along a contact patch's centre line at several instants (the
squeal scene's Fig. 5): one panel per patch file <step>_contact_<pair>_patch_<k>.csv, with the
longitudinal and lateral shear traction and the bound mu p of the nodes on the centre line, the
row of slave nodes nearest the line through the patch centre (s2 = 0: the files' s1, s2 are about
the force-weighted centre) along the rolling direction s1. Slipping nodes are marked.

    /usr/bin/python3 regression/charts/patch_centre_line.py --mu 0.45 --png out.png \\
        [--csv out.csv] roll_contact_wheel-rail_patch_1.csv roll_contact_wheel-rail_patch_2.csv ...

Without --mu the friction coefficient is the median |q| / p of the slipping nodes (said in the
title). For falling friction (the squeal scene's case 5), --falling MU_S MU_D DECAY gives each
node its own bound mu(v) p, mu(v) = MU_D + (MU_S - MU_D) exp(-DECAY |v|) at the node's slip speed
|v| in the file, the law the explicit contact applies. --csv writes the centre-line values of
every panel.
"""
import argparse
import csv
import math

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLUMNS = ("time_s", "s1_m", "s2_m", "pressure_Pa", "shear_1_Pa", "shear_2_Pa",
           "slip_velocity_1_m/s", "slip_velocity_2_m/s", "slipping")


def read_patch(path):
    """The columns of a patch file as numpy arrays (node, area_m2 and the positions x_m, y_m, z_m
    too where the file has them)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no node in contact")
    names = COLUMNS + tuple(n for n in ("node", "area_m2", "x_m", "y_m", "z_m") if n in rows[0])
    return {name: np.array([float(r[name]) for r in rows]) for name in names}


def node_spacing(patch):
    """The median distance from a node to its nearest neighbour in the contact plane (m)."""
    s = np.column_stack([patch["s1_m"], patch["s2_m"]])
    d = np.hypot(s[:, None, 0] - s[None, :, 0], s[:, None, 1] - s[None, :, 1])
    np.fill_diagonal(d, np.inf)
    return float(np.median(d.min(axis=1)))


def centre_line(patch):
    """Indices of the row of nodes nearest s2 = 0, within 0.3 node spacings of that row, by s1."""
    s2 = patch["s2_m"]
    row = s2[np.argmin(np.abs(s2))]
    chosen = np.flatnonzero(np.abs(s2 - row) <= 0.3 * node_spacing(patch))
    if len(chosen) < 2:
        raise SystemExit(f"t = {patch['time_s'][0]:g} s: fewer than 2 nodes on the centre line")
    return chosen[np.argsort(patch["s1_m"][chosen])]


def estimated_friction(patches):
    """The median |q| / p over the slipping nodes of every patch (None without any)."""
    ratios = []
    for p in patches:
        slip = (p["slipping"] > 0.5) & (p["pressure_Pa"] > 0)
        ratios += list(np.hypot(p["shear_1_Pa"][slip], p["shear_2_Pa"][slip])
                       / p["pressure_Pa"][slip])
    return float(np.median(ratios)) if ratios else None


def panel(ax, patch, mu):
    """Draws one instant's centre line on \\p ax; returns its rows for the CSV. \\p mu maps the
    nodes' slip speeds (m/s) to their friction coefficients."""
    line = centre_line(patch)
    s1 = 1e3 * patch["s1_m"][line]
    speed = np.hypot(patch["slip_velocity_1_m/s"][line], patch["slip_velocity_2_m/s"][line])
    bound = 1e-6 * mu(speed) * patch["pressure_Pa"][line]
    q1 = 1e-6 * patch["shear_1_Pa"][line]
    q2 = 1e-6 * patch["shear_2_Pa"][line]
    slip = patch["slipping"][line] > 0.5
    ax.fill_between(s1, -bound, bound, color="0.9", label="±μp")
    ax.plot(s1, bound, "k-", lw=1)
    ax.plot(s1, -bound, "k-", lw=1)
    ax.plot(s1, q1, "o-", color="tab:blue", ms=3, label="longitudinal q1")
    ax.plot(s1, q2, "s-", color="tab:orange", ms=3, label="lateral q2")
    ax.plot(s1[slip], q1[slip], "x", color="red", ms=7, label="slipping node")
    time = patch["time_s"][0]
    ax.set_title(f"t = {1e3 * time:.4f} ms (s2 = {1e3 * patch['s2_m'][line].mean():.2f} mm)",
                 fontsize=9)
    ax.grid(alpha=0.3)
    return [(time, *values, int(s)) for *values, s in zip(s1, bound, q1, q2, slip)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("patches", nargs="+", help="patch CSV files, in time order")
    parser.add_argument("--mu", type=float, help="friction coefficient of the bound mu p")
    parser.add_argument("--falling", type=float, nargs=3, metavar=("MU_S", "MU_D", "DECAY"),
                        help="velocity-dependent friction: static and dynamic coefficients and "
                             "the decay (s/m)")
    parser.add_argument("--png", required=True)
    parser.add_argument("--csv", help="write the centre-line values here")
    args = parser.parse_args()
    if args.mu is not None and args.falling:
        parser.error("--mu and --falling: give one friction law")
    patches = [read_patch(path) for path in args.patches]
    if args.falling:
        mu_s, mu_d, decay = args.falling
        if not (0 < mu_d <= mu_s and decay >= 0):
            parser.error("--falling MU_S MU_D DECAY: need 0 < MU_D <= MU_S and DECAY >= 0")
        law = lambda v: mu_d + (mu_s - mu_d) * np.exp(-decay * v)  # noqa: E731
        title = f"μ = {mu_d:g} + {mu_s - mu_d:g} exp(−{decay:g} s/m |v|), each node's slip speed"
    else:
        mu = args.mu if args.mu is not None else estimated_friction(patches)
        if mu is None:
            raise SystemExit("no slipping node to estimate mu from: give --mu")
        source = "given" if args.mu is not None else "estimated from the slipping nodes"
        law = lambda v: np.full_like(v, mu)  # noqa: E731
        title = f"μ = {mu:.3g}, {source}"
    columns = min(4, len(patches))
    rows = math.ceil(len(patches) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 3.2 * rows), sharex=True,
                             sharey=True, squeeze=False)
    table = []
    for ax, patch in zip(axes.flat, patches):
        table += panel(ax, patch, law)
    for ax in axes.flat[len(patches):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("s1 along the rolling direction (mm)")
    for ax in axes[:, 0]:
        ax.set_ylabel("shear traction (MPa)")
    axes.flat[0].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"Shear traction and bound μp along the patch centre line ({title})")
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["time_s", "s1_mm", "mu_p_MPa", "shear_1_MPa", "shear_2_MPa",
                          "slipping"])
            out.writerows(table)


if __name__ == "__main__":
    main()
