#!/usr/bin/env python3
"""Writes hexahedral meshes of the NAFEMS elliptic plates (The Standard NAFEMS Benchmarks, TNSB
Rev. 3, 1990): LE1, the elliptic membrane, and LE10, the thick plate under pressure.

Both are a quarter of the region between the ellipses (x/2)^2 + y^2 = 1 and
(x/3.25)^2 + (y/2.75)^2 = 1 (m). The two ellipses are confocal (focal distance sqrt(3)), so the
mesh follows elliptic coordinates: x = sqrt(3) cosh(mu) cos(nu), y = sqrt(3) sinh(mu) sin(nu),
with N_THETA equal steps of nu from the x axis (nu = 0) to the y axis and N_RADIAL equal steps of
mu from the inner to the outer ellipse. Point D = (2, 0) is a corner node of the mesh.

  le1:  thickness 0.1 (z = 0 .. 0.1), LAYERS elements through it (one is enough: plane stress).
  le10: thickness 0.6 (z = -0.3 .. 0.3), LAYERS elements through it (even: the mid-plane is a
        node layer).

Gmsh .msh 4.1 ASCII. Block 'plate'. Side and node sets: 'outer' (the outer elliptic face),
'x0' (the face on the y axis, x = 0), 'y0' (the face on the x axis, y = 0), 'bottom' and 'top'
(the faces z = min and z = max). Node sets: 'D' (the nodes at x = 2, y = 0: the line through
the thickness for le1, the top node for le10) and, for le10, 'outer_mid' (the outer face's
nodes at z = 0).

Run: python3 make_nafems_plates.py le1 N_THETA N_RADIAL LAYERS OUT.msh
     (the shipped meshes: le1 6 4 1 nafems_le1.msh; le10 ... see inputs/verification/nafems_*)
"""
import math
import sys

FOCUS = math.sqrt(3.0)
MU_INNER = math.acosh(2.0 / FOCUS)
MU_OUTER = math.acosh(3.25 / FOCUS)
THICKNESS = {"le1": (0.0, 0.1), "le10": (-0.3, 0.3)}


def build(case, n_theta, n_radial, layers):
    """Returns (points, hexes, sets): points [(x, y, z)], hexes [8 node indices, 0-based], sets
    {name: (dim, [elements as node-index lists])} for quads (dim 2), lines (1) and points (0)."""
    if case == "le10" and layers % 2:
        raise ValueError("le10 needs an even number of layers (the mid-plane is a node layer)")
    z0, z1 = THICKNESS[case]

    def index(i, j, k):  # i radial, j around (nu), k through the thickness
        return (k * (n_theta + 1) + j) * (n_radial + 1) + i

    points = []
    for k in range(layers + 1):
        z = z0 + (z1 - z0) * k / layers
        for j in range(n_theta + 1):
            nu = 0.5 * math.pi * j / n_theta
            for i in range(n_radial + 1):
                mu = MU_INNER + (MU_OUTER - MU_INNER) * i / n_radial
                x = 0.0 if j == n_theta else FOCUS * math.cosh(mu) * math.cos(nu)
                y = 0.0 if j == 0 else FOCUS * math.sinh(mu) * math.sin(nu)
                points.append((x, y, z))
    hexes = []
    for k in range(layers):
        for j in range(n_theta):
            for i in range(n_radial):
                base = [index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k),
                        index(i, j + 1, k)]
                hexes.append(base + [n + (n_theta + 1) * (n_radial + 1) for n in base])
    sets = {
        "outer": (2, [[index(n_radial, j, k), index(n_radial, j + 1, k),
                       index(n_radial, j + 1, k + 1), index(n_radial, j, k + 1)]
                      for j in range(n_theta) for k in range(layers)]),
        "x0": (2, [[index(i, n_theta, k), index(i + 1, n_theta, k),
                    index(i + 1, n_theta, k + 1), index(i, n_theta, k + 1)]
                   for i in range(n_radial) for k in range(layers)]),
        "y0": (2, [[index(i, 0, k), index(i + 1, 0, k), index(i + 1, 0, k + 1),
                    index(i, 0, k + 1)] for i in range(n_radial) for k in range(layers)]),
        "bottom": (2, [[index(i, j, 0), index(i + 1, j, 0), index(i + 1, j + 1, 0),
                        index(i, j + 1, 0)] for i in range(n_radial) for j in range(n_theta)]),
        "top": (2, [[index(i, j, layers), index(i + 1, j, layers), index(i + 1, j + 1, layers),
                     index(i, j + 1, layers)] for i in range(n_radial) for j in range(n_theta)]),
    }
    if case == "le1":
        sets["D"] = (1, [[index(0, 0, k), index(0, 0, k + 1)] for k in range(layers)])
    else:
        sets["D"] = (0, [[index(0, 0, layers)]])
        sets["outer_mid"] = (1, [[index(n_radial, j, layers // 2),
                                  index(n_radial, j + 1, layers // 2)] for j in range(n_theta)])
    return points, hexes, sets


def write_msh(path, points, hexes, sets):
    names = list(sets)
    lines = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$PhysicalNames",
             str(len(names) + 1)]
    for tag, name in enumerate(names, start=1):
        lines.append(f'{sets[name][0]} {tag} "{name}"')
    lines += [f'3 {len(names) + 1} "plate"', "$EndPhysicalNames"]
    # One entity per set (its own tag = its physical tag), and the volume.
    counts = [sum(1 for n in names if sets[n][0] == d) for d in range(3)]
    lines += ["$Entities", f"{counts[0]} {counts[1]} {counts[2]} 1"]
    for dim in range(3):
        for tag, name in enumerate(names, start=1):
            if sets[name][0] != dim:
                continue
            box = "0 0 0" if dim == 0 else "0 0 0 0 0 0"
            lines.append(f"{tag} {box} 1 {tag}" + ("" if dim == 0 else " 0"))
    lines += [f"1 0 0 0 0 0 0 1 {len(names) + 1} 0", "$EndEntities"]
    lines += ["$Nodes", f"1 {len(points)} 1 {len(points)}", f"3 1 0 {len(points)}"]
    lines += [str(n) for n in range(1, len(points) + 1)]
    lines += [f"{x:.15g} {y:.15g} {z:.15g}" for x, y, z in points]
    lines.append("$EndNodes")
    n_elements = len(hexes) + sum(len(sets[n][1]) for n in names)
    lines += ["$Elements", f"{len(names) + 1} {n_elements} 1 {n_elements}"]
    gmsh_type = {0: 15, 1: 1, 2: 3}
    number = 1
    for tag, name in enumerate(names, start=1):
        dim, elements = sets[name]
        lines.append(f"{dim} {tag} {gmsh_type[dim]} {len(elements)}")
        for element in elements:
            lines.append(" ".join(str(v) for v in [number] + [n + 1 for n in element]))
            number += 1
    lines.append(f"3 1 5 {len(hexes)}")
    for element in hexes:
        lines.append(" ".join(str(v) for v in [number] + [n + 1 for n in element]))
        number += 1
    lines.append("$EndElements")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 6 or sys.argv[1] not in THICKNESS:
        sys.exit(__doc__)
    case, n_theta, n_radial, layers, path = (sys.argv[1], int(sys.argv[2]), int(sys.argv[3]),
                                             int(sys.argv[4]), sys.argv[5])
    write_msh(path, *build(case, n_theta, n_radial, layers))


if __name__ == "__main__":
    main()
