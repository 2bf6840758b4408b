#!/usr/bin/python3
"""Chart of the explicit squeal scene's strong scaling on the device machine (16 cores), from
docs/data/squeal_device_scaling.csv, which regression/benchmarks/device/device_run.sh's
timings.csv gave (see docs/benchmarks.md, "Squeal scene at 16 ranks"). Writes
docs/img/squeal_device_scaling.png. Run: /usr/bin/python3 regression/benchmarks/squeal_device_scaling.py
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    rows = list(csv.DictReader(open(os.path.join(ROOT, "docs", "data", "squeal_device_scaling.csv"))))
    mid = {}
    for r in rows:  # the longest run at each rank count of the 4 mm mesh
        if r["mesh"] == "mid 4 mm":
            n = int(r["ranks"])
            if n not in mid or int(r["steps"]) > int(mid[n]["steps"]):
                mid[n] = r
    ranks = sorted(mid)
    base = float(mid[1]["ms_per_step"])
    speedup = [base / float(mid[n]["ms_per_step"]) for n in ranks]
    contact = [float(mid[n]["contact_share"]) * 100 for n in ranks]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(ranks, ranks, "k--", label="ideal")
    left.plot(ranks, speedup, "o-", label="4 mm mesh, 106,940 hex8")
    left.set_xscale("log", base=2)
    left.set_yscale("log", base=2)
    left.set_xticks(ranks, [str(n) for n in ranks])
    left.set_yticks([1, 2, 4, 8, 16], ["1", "2", "4", "8", "16"])
    left.set_xlabel("MPI ranks")
    left.set_ylabel("speed-up of the time step")
    left.set_title("Strong scaling, explicit rolling (case 1)")
    left.legend()
    left.grid(True, which="both", alpha=0.3)
    right.bar([str(n) for n in ranks], contact)
    right.set_xlabel("MPI ranks")
    right.set_ylabel("contact share of the stepping time [%]")
    right.set_title("Contact (exchange, search, forces)")
    right.grid(True, axis="y", alpha=0.3)
    fig.suptitle("Device machine: 16-core Intel Xeon (KVM, gVisor), Open MPI 4.1 shared memory")
    fig.tight_layout()
    out = os.path.join(ROOT, "docs", "img", "squeal_device_scaling.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
