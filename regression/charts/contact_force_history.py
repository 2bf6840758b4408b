#!/usr/bin/env python3
"""Contact force histories of one pair of an explicit step (the squeal scene's Fig. 4): the normal
force, the longitudinal and lateral tangential forces, the creep force (their resultant) and the
traction bound mu N, against time, from the pair's <step>_contact_<pair>.csv.

    /usr/bin/python3 regression/charts/contact_force_history.py <step>_contact_<pair>.csv out.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(history_csv, png):
    with open(history_csv) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{history_csv}: no rows")
    t = [1e3 * float(r["time_s"]) for r in rows]
    kn = lambda name: [1e-3 * float(r[name]) for r in rows]  # noqa: E731
    normal, longitudinal, lateral = kn("normal_force_N"), kn("tangential_1_N"), kn("tangential_2_N")
    creep = [math.hypot(a, b) for a, b in zip(longitudinal, lateral)]
    bound = kn("friction_bound_N")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [1, 1.4]})
    top.plot(t, normal, color="black", label="normal force N")
    top.set_ylabel("force (kN)")
    top.legend(loc="best")
    top.grid(alpha=0.3)
    bottom.plot(t, longitudinal, label="longitudinal (tangential 1)")
    bottom.plot(t, lateral, label="lateral (tangential 2)")
    bottom.plot(t, creep, color="black", label="creep force (resultant)")
    bottom.plot(t, bound, color="red", linestyle="--", label="traction bound mu N")
    bottom.set_xlabel("time (ms)")
    bottom.set_ylabel("force (kN)")
    bottom.legend(loc="best", fontsize=8)
    bottom.grid(alpha=0.3)
    fig.suptitle(f"contact forces: {history_csv.split('/')[-1]}")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
