#!/usr/bin/env python3
"""Map of one contact patch written by an explicit step with contact pairs: on the left the
pressure as colour with the shear traction as arrows, on the right the micro-slip velocity as
arrows over the stick (blue) and slip (red) nodes, both in the contact plane (s1 along the pair's
Longitudinal direction, s2 across).

    /usr/bin/python3 regression/charts/contact_patch_map.py <step>_contact_<pair>_patch_<k>.csv out.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def column(rows, name):
    return [float(r[name]) for r in rows]


def pressure_shear_panel(fig, ax, s1, s2, pressure, shear1, shear2, marker_size=40, arrows=None):
    """Pressure (MPa) as colour at points s1, s2 (mm) with the shear traction (Pa) as arrows, at
    the points \p arrows (indices; every point when None)."""
    dots = ax.scatter(s1, s2, c=pressure, cmap="viridis", s=marker_size, marker="s")
    fig.colorbar(dots, ax=ax, label="pressure (MPa)")
    chosen = range(len(s1)) if arrows is None else arrows
    if any(shear1) or any(shear2):
        ax.quiver([s1[i] for i in chosen], [s2[i] for i in chosen], [shear1[i] for i in chosen],
                  [shear2[i] for i in chosen], color="white", edgecolor="black", linewidth=0.4,
                  width=0.004)
    ax.set_title(f"pressure and shear traction (largest {max(pressure):.4g} MPa)")


def slip_panel(ax, s1, s2, slip1, slip2, slipping, unit="m/s", marker_size=30):
    """Stick (blue) and slip (red) points with the micro-slip of the slipping ones as arrows."""
    stick = [i for i, s in enumerate(slipping) if not s]
    slip = [i for i, s in enumerate(slipping) if s]
    for group, colour, label in ((stick, "tab:blue", "not slipping"), (slip, "tab:red", "slip")):
        if group:
            ax.scatter([s1[i] for i in group], [s2[i] for i in group], c=colour, s=marker_size,
                       marker="s", alpha=0.5, label=f"{label} ({len(group)} points)")
    if slip and any(abs(slip1[i]) + abs(slip2[i]) > 0 for i in slip):
        ax.quiver([s1[i] for i in slip], [s2[i] for i in slip], [slip1[i] for i in slip],
                  [slip2[i] for i in slip], color="black", width=0.004)
    largest = max((abs(complex(slip1[i], slip2[i])) for i in slip), default=0.0)
    ax.set_title(f"micro-slip (largest {largest:.3g} {unit}) over stick and slip areas")
    ax.legend(loc="upper right", fontsize=8)


def shear_angles(shear1, shear2):
    """The direction of each shear traction, degrees from s1 towards s2."""
    return [math.degrees(math.atan2(b, a)) for a, b in zip(shear1, shear2)]


def shear_angle_panel(fig, ax, s1, s2, shear1, shear2, limit=180.0, marker_size=40):
    """The direction of the shear traction at each point, degrees from s1 (towards s2), as
    colour over +-`limit` (beyond it clipped): how the traction turns across the patch as
    lateral creepage grows."""
    dots = ax.scatter(s1, s2, c=shear_angles(shear1, shear2), cmap="coolwarm", vmin=-limit,
                      vmax=limit, s=marker_size, marker="s")
    fig.colorbar(dots, ax=ax, label="shear direction (deg from s1)")
    ax.set_title("direction of the shear traction")


def main(patch_csv, png):
    with open(patch_csv) as f:
        rows = list(csv.DictReader(f))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2), sharex=True, sharey=True)
    if not rows:
        for ax in (left, right):
            ax.text(0.5, 0.5, "no node in contact", ha="center", va="center",
                    transform=ax.transAxes)
        fig.suptitle(f"{patch_csv}: empty patch")
        fig.savefig(png, dpi=110, format="png")  # the step hands a staging name (.part)
        return
    time = float(rows[0]["time_s"])
    s1 = [1e3 * v for v in column(rows, "s1_m")]
    s2 = [1e3 * v for v in column(rows, "s2_m")]
    pressure_shear_panel(fig, left, s1, s2, [1e-6 * v for v in column(rows, "pressure_Pa")],
                         column(rows, "shear_1_Pa"), column(rows, "shear_2_Pa"))
    slipping = [r["slipping"] == "1" or float(r["slipping"]) > 0.5 for r in rows]
    slip_panel(right, s1, s2, column(rows, "slip_velocity_1_m/s"),
               column(rows, "slip_velocity_2_m/s"), slipping)
    for ax in (left, right):
        ax.set_xlabel("s1 along the longitudinal direction (mm)")
        ax.set_aspect("equal", adjustable="box")
        ax.grid(alpha=0.3)
    left.set_ylabel("s2 across (mm)")
    fig.suptitle(f"contact patch at t = {time:.6g} s ({len(rows)} nodes in contact)")
    fig.tight_layout()
    fig.savefig(png, dpi=110, format="png")  # the step hands a staging name (.part)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
