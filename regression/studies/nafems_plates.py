#!/usr/bin/env python3
"""Speed against accuracy of both hex8 formulations on two NAFEMS linear-elastic benchmarks (The
Standard NAFEMS Benchmarks, TNSB Rev. 3, 1990), with the benchmark's targets:

  LE1   elliptic membrane, plane stress, 0.1 m thick, outward pressure 10 MPa on the outer
        ellipse: sigma_yy at D = (2, 0) is 92.7 MPa.
  LE10  thick elliptic plate, 0.6 m thick, 1 MPa on the upper face; outer face held in x and y,
        its mid-plane edge in z: sigma_yy at D = (2, 0, 0.3) is -5.38 MPa.

Geometry, loads, supports and targets as NAFEMS states them (the quarter between the ellipses
(x/2)^2 + y^2 = 1 and (x/3.25)^2 + (y/2.75)^2 = 1; E 210 GPa, nu 0.3). Meshes from
inputs/meshes/make_nafems_plates.py (elliptic coordinates, N_THETA x N_RADIAL in plan); the
coarsest level of each series has the element counts of NAFEMS's coarse mesh (3 x 2 in plan)
and the next those of its fine mesh (6 x 4), each refinement halves every element. The stress at
D is the statics probe's nodal stress (Gauss-point stresses extrapolated to the node, averaged
over the elements around it). Each run is timed best of --repeat (interleaved).

    nice /usr/bin/python3 regression/studies/nafems_plates.py [build/bin/railfe] [--levels 7 5]

Writes docs/data/nafems_plates.csv and docs/img/nafems_plates.png.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "inputs", "meshes"))
from make_nafems_plates import build, write_msh  # noqa: E402
from railfe_runs import csv_rows, run_deck, step_section, study_parser, typed_rows  # noqa: E402

FULL, ENHANCED = "full integration", "enhanced strain"
TARGET = {"le1": 92.7e6, "le10": -5.38e6}
TITLE = {"le1": "LE1 elliptic membrane", "le10": "LE10 thick plate"}


def layers_of(case, level):
    """Elements through the thickness: one for the membrane; for the thick plate as many as the
    radial direction has (2 at NAFEMS's coarse plan), so the elements keep their shape."""
    return 1 if case == "le1" else 2 * 2 ** level


def nafems_deck(case, mesh, element):
    """The statics deck of `case` on the mesh file `mesh` with the material's `element`."""
    if case == "le1":
        supports = (("symmetry x", "x0", "x"), ("symmetry y", "y0", "y"),
                    ("mid-plane", "bottom", "z"))
        load = ("outer", -10e6)  # tension: pressure against the outward normal, negative
    else:
        supports = (("symmetry x", "x0", "x"), ("symmetry y", "y0", "y"),
                    ("outer face", "outer", "xy"), ("outer mid-plane edge", "outer_mid", "z"))
        load = ("top", 1e6)
    support_xml = "".join(
        f'        <ParameterList name="{name}">\n'
        f'          <Parameter name="Node set" type="string" value="{nodes}"/>\n'
        f'          <Parameter name="Components" type="string" value="{components}"/>\n'
        f'        </ParameterList>\n' for name, nodes, components in supports)
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="NAFEMS {case.upper()}, {element}"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="gmsh"/>
    <Parameter name="File" type="string" value="{mesh}"/>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="steel">
      <Parameter name="Young's modulus" type="double" value="210e9"/>
      <Parameter name="Poisson's ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="7800"/>
      <Parameter name="Blocks" type="Array(string)" value="{{plate}}"/>
      <Parameter name="Element" type="string" value="{element}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Exodus" type="bool" value="false"/>
  </ParameterList>
  <ParameterList name="Steps">
    <ParameterList name="load">
      <Parameter name="Module" type="string" value="statics"/>
      <ParameterList name="Displacements">
{support_xml}      </ParameterList>
      <ParameterList name="Surface loads">
        <ParameterList name="pressure">
          <Parameter name="Side set" type="string" value="{load[0]}"/>
          <Parameter name="Pressure" type="Array(double)" value="{{{load[1]:g}}}"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Probes">
        <ParameterList name="D"><Parameter name="Node set" type="string" value="D"/></ParameterList>
      </ParameterList>
      <ParameterList name="Linear solver">
        <Parameter name="Method" type="string" value="cholmod"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def run(railfe, case, level, element, work):
    n_theta, n_radial, layers = 3 * 2 ** level, 2 * 2 ** level, layers_of(case, level)
    os.makedirs(work, exist_ok=True)
    mesh = os.path.join(work, f"{case}_{n_theta}x{n_radial}x{layers}.msh")
    if not os.path.exists(mesh):
        write_msh(mesh, *build(case, n_theta, n_radial, layers))
    name = f"{case}_{level}_{element.replace(' ', '_')}"
    results, summary = run_deck(railfe, nafems_deck(case, mesh, element), work, name)
    probe = csv_rows(os.path.join(results, "load_probes.csv"))[0]
    return {"case": case, "element": element, "mesh": f"{n_theta}x{n_radial}x{layers}",
            "dofs": int(step_section(summary, "load")["degrees of freedom"]),
            "wall": summary["Wall time"]["total [s]"], "syy": float(probe["syy_Pa"])}


def chart(rows, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, key, label in ((axes[0], "dofs", "degrees of freedom"),
                           (axes[1], "wall_s", "railfe wall time (summary total), 1 core (s)")):
        for case, marker in (("le1", "o"), ("le10", "s")):
            for element, color in ((FULL, "tab:blue"), (ENHANCED, "tab:red")):
                series = [r for r in rows if r["case"] == case and r["element"] == element]
                ax.plot([r[key] for r in series], [r["error_percent"] for r in series],
                        marker + ("-" if case == "le1" else "--"), color=color,
                        label=f"{TITLE[case]}, {element}")
                for r, name in zip(series, ("NAFEMS coarse plan", "NAFEMS fine plan")):
                    if element == ENHANCED:
                        ax.annotate(f"{name}", (r[key], r["error_percent"]), fontsize=6,
                                    textcoords="offset points", xytext=(5, -3), color="grey")
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=1.0)
        ticks = [-30, -10, -3, -1, 0, 1, 3, 10]
        ax.set_yticks(ticks, [f"{t:+d} %" if t else "0" for t in ticks])
        ax.set_ylim(-45, 12)
        for level in (-1, 1):
            ax.axhline(level, color="grey", lw=0.6, ls=":")
        ax.axhline(0, color="black", lw=0.6)
        ax.set_xlabel(label)
        ax.set_ylabel("error of sigma_yy at D against NAFEMS (%)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="lower right")
    fig.suptitle("NAFEMS LE1 (92.7 MPa) and LE10 (-5.38 MPa), hex8: full integration against "
                 "enhanced strain (symlog: linear within 1 %)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = study_parser(__doc__.split("\n")[0], "/tmp/railfe_nafems_plates", ROOT)
    parser.add_argument("--levels", type=int, nargs=2, default=[7, 5], metavar=("LE1", "LE10"),
                        help="refinement levels of each case (from 3 x 2 in plan)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per configuration (best)")
    args = parser.parse_args()
    data = os.path.join(ROOT, "docs", "data", "nafems_plates.csv")
    image = os.path.join(ROOT, "docs", "img", "nafems_plates.png")
    if args.replot:
        rows = typed_rows(data, {"case", "element", "mesh"})
        chart(rows, image)
        return
    railfe = os.path.abspath(args.railfe)
    rows = []
    for case, levels in zip(("le1", "le10"), args.levels):
        for level in range(levels):
            best = {}
            for _ in range(args.repeat):  # interleaved: both elements see the same machine load
                for element in (FULL, ENHANCED):
                    r = run(railfe, case, level, element, args.work)
                    if element not in best or r["wall"] < best[element]["wall"]:
                        best[element] = r
            for element in (FULL, ENHANCED):
                r = best[element]
                r["error_percent"] = 100 * (r["syy"] / TARGET[case] - 1)
                rows.append(r)
                print(f"{case:4s} {r['mesh']:>9s} {element:17s} {r['dofs']:7d} DOFs "
                      f"{r['wall']:6.2f} s  syy(D) {r['syy'] / 1e6:8.3f} MPa "
                      f"({r['error_percent']:+.2f} %)", flush=True)
    with open(data, "w") as out:
        out.write("case,element,mesh,dofs,wall_s,syy_D_MPa,error_percent\n")
        for r in rows:
            out.write(f"{r['case']},{r['element']},{r['mesh']},{r['dofs']},{r['wall']:.3f},"
                      f"{r['syy'] / 1e6:.4f},{r['error_percent']:.3f}\n")
    for r in rows:
        r["wall_s"] = r["wall"]
    chart(rows, image)


if __name__ == "__main__":
    main()
