#!/usr/bin/python3
"""Writes the four decks of the "lateral train-structure interaction" scene (issue 19):
inputs/scenes/lateral_structure_{bs,ts}{20,40}.xml. Each runs the test car of
docs/vehicle_parameters.md (regression/studies/vehicle_parameters.csv, calibrated to the nine
published modes, with the yaw dampers of regression/studies/vehicle_critical_speed.py) at
300 km/h over a structure deviation (bending or translation shape, 20 or 40 m spans, 8 mm), as
published: dt 1 ms, 2500 steps, alpha 0, static balance first; twice, with railfe's online
contact search and creep-force table, then with the offline contact table and Kalker's linear
theory saturated (the DIASTARS approach), charted on the same axes.

Run from the repository root: /usr/bin/python3 regression/scenes/make_lateral_structure_decks.py
[--check]   (--check: exit 1 if a shipped deck differs from what this would write)
"""
import csv
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "regression", "studies"))
import vehicle_modes_fit  # noqa: E402  (the parameters and the deck's vehicle)

PARAMETERS = vehicle_modes_fit.CSV_PATH
YAW_DAMPING = 4e6  # N m s/rad per bogie (vehicle_critical_speed.py: stable to 104 m/s)
SPEED = 300 / 3.6
REACH = 0.5  # s: when the first wheelset reaches the deviation


TRACK = """      <ParameterList name="Profiles">
        <Parameter name="Rail" type="string" value="drawing:JIS60"/>
        <Parameter name="Wheel" type="string" value="drawing:Shinkansen860"/>
      </ParameterList>
      <ParameterList name="Track">
        <Parameter name="Gauge" type="double" value="1.067"/>
        <Parameter name="Gauge point depth" type="double" value="0.016"/>
        <Parameter name="Inclination" type="double" value="0.025"/>
        <Parameter name="Back to back" type="double" value="0.990"/>
        <Parameter name="Flange back" type="double" value="0.065"/>
        <Parameter name="Nominal radius" type="double" value="0.43"/>
      </ParameterList>
"""


def step_xml(name, shape, span, start, online, compare="", alpha=0, extra_xml="", end=2.5):
    contact = ('        <Parameter name="Table half range" type="double" value="0.0073"/>\n')
    if not online:
        contact += ('        <Parameter name="Geometry" type="string" value="offline table"/>\n'
                    '        <Parameter name="Creep theory" type="string" '
                    'value="shen-hedrick-elkins"/>\n')
    extra = extra_xml + (
        f'      <Parameter name="Compare with step" type="string" value="{compare}"/>\n'
        if compare else "")
    return f"""    <ParameterList name="{name}">
      <Parameter name="Module" type="string" value="vehicle dynamics"/>
{TRACK}      <ParameterList name="Contact">
{contact}      </ParameterList>
      <Parameter name="Speed" type="double" value="{SPEED:.10g}"/>
      <Parameter name="End time" type="double" value="{end:g}"/>
      <Parameter name="Time step" type="double" value="0.001"/>
      <Parameter name="Alpha" type="double" value="{alpha:g}"/>
      <Parameter name="Newton tangent" type="string" value="once per step"/>
      <Parameter name="Measuring points" type="Array(string)" value="{{floor_above_rear_bogie}}"/>
      <ParameterList name="Structure deviation">
        <Parameter name="Shape" type="string" value="{shape}"/>
        <Parameter name="Start" type="double" value="{start:.6g}"/>
        <Parameter name="Span" type="double" value="{span:g}"/>
        <Parameter name="Amplitude" type="double" value="0.008"/>
      </ParameterList>
{extra}    </ParameterList>
"""


def deck(shape, span, p):
    short = "BS" if shape == "bending" else "TS"
    front = p["half_bogie_spacing"] + p["half_wheelbase"]
    start = front + SPEED * REACH
    what = ("two consecutive spans bent: the pier between them moved 8 mm" if shape == "bending"
            else "one span rotated to 8 mm, the next translated by 8 mm, then back")
    return f"""<!--
  Lateral train-structure interaction, {short} {span:g} m (issue 19): the test car (car body, two
  bogies, four wheelsets; docs/vehicle_parameters.md, its nine published modes reproduced, with
  yaw dampers of 4 MN m s/rad per bogie, which keep it from hunting at this speed) at 300 km/h on
  JIS 60 kg rails with 860 mm Shinkansen-type wheels (gauge 1067 mm, 1:40) over a structure whose
  lateral deviation has the {short} shape: {what}, spans of {span:g} m, the rails following on
  their pads (transitions of about 3 m at the span ends). The first wheelset reaches the
  structure at t = {REACH:g} s. As published: dt 1 ms, 2500 steps, HHT alpha 0, static balance
  first; rigid structure (the roller rig of the test plant).
  Step 'online': railfe's model (online contact search, creep-force table). Step 'offline': the
  DIASTARS approach (offline contact table, Kalker's linear theory saturated by
  Shen-Hedrick-Elkins), charted against 'online'.
  Written by regression/scenes/make_lateral_structure_decks.py.
  Run: railfe {os.path.basename(name_of(shape, span))}   (about 4 s)
  Look at: online_chart.png, offline_chart.png (both models), *_flange_impacts.csv,
  *_safety.csv, *_comfort.csv, summary.txt
-->
<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="Lateral train-structure interaction: {short} {span:g} m at 300 km/h"/>
{vehicle_modes_fit.vehicle_deck_xml(p, yaw_damping=YAW_DAMPING)}  <ParameterList name="Steps">
{step_xml("online", shape, span, start, True)}{step_xml("offline", shape, span, start, False, "online")}  </ParameterList>
</ParameterList>
"""


def girders_xml(start):
    return f"""      <ParameterList name="Structure">
        <Parameter name="Model" type="string" value="girders"/>
        <Parameter name="Start" type="double" value="{start:.6g}"/>
        <Parameter name="Span" type="double" value="20"/>
        <Parameter name="Spans" type="int" value="4"/>
      </ParameterList>
"""


def viaduct_deck(p):
    """BS 20 m on the roller rig and on a viaduct of four continuous 20 m spans (the deviated
    pair in the middle), both with alpha -0.1: at 0 the girders' unresolved modes ring through
    the massless contact nodes and Newton needs 14 to 25 iterations, then fails at 0.67 s."""
    front = p["half_bogie_spacing"] + p["half_wheelbase"]
    start = front + SPEED * REACH
    return f"""<!--
  Lateral train-structure interaction, BS 20 m (issue 19): the structure as a girder against the
  roller rig. The test car at 300 km/h over the BS deviation (8 mm, spans of 20 m) twice: step
  'roller_rig' on rigid ground (the test plant), step 'viaduct' on a girder continuous over four
  20 m spans (the deviated pair in the middle, piers on bearings, abutments at both ends; the
  Structure defaults: a representative single-track share of a prestressed-concrete Shinkansen
  girder, docs/vehicle_parameters.md), whose deflection under the wheels the rails follow on top
  of the deviation. Both with HHT alpha -0.1: at alpha 0 the girder's modes above what 1 ms
  resolves ring through the massless contact nodes (Newton 14 to 25 iterations a step, then no
  convergence at 0.67 s; docs/verification.md#vehicle).
  Written by regression/scenes/make_lateral_structure_decks.py.
  Run: railfe lateral_structure_bs20_viaduct.xml   (about 4 s)
  Look at: viaduct_chart.png (both), viaduct_girders.csv (midspan displacements), summary.txt
-->
<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="Lateral train-structure interaction: BS 20 m, roller rig and viaduct"/>
{vehicle_modes_fit.vehicle_deck_xml(p, yaw_damping=YAW_DAMPING)}  <ParameterList name="Steps">
{step_xml("roller_rig", "bending", 20, start, True, alpha=-0.1)}{step_xml("viaduct", "bending", 20, start, True, "roller_rig", -0.1, girders_xml(start - 20))}  </ParameterList>
</ParameterList>
"""


SWEEP = """      <ParameterList name="Sweep">
        <Parameter name="Speeds" type="Array(double)" value="{55.55555555555556, 69.44444444444444, 83.33333333333333, 97.22222222222223}"/>
        <Parameter name="Amplitudes" type="Array(double)" value="{0.008, 0.016, 0.024}"/>
      </ParameterList>
"""


def sweep_deck(p):
    front = p["half_bogie_spacing"] + p["half_wheelbase"]
    start = front + SPEED * REACH
    return f"""<!--
  Lateral train-structure interaction, BS 20 m (issue 19), swept: 200, 250, 300 and 350 km/h
  against deviation amplitudes of 8, 16 and 24 mm, twelve cases of railfe's online model (alpha
  0, 1 ms as published), each over the same 208 m of track, dealt out over the MPI ranks
  (mpirun -np 2 railfe lateral_structure_bs20_sweep.xml). One table, sweep_sweep.csv, and its
  chart sweep_sweep.png: running safety (Y/Q, its 2 m mean, dQ/Q) and comfort against speed, a
  line per amplitude, cases that stopped (Newton failed, a wheelset left the rails) marked.
  Written by regression/scenes/make_lateral_structure_decks.py.
  Run: railfe lateral_structure_bs20_sweep.xml   (about 40 s on one rank)
-->
<ParameterList name="railfe">
  <Parameter name="Title" type="string" value="Lateral train-structure interaction: BS 20 m swept over speed and amplitude"/>
{vehicle_modes_fit.vehicle_deck_xml(p, yaw_damping=YAW_DAMPING)}  <ParameterList name="Steps">
{step_xml("sweep", "bending", 20, start, True, extra_xml=SWEEP)}  </ParameterList>
</ParameterList>
"""


def name_of(shape, span):
    return os.path.join(ROOT, "inputs", "scenes",
                        "lateral_structure_%s%d.xml" % ("bs" if shape == "bending" else "ts", span))


def main():
    check = "--check" in sys.argv[1:]
    p = {r["name"]: float(r["value"]) for r in csv.DictReader(open(PARAMETERS))}
    stale = []
    decks = [(name_of(shape, span), deck(shape, span, p)) for shape in ("bending", "translation")
             for span in (20, 40)]
    scenes = os.path.join(ROOT, "inputs", "scenes")
    decks.append((os.path.join(scenes, "lateral_structure_bs20_viaduct.xml"), viaduct_deck(p)))
    decks.append((os.path.join(scenes, "lateral_structure_bs20_sweep.xml"), sweep_deck(p)))
    for path, text in decks:
        if check:
            if not os.path.exists(path) or open(path).read() != text:
                stale.append(path)
            continue
        with open(path, "w") as f:
            f.write(text)
        print(path)
    if stale:
        print("not what make_lateral_structure_decks.py writes (run it): " + ", ".join(stale))
        sys.exit(1)


if __name__ == "__main__":
    main()
