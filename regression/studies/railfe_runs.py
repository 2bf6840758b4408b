"""Helpers shared by the study and benchmark scripts: run railfe on a generated deck and read what
it wrote (summary.json, CSV files). Uses only the Python standard library."""
import argparse
import csv
import json
import os
import subprocess


def steel_materials_xml(blocks, young=210e9, density=7850):
    """The Materials section: one steel (nu 0.3; E 210 GPa, rho 7850 kg/m^3 unless given) on the
    named blocks."""
    return f"""  <ParameterList name="Materials">
    <ParameterList name="steel">
      <Parameter name="Young's modulus" type="double" value="{young:g}"/>
      <Parameter name="Poisson's ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="{density:g}"/>
      <Parameter name="Blocks" type="Array(string)" value="{{{', '.join(blocks)}}}"/>
    </ParameterList>
  </ParameterList>
"""


def xml_array(values):
    """A Teuchos array value: {a, b, c}."""
    return "{" + ", ".join(str(v) for v in values) + "}"


def box_mesh_xml(lengths, elements, block=None, origin=None):
    """The Mesh section of a generated box: `lengths` (m) and `elements` per axis, optional block
    name and origin (m)."""
    extra = ""
    if origin is not None:
        extra += f'\n      <Parameter name="Origin" type="Array(double)" value="{xml_array(origin)}"/>'
    if block is not None:
        extra += f'\n      <Parameter name="Block name" type="string" value="{block}"/>'
    return f"""  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="box"/>
    <ParameterList name="Box">
      <Parameter name="Lengths" type="Array(double)" value="{xml_array(lengths)}"/>
      <Parameter name="Elements" type="Array(int)" value="{xml_array(elements)}"/>{extra}
    </ParameterList>
  </ParameterList>
"""


def output_xml(exodus=False):
    """The top-level Output section: Exodus on or off."""
    return f"""  <ParameterList name="Output">
    <Parameter name="Exodus" type="bool" value="{'true' if exodus else 'false'}"/>
  </ParameterList>
"""


def box_statics_deck(lengths, elements, clamp, load_set, load, solver=None, gravity=None,
                     probe=None, exodus=False):
    """A statics deck for a steel box (E 210 GPa, nu 0.3): `clamp` fully fixed, `load` = (kind,
    values) on side set `load_set` with kind 'Total force' or 'Pressure', optional Linear solver
    parameters {name: value}, gravity vector, a probe on node set `probe`."""
    solver_xml = "".join(
        f'<Parameter name="{name}" type="{"int" if isinstance(value, int) else "string"}" '
        f'value="{value}"/>' for name, value in (solver or {}).items())
    gravity_xml = (f'<Parameter name="Gravity" type="Array(double)" value="{xml_array(gravity)}"/>'
                   if gravity else "")
    probe_xml = (f'<ParameterList name="Probes"><ParameterList name="{probe}">'
                 f'<Parameter name="Node set" type="string" value="{probe}"/>'
                 f'</ParameterList></ParameterList>' if probe else "")
    kind, values = load
    return f"""<ParameterList name="railfe">
{box_mesh_xml(lengths, elements)}{steel_materials_xml(["block_1"])}{output_xml(exodus)}  <ParameterList name="Steps">
    <ParameterList name="load">
      <Parameter name="Module" type="string" value="statics"/>
      {gravity_xml}
      <ParameterList name="Displacements">
        <ParameterList name="clamp"><Parameter name="Node set" type="string" value="{clamp}"/></ParameterList>
      </ParameterList>
      <ParameterList name="Surface loads">
        <ParameterList name="load"><Parameter name="Side set" type="string" value="{load_set}"/>
          <Parameter name="{kind}" type="Array(double)" value="{xml_array(values)}"/></ParameterList>
      </ParameterList>
      {probe_xml}
      <ParameterList name="Linear solver">{solver_xml}</ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def mpi_prefix(ranks):
    """The command prefix that starts `ranks` processes (as the test suite does)."""
    prefix = ["mpirun", "-np", str(ranks), "--oversubscribe", "--bind-to", "none"]
    if os.geteuid() == 0:
        prefix.insert(1, "--allow-run-as-root")
    return prefix


def run_deck(railfe, deck_text, workdir, name, ranks=1):
    """Writes deck_text to workdir/name.xml, runs it, returns (results dir, summary dict)."""
    os.makedirs(workdir, exist_ok=True)
    deck = os.path.join(workdir, name + ".xml")
    with open(deck, "w") as out:
        out.write(deck_text)
    results = os.path.join(workdir, name + "_results")
    command = mpi_prefix(ranks) + [railfe, deck, "--output", results, "--quiet"]
    completed = subprocess.run(command, capture_output=True, text=True)
    if completed.returncode != 0:
        raise RuntimeError(f"railfe failed on {deck}:\n{completed.stderr}")
    with open(os.path.join(results, "summary.json")) as summary:
        return results, json.load(summary)


def run_or_reuse(railfe, deck_text, workdir, name, reuse=True, ranks=1):
    """run_deck (on `ranks` ranks), or (with `reuse`) the run already in workdir from the same
    deck text: its results dir and summary, read instead of run again."""
    deck = os.path.join(workdir, name + ".xml")
    results = os.path.join(workdir, name + "_results")
    if (reuse and os.path.exists(os.path.join(results, "summary.json"))
            and os.path.exists(deck) and open(deck).read() == deck_text):
        with open(os.path.join(results, "summary.json")) as summary:
            return results, json.load(summary)
    return run_deck(railfe, deck_text, workdir, name, ranks)


def csv_rows(path):
    """Rows of a CSV file as dictionaries keyed by the header."""
    with open(path) as table:
        return list(csv.DictReader(table))


def kept_rows(path, column, replaced):
    """The rows of the CSV table at `path` (none if it does not exist) whose `column` is not
    among `replaced` (compared as text): what a study keeps of runs it was not given."""
    if not os.path.exists(path):
        return []
    replaced = {str(value) for value in replaced}
    return [row for row in csv_rows(path) if row[column] not in replaced]


def step_section(summary, step):
    """The summary section of step `step` (its key starts with 'Step <name>')."""
    for key, value in summary.items():
        if key.startswith("Step " + step + " "):
            return value
    raise KeyError(step)


def wheel_modal_deck(element_size, modes, band=None, block_size=4, export=False):
    """A modal deck for the default wheel (S1002, bore fixed on a rigid axle) at `element_size`:
    the `modes` lowest modes, or every mode in `band` (Hz) with `modes` as the first guess."""
    band_xml = (f'<Parameter name="Frequency band" type="Array(double)" '
                f'value="{{{band[0]}, {band[1]}}}"/>' if band else "")
    return f"""<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="wheel modes, {element_size} m elements"/>
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="wheel"/>
    <ParameterList name="Wheel">
      <Parameter name="Element size" type="double" value="{element_size}"/>
    </ParameterList>
  </ParameterList>
{steel_materials_xml(["wheel"])}  <ParameterList name="Steps">
    <ParameterList name="wheel">
      <Parameter name="Module" type="string" value="modal"/>
      <Parameter name="Modes" type="int" value="{modes}"/>
      {band_xml}
      <Parameter name="Block size" type="int" value="{block_size}"/>
      <Parameter name="Exodus" type="bool" value="false"/>
      <Parameter name="Export matrices" type="bool" value="{str(export).lower()}"/>
      <ParameterList name="Supports">
        <ParameterList name="axle seat"><Parameter name="Node set" type="string" value="bore"/></ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def study_parser(description, work, root, reuse=False):
    """The command line every study shares: the railfe binary (default build/bin/railfe under
    `root`), --work (default `work`), --jobs and --replot; with `reuse`, --reuse too (read the
    runs already in --work from the same decks instead of running them again)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("railfe", nargs="?", default=os.path.join(root, "build", "bin", "railfe"))
    parser.add_argument("--work", default=work)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--replot", action="store_true",
                        help="redraw the chart from the CSV file without running railfe")
    if reuse:
        parser.add_argument("--reuse", action="store_true",
                            help="read the runs already in --work (same decks) instead of "
                                 "running them again")
    return parser


def typed_rows(path, text_columns):
    """The rows of a study's CSV with every value a float except the `text_columns`."""
    return [{k: (v if k in text_columns else float(v)) for k, v in row.items()}
            for row in csv_rows(path)]


def write_rows(path, rows):
    """Writes dict rows to CSV at `path` (header from the first row; floats as repr, so that
    every digit survives), creating its directory."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    columns = list(rows[0].keys())
    with open(path, "w", newline="") as out:
        # Quoted where a text holds a comma (a run's label), so that every row keeps its columns.
        table = csv.writer(out, lineterminator="\n")
        table.writerow(columns)
        for row in rows:
            table.writerow([repr(row[c]) if isinstance(row[c], float) else str(row[c])
                            for c in columns])
