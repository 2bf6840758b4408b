# Draws the default wheel mesh (Mesh/Type wheel) for docs/img/wheel_mesh.png: the cross-section
# at θ = 0 with the S1002 profile over it, the tread enlarged, and the revolved wheel with a
# quarter cut away. Runs railfe on a throw-away deck (a clamped bore under gravity) to get the
# mesh as Exodus, and reads it with VTK:
#   /usr/bin/python3 regression/charts/wheel_mesh_picture.py build/bin/railfe docs/img/wheel_mesh.png
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
from vtk import vtkExodusIIReader
from vtk.util.numpy_support import vtk_to_numpy

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ELEMENT_SIZE = 0.014
DECK = """<ParameterList name="railfe">
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="wheel"/>
    <ParameterList name="Wheel">
      <Parameter name="Element size" type="double" value="%g"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="steel">
      <Parameter name="Young's modulus" type="double" value="210e9"/>
      <Parameter name="Poisson's ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="7850"/>
      <Parameter name="Blocks" type="Array(string)" value="{wheel}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Steps">
    <ParameterList name="mesh">
      <Parameter name="Module" type="string" value="statics"/>
      <Parameter name="Gravity" type="Array(double)" value="{0, 0, -9.81}"/>
      <ParameterList name="Displacements">
        <ParameterList name="seat"><Parameter name="Node set" type="string" value="bore"/></ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
""" % ELEMENT_SIZE


def read_hexes(path):
    reader = vtkExodusIIReader()
    reader.SetFileName(path)
    reader.SetApplyDisplacements(False)  # the mesh as generated, not deformed
    reader.Update()
    block = reader.GetOutput().GetBlock(0).GetBlock(0)
    points = vtk_to_numpy(block.GetPoints().GetData())
    cells = vtk_to_numpy(block.GetCells().GetConnectivityArray()).reshape(-1, 8)
    return points, cells


def s1002():
    text = open(os.path.join(ROOT, "inputs/profiles/MBench_S1002_v3.prw")).read()
    block = text.split("point.begin")[1].split("point.end")[0]
    rows = [line.split()[:2] for line in block.splitlines()
            if line.strip() and line.strip()[0] not in "!%"]
    points = np.array(rows, dtype=float)[::-1] / 1000  # (y, z) in m, y increasing
    z0 = np.interp(0, points[:, 0], points[:, 1])
    return points[:, 0], 0.46 + points[:, 1] - z0


def main(railfe, output):
    with tempfile.TemporaryDirectory() as work:
        deck = os.path.join(work, "wheel.xml")
        open(deck, "w").write(DECK)
        subprocess.run([railfe, deck, "--quiet", "--output", work], check=True)
        points, hexes = read_hexes(os.path.join(work, "mesh.exo"))
    figure = plt.figure(figsize=(15, 6))
    # The section: nodes 0-3 of the hexes of slice 0 lie in the plane z = 0, x > 0.
    first = hexes[:, :4]
    in_plane = np.all((np.abs(points[first, 2]) < 1e-9) & (points[first, 0] > 0), axis=1)
    quads = [points[q][:, [1, 0]] * 1000 for q in first[in_plane]]
    n_around = len(hexes) // len(quads)
    a, r = s1002()
    for index, (title, limits) in enumerate(
            [("Cross-section (%d quadrilaterals)" % len(quads), None),
             ("Tread: S1002 profile (red) and mesh", ((-75, 80), (440, 495)))]):
        axes = figure.add_subplot(1, 3, index + 1)
        axes.add_collection(PolyCollection(quads, facecolor="#dde6f0", edgecolor="#3a5a80",
                                           linewidth=0.6))
        axes.plot(a * 1000, r * 1000, color="#c0392b", linewidth=1.0)
        axes.plot([0], [460], "o", color="#c0392b", markersize=4)
        axes.set_aspect("equal")
        axes.set_xlabel("a = y (mm), flange side +")
        axes.set_ylabel("r (mm)")
        axes.set_title(title, fontsize=10)
        if limits:
            axes.set_xlim(*limits[0])
            axes.set_ylim(*limits[1])
        else:
            axes.autoscale_view()

    # The revolved wheel as a wireframe of its surface (the section's boundary at every slice and
    # each boundary node's circle) over three quarters, the section filled where it is cut (at
    # θ = 90° and 360°, x = r cos θ, z = r sin θ).
    axes = figure.add_subplot(1, 3, 3, projection="3d")
    section = [q[:, ::-1] / 1000 for q in quads]  # (r, a) in m
    edges = {}
    for quad in section:
        for k in range(4):
            key = tuple(sorted((tuple(quad[k]), tuple(quad[(k + 1) % 4]))))
            edges[key] = edges.get(key, 0) + 1
    boundary = [np.array(edge) for edge, uses in edges.items() if uses == 1]
    place = lambda ra, t: np.column_stack([ra[..., 0] * np.cos(t), ra[..., 1],
                                           ra[..., 0] * np.sin(t)])
    angles = 2 * np.pi * np.arange(n_around + 1) / n_around
    angles = angles[angles >= np.pi / 2 - 1e-9]  # the quarter facing the viewer cut away
    lines = [place(edge, t) for t in angles for edge in boundary]
    nodes = np.unique(np.concatenate(boundary), axis=0)
    lines += [place(np.repeat(node[None, :], len(angles), axis=0), angles) for node in nodes]
    axes.add_collection3d(Line3DCollection(lines, colors="#3a5a80", linewidths=0.15))
    for t in (angles[0], angles[-1]):
        axes.add_collection3d(Poly3DCollection([place(q, t) for q in section],
                                               facecolor="#f2c9a0", edgecolor="#8a5a2b",
                                               linewidth=0.3))
    axes.set_xlim(-0.5, 0.5)
    axes.set_ylim(-0.5, 0.5)
    axes.set_zlim(-0.5, 0.5)
    axes.set_box_aspect((1, 1, 1))
    axes.view_init(elev=25, azim=-35)
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_zlabel("z (m)")
    axes.set_title("Revolved: %d elements around, %d hex8" % (n_around, len(hexes)), fontsize=10)
    figure.suptitle("Mesh/Type wheel, defaults (920 mm, S1002), Element size %g mm"
                    % (ELEMENT_SIZE * 1000))
    figure.tight_layout()
    figure.savefig(output, dpi=110)
    print("wrote", output)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
