#!/usr/bin/python3
"""Benchmark: the cost of explicit penalty contact (issue 15, "Benchmark"): the contact's wall time
(exchange, search, forces; ContactPairs::seconds(), reported in summary.txt) per slave node per
step, and the whole step with the contact against the same model without it.

Model ("wheel" on "rail", two boxes; Mesh Type parts): a rail box of (n + 1) x (n + 1) x 4
one-point hex8 of 2 mm, bottom held, and on it a wheel box of n x n x 4 elements of 2 mm shifted
by half an element in x and y, so that every slave node (the wheel's bottom face, (n + 1)^2
nodes) lies over the inside of a master face (the rail's top). A pressure of 1 MPa on the
wheel's top presses it on. The slave face holds 10 % of the model's nodes and every slave node
is within the search's reach all the time: the worst case of a wheel-on-rail model, whose tread
is mostly far from the rail. Frictional contact (Coulomb 0.3), bulk-modulus penalty f = 0.1
(the default), search every 10 steps, automatic step (0.9 x the solids' limit; the contact's is
larger). Without contact: the same deck with the pair removed (the wheel box then moves off
under the pressure; the solids' cost is the same).

For each size the two runs go back to back, REPEATS times; the medians are reported (the
machine is shared, so single timings are noisy). Per run: steps, stepping wall time (the loop
only: no setup, no stable-step calibration), contact wall time. Writes
docs/data/explicit_contact_benchmark.csv (one row per size: medians, and every repeat's ratio)
and prints a Markdown table.

With --wheel SIZE ... the model is instead the default wheel of Mesh Type wheel (S1002, 920 mm)
at those Element sizes standing 2 mm above a rail-like box (5 mm elements) under 50 kN on its
bore, the whole tread the slave surface: the realistic case, where only the tread nodes near the
rail are within the search's reach (the run warns that the pair never touched: the gap does not
close in so few steps).

  /usr/bin/python3 regression/benchmarks/explicit_contact_benchmark.py [--railfe build/bin/railfe]
      [--sizes 100 173 316 | --wheel 0.02 0.012 0.008] [--steps 200 100 40] [--repeats 3]
      [--work DIR] [--csv FILE]
"""
import argparse
import csv
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "studies"))
from railfe_runs import output_xml, run_deck, steel_materials_xml, step_section  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSV = os.path.join(ROOT, "docs", "data", "explicit_contact_benchmark.csv")
H = 2e-3      # element size (m)
LAYERS = 4    # elements through each box


def box_part(name, n, origin):
    return f"""      <ParameterList name="{name}">
        <Parameter name="Type" type="string" value="box"/>
        <ParameterList name="Box">
          <Parameter name="Lengths" type="Array(double)" value="{{{n * H!r}, {n * H!r}, {LAYERS * H!r}}}"/>
          <Parameter name="Elements" type="Array(int)" value="{{{n}, {n}, {LAYERS}}}"/>
          <Parameter name="Block name" type="string" value="solid"/>
        </ParameterList>
        <Parameter name="Translation" type="Array(double)" value="{{{origin[0]!r}, {origin[1]!r}, {origin[2]!r}}}"/>
      </ParameterList>
"""


def pair_xml(slave, contact):
    """The frictional contact pair of `slave` on the rail's top (Coulomb 0.3), or nothing."""
    if not contact:
        return ""
    return f"""      <ParameterList name="Contact pairs">
        <ParameterList name="wheel on rail">
          <Parameter name="Slave side set" type="string" value="{slave}"/>
          <Parameter name="Master side set" type="string" value="rail.zmax"/>
          <Parameter name="Friction" type="string" value="coulomb"/>
          <Parameter name="Friction coefficient" type="double" value="0.3"/>
        </ParameterList>
      </ParameterList>
"""


def deck(n, steps, contact):
    """The model with n x n wheel elements per layer, about `steps` steps, with or without the
    contact pair."""
    end_time = steps * 0.85 * H / 6001.4  # the step is about 0.9 x 0.96 x h / c_P
    pair = pair_xml("wheel.zmin", contact)
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="contact benchmark {n}"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="parts"/>
    <ParameterList name="Parts">
{box_part("rail", n + 1, (0.0, 0.0, 0.0))}{box_part("wheel", n, (0.5 * H, 0.5 * H, LAYERS * H))}    </ParameterList>
  </ParameterList>
{output_xml()}{steel_materials_xml(["rail.solid", "wheel.solid"])}  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:.9g}"/>
      <ParameterList name="Prescribed motion">
        <ParameterList name="rail held">
          <Parameter name="Node set" type="string" value="rail.zmin"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Surface loads">
        <ParameterList name="press">
          <Parameter name="Side set" type="string" value="wheel.zmax"/>
          <Parameter name="Pressure" type="Array(double)" value="{{1e6}}"/>
        </ParameterList>
      </ParameterList>
{pair}      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1000000"/>
        <Parameter name="History interval" type="int" value="1000000"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def wheel_deck(size, steps, contact):
    """The default wheel (Mesh Type wheel, S1002, 920 mm; Element size `size` m) standing 2 mm
    above a rail-like box (0.3 x 0.055 x 0.04 m, y from -35 to +20 mm, clear of the flange; 5 mm
    elements, bottom held), its whole tread the
    slave surface, pushed down by 50 kN on its bore and gravity; about `steps` steps."""
    end_time = steps * 3.5e-5 * size  # the step is about 3.7e-5 s per metre of Element size
    pair = pair_xml("wheel.tread", contact)
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="contact benchmark, wheel {size}"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="parts"/>
    <ParameterList name="Parts">
      <ParameterList name="wheel">
        <Parameter name="Type" type="string" value="wheel"/>
        <ParameterList name="Wheel">
          <Parameter name="Element size" type="double" value="{size!r}"/>
        </ParameterList>
        <Parameter name="Translation" type="Array(double)" value="{{0, 0, 0.462}}"/>
      </ParameterList>
      <ParameterList name="rail">
        <Parameter name="Type" type="string" value="box"/>
        <ParameterList name="Box">
          <Parameter name="Lengths" type="Array(double)" value="{{0.3, 0.055, 0.04}}"/>
          <Parameter name="Elements" type="Array(int)" value="{{60, 11, 8}}"/>
          <Parameter name="Block name" type="string" value="solid"/>
        </ParameterList>
        <Parameter name="Translation" type="Array(double)" value="{{-0.15, -0.035, -0.04}}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
{output_xml()}{steel_materials_xml(["wheel.wheel", "rail.solid"])}  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="explicit"/>
      <Parameter name="End time" type="double" value="{end_time:.9g}"/>
      <Parameter name="Gravity" type="Array(double)" value="{{0, 0, -9.81}}"/>
      <ParameterList name="Prescribed motion">
        <ParameterList name="rail held">
          <Parameter name="Node set" type="string" value="rail.zmin"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Nodal forces">
        <ParameterList name="load">
          <Parameter name="Node set" type="string" value="wheel.bore"/>
          <Parameter name="Total force" type="Array(double)" value="{{0, 0, -5e4}}"/>
        </ParameterList>
      </ParameterList>
{pair}      <ParameterList name="Output">
        <Parameter name="Energy interval" type="int" value="1000000"/>
        <Parameter name="History interval" type="int" value="1000000"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def run(railfe, work, n, steps, contact, repeat, wheel=None):
    name = f"{f'wheel{wheel:g}' if wheel else f'n{n}'}_{'contact' if contact else 'none'}_{repeat}"
    text = wheel_deck(wheel, steps, contact) if wheel else deck(n, steps, contact)
    _, summary = run_deck(railfe, text, work, name)
    step = step_section(summary, "run")
    result = {"steps": step["steps"], "elements": step["elements"], "nodes": step["nodes"],
              "stepping_s": step["time: stepping [s]"],
              "memory_MiB": step["peak memory per rank [MiB]"]}
    if contact:
        result["contact_s"] = step["time: contact (exchange, search, forces) [s]"]
        result["slaves"] = step["slave nodes"]
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--railfe", default=os.path.join(ROOT, "build", "bin", "railfe"))
    parser.add_argument("--sizes", type=int, nargs="+", default=[100, 173, 316])
    parser.add_argument("--steps", type=int, nargs="+", default=[200, 100, 40])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--work", default="/tmp/explicit_contact_benchmark")
    parser.add_argument("--csv", default=CSV)
    parser.add_argument("--wheel", type=float, nargs="+", default=None,
                        help="instead of the boxes: the wheel on a rail box at these Element "
                             "sizes (m), --steps steps each")
    args = parser.parse_args()
    railfe = os.path.abspath(args.railfe)
    rows = []
    cases = ([(None, steps, size) for size, steps in zip(args.wheel, args.steps)] if args.wheel
             else [(n, steps, None) for n, steps in zip(args.sizes, args.steps)])
    for n, steps, wheel in cases:
        with_contact, without = [], []
        for repeat in range(args.repeats):
            with_contact.append(run(railfe, args.work, n, steps, True, repeat, wheel))
            without.append(run(railfe, args.work, n, steps, False, repeat, wheel))
            a, b = with_contact[-1], without[-1]
            print(f"{n or wheel} repeat {repeat}: with contact {a['stepping_s'] / a['steps'] * 1e3:.2f} "
                  f"ms/step (contact {a['contact_s'] / a['steps'] * 1e3:.2f}), without "
                  f"{b['stepping_s'] / b['steps'] * 1e3:.2f} ms/step", flush=True)
        per_step = [a["stepping_s"] / a["steps"] for a in with_contact]
        per_step_without = [b["stepping_s"] / b["steps"] for b in without]
        contact = [a["contact_s"] / a["steps"] for a in with_contact]
        ratios = [x / y for x, y in zip(per_step, per_step_without)]
        first = with_contact[0]
        rows.append({
            "model": f"wheel {wheel:g} m on rail box" if wheel else f"boxes, n {n}",
            "elements": first["elements"],
            "nodes": first["nodes"],
            "slave_nodes": first["slaves"],
            "slave_fraction": first["slaves"] / first["nodes"],
            "steps": first["steps"],
            "repeats": args.repeats,
            "step_with_contact_ms": 1e3 * statistics.median(per_step),
            "step_without_contact_ms": 1e3 * statistics.median(per_step_without),
            "contact_per_step_ms": 1e3 * statistics.median(contact),
            "contact_ns_per_slave_node_step": 1e9 * statistics.median(contact) / first["slaves"],
            "step_ratio_with_over_without": statistics.median(ratios),
            "contact_share_of_step": statistics.median(
                [c / s for c, s in zip(contact, per_step)]),
            "ratios_of_each_repeat": " ".join(f"{r:.3f}" for r in ratios),
            "peak_memory_with_contact_MiB": first["memory_MiB"],
            "peak_memory_without_contact_MiB": without[0]["memory_MiB"],
        })
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("| model | slave nodes | nodes | elements | step with contact (ms) | without (ms) | ratio | "
          "contact (ms/step) | contact (ns per slave node-step) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['model']} | {r['slave_nodes']:.0f} | {r['nodes']:.0f} | {r['elements']:.0f} | "
              f"{r['step_with_contact_ms']:.2f} | {r['step_without_contact_ms']:.2f} | "
              f"{r['step_ratio_with_over_without']:.3f} | {r['contact_per_step_ms']:.2f} | "
              f"{r['contact_ns_per_slave_node_step']:.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
