#!/usr/bin/env python3
"""The static wheel load the squeal scene's preload must carry, computed from its mesh alone: the
sprung weight on the axle end plus the weight of the wheel and half axle (their hex8 volumes
times the density) plus the vertical resultant of their centrifugal load (the lumped nodal
masses times omega^2 r; not zero, because the refined arc's slices are chords of a different
length than the coarse ones, so the discrete wheel's mass centre is not on the axis).

    /usr/bin/python3 regression/scenes/squeal_wheel_load.py RESULTS/preload.exo \\
        [--sprung-weight 106301.16] [--omega 60.3366301] [--axis-z 0.459916265]

Reads the Exodus file (netCDF-3, scipy) and prints the masses, the centrifugal resultant and
the expected vertical contact force (N).
"""
import argparse

import numpy as np
from scipy.io import netcdf_file

GAUSS = np.array([-1, 1]) / np.sqrt(3)
CORNERS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)


def lumped_masses(x, density):
    """Row sums of the consistent hex8 mass, 2x2x2 Gauss: (elements, 8) nodal masses."""
    masses = np.zeros((x.shape[0], 8))
    for xi in GAUSS:
        for eta in GAUSS:
            for zeta in GAUSS:
                p = np.array([xi, eta, zeta])
                n = np.prod(1 + CORNERS * p, axis=1) / 8
                dn = np.empty((8, 3))
                for d in range(3):
                    q = 1 + CORNERS * p
                    q[:, d] = CORNERS[:, d]
                    dn[:, d] = np.prod(q, axis=1) / 8
                jac = np.einsum("eai,aj->eij", x, dn)
                masses += density * np.abs(np.linalg.det(jac))[:, None] * n[None, :]
    return masses


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("exodus")
    parser.add_argument("--sprung-weight", type=float, default=10836.0 * 9.81)
    parser.add_argument("--omega", type=float, default=60.3366301)
    parser.add_argument("--axis-z", type=float, default=0.459916265)
    parser.add_argument("--density", type=float, default=7850.0)
    parser.add_argument("--gravity", type=float, default=9.81)
    args = parser.parse_args()
    exo = netcdf_file(args.exodus, "r", mmap=False)
    coords = np.stack([exo.variables[f"coord{c}"][:].copy() for c in "xyz"], axis=1)
    names = ["".join(c.decode() for c in row if c) for row in exo.variables["eb_names"][:]]
    total_mass, resultant_z = 0.0, 0.0
    for k, name in enumerate(names):
        if not name.startswith("wheel."):
            continue
        connect = exo.variables[f"connect{k + 1}"][:].astype(int) - 1
        masses = lumped_masses(coords[connect], args.density)
        total_mass += masses.sum()
        z = coords[connect][:, :, 2] - args.axis_z
        resultant_z += args.omega**2 * np.sum(masses * z)
        print(f"{name}: {masses.sum():.4f} kg")
    weight = total_mass * args.gravity
    load = args.sprung_weight + weight - resultant_z
    print(f"wheel and half axle: {total_mass:.4f} kg, weight {weight:.2f} N")
    print(f"centrifugal resultant along z: {resultant_z:.2f} N")
    print(f"expected vertical contact force on the rail: {load:.2f} N")


if __name__ == "__main__":
    main()
