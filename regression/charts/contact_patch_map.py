#!/usr/bin/env python3
"""Map of one contact patch written by an explicit step with contact pairs: on the left the
pressure as colour with the shear traction as arrows, on the right the micro-slip velocity as
arrows over the stick (blue) and slip (red) nodes, both in the contact plane (s1 along the pair's
Longitudinal direction, s2 across).

    /usr/bin/python3 regression/charts/contact_patch_map.py <step>_contact_<pair>_patch_<k>.csv out.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def column(rows, name):
    return [float(r[name]) for r in rows]


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
    pressure = [1e-6 * v for v in column(rows, "pressure_Pa")]
    shear1 = column(rows, "shear_1_Pa")
    shear2 = column(rows, "shear_2_Pa")
    slip1 = column(rows, "slip_velocity_1_m/s")
    slip2 = column(rows, "slip_velocity_2_m/s")
    slipping = [r["slipping"] == "1" or float(r["slipping"]) > 0.5 for r in rows]

    dots = left.scatter(s1, s2, c=pressure, cmap="viridis", s=40, marker="s")
    fig.colorbar(dots, ax=left, label="pressure (MPa)")
    if any(shear1) or any(shear2):
        left.quiver(s1, s2, shear1, shear2, color="white", edgecolor="black", linewidth=0.4,
                    width=0.004)
    left.set_title(f"pressure and shear traction (largest {max(pressure):.4g} MPa)")

    stick = [i for i, s in enumerate(slipping) if not s]
    slip = [i for i, s in enumerate(slipping) if s]
    for group, colour, label in ((stick, "tab:blue", "not slipping"), (slip, "tab:red", "slip")):
        if group:
            right.scatter([s1[i] for i in group], [s2[i] for i in group], c=colour, s=30,
                          marker="s", alpha=0.5, label=f"{label} ({len(group)} nodes)")
    if slip and any(abs(slip1[i]) + abs(slip2[i]) > 0 for i in slip):
        right.quiver([s1[i] for i in slip], [s2[i] for i in slip], [slip1[i] for i in slip],
                     [slip2[i] for i in slip], color="black", width=0.004)
    largest = max((abs(complex(slip1[i], slip2[i])) for i in slip), default=0.0)
    right.set_title(f"micro-slip (largest {largest:.3g} m/s) over stick and slip areas")
    right.legend(loc="upper right", fontsize=8)
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
