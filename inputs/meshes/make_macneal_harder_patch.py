#!/usr/bin/env python3
"""Writes macneal_harder_patch.msh: the 7-element hexahedral patch of MacNeal & Harder,
"A proposed standard set of problems to test finite element accuracy" (Finite Elements in
Analysis and Design 1, 1985): a unit cube whose inner hexahedron has the distorted corners below,
joined to the cube's faces by six more hexahedra.

Gmsh .msh 4.1 ASCII. Node sets: 'outer' (the 8 cube corners) and 'inner' (the 8 interior
nodes); element block 'patch'. Run: python3 make_macneal_harder_patch.py
"""
CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
INNER = [(0.249, 0.342, 0.192), (0.826, 0.288, 0.288), (0.850, 0.649, 0.263),
         (0.273, 0.750, 0.230), (0.320, 0.186, 0.643), (0.677, 0.305, 0.683),
         (0.788, 0.693, 0.644), (0.165, 0.745, 0.702)]
# Exodus/Gmsh hexahedron faces, counter-clockwise seen from outside.
FACES = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1), (4, 5, 6, 7)]


def main():
    outer = list(range(1, 9))    # node tags of the cube corners
    inner = list(range(9, 17))   # node tags of the interior nodes
    hexes = [inner]
    for face in FACES:
        # bottom on the inner face, top on the matching cube face: positive Jacobian
        hexes.append([inner[k] for k in face] + [outer[k] for k in face])
    points = CORNERS + INNER
    lines = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat",
             "$PhysicalNames", "3", '0 1 "outer"', '0 2 "inner"', '3 3 "patch"',
             "$EndPhysicalNames", "$Entities", "16 0 0 1"]
    for tag, (x, y, z) in enumerate(points, start=1):
        lines.append(f"{tag} {x} {y} {z} 1 {1 if tag <= 8 else 2}")
    lines += ["1 0 0 0 1 1 1 1 3 0", "$EndEntities", "$Nodes", "16 16 1 16"]
    for tag, (x, y, z) in enumerate(points, start=1):
        lines += [f"0 {tag} 0 1", str(tag), f"{x} {y} {z}"]
    lines += ["$EndNodes", "$Elements", f"17 {16 + len(hexes)} 1 {16 + len(hexes)}"]
    for tag in range(1, 17):
        lines += [f"0 {tag} 15 1", f"{tag} {tag}"]
    lines.append(f"3 1 5 {len(hexes)}")
    for number, nodes in enumerate(hexes, start=17):
        lines.append(" ".join(str(n) for n in [number] + nodes))
    lines.append("$EndElements")
    with open("macneal_harder_patch.msh", "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
