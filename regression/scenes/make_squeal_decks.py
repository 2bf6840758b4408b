#!/usr/bin/env python3
"""Writes the squeal rolling scene's decks (issue 16): inputs/scenes/squeal_case1..5.xml at full
scale, inputs/scenes/squeal_demo.xml (case 3, coarse, about a minute) and, for the studies, any
variant (mesh size, track length, sleepers, end time) with --variant options. Also the steady
check's cylindrical tread, inputs/profiles/cylindrical_tread.prw (--tread cylinder).

One model, every deck: an S1002 wheel (920 mm) with half its axle on a 54E1 rail inclined 1:40
on rail pads, sleepers (point masses) and ballast; a statics preload under gravity and the sprung
mass's weight, then explicit rolling at 100 km/h with a driving torque and, for cases 2-5, a
prescribed lateral motion of the axle box. The decks are generated so that the wheel's refined
arc, the rail's solution zone and the time line always agree; edit this script, not the decks.

  make_squeal_decks.py                 # rewrite the shipped decks in inputs/scenes
  make_squeal_decks.py --check         # exit 1 if a shipped deck differs from what it would write
  make_squeal_decks.py --case 1 --zone-size 0.004 --output /tmp/case1_4mm.xml   # a study variant
  make_squeal_decks.py --case 1 --scale demo --torque 0 --kinematics   # free rolling, creepage
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "inputs", "scenes")

SPEED = 100 / 3.6  # m/s
ROLLING_RADIUS = 0.46038  # m, S1002 radius at the contact point on the inclined 54E1
WHEEL_RADIUS = 0.46  # m, the wheel generator's running circle (its slices' lengths are there)
RAIL_OFFSET = -0.0025  # m, rail centre from the running circle (standard gauge)
AXIS_HEIGHT = 0.459916265  # m, wheel part Translation z: 20 um into the rail (squeal_placement.py)
INCLINATION = -math.degrees(math.atan(1 / 40))  # about +x: the head tilts towards +y (the flange)
SPRUNG_MASS = 10836.0  # kg: car body and bogie share, the static wheel load 111.3 kN
SPRUNG_WEIGHT = SPRUNG_MASS * 9.81
TORQUE = 13800.0  # N m: traction coefficient about 0.27 at the 111 kN load (0.27 * Q * r)
SLEEPER_SPACING = 0.6  # m
SLEEPER_MASS = 150.0  # kg, half a concrete monoblock sleeper
PAD = {"vertical": 1.3e9, "damping": 4.5e4, "shear": 5.0e7}  # N/m, N s/m, N/m
BALLAST = {"vertical": 4.5e7, "damping": 3.2e4}  # N/m, N s/m per sleeper (per rail seat)
PAD_LENGTH = 0.15  # m along the rail under each seat
# Sleepers as coarse solids (--sleepers solids): half a concrete monoblock (B70-like, 2.6 m long)
# under each seat, 12 hex8 as in the seed, from 0.55 m outside the rail's centre to the track's
# centre line, 0.25 m wide and 0.2 m deep (156 kg); its top 15 mm below the rail's foot.
SLEEPER_BOX = {"lengths": (0.25, 1.3, 0.2), "elements": (2, 6, 1), "field_side": 0.55,
               "top": -0.175}
CONCRETE = {"E": 38e9, "nu": 0.2, "density": 2400}  # Pa, -, kg/m3: prestressed C50/60
# Pad and ballast in series (N/m): a seat's vertical support in statics and in the shipped decks.
SEAT_VERTICAL = PAD["vertical"] * BALLAST["vertical"] / (PAD["vertical"] + BALLAST["vertical"])

LEAD_IN = 0.056  # m of refined arc rolled before the solution zone (2 ms at 100 km/h)

# Lateral motion of the axle box (cases 2-4 small, medium, large): the lateral speed reached,
# as a rigid lateral creepage v_y / V. The creepage in the patch lags it far behind: until the
# lateral force nears its bound, the wheel, axle and rail bend and take the motion (about 25 kN
# of lateral force per mm of axle box motion, 70 N per mm/s of its speed at 19 ms, linear up to
# 28.7 kN; a time constant of some 25 ms against the 3 ms the run has). The speeds are chosen
# from that and the exact solver's inverse problem on the profiles so that the patch's lateral
# creepage at 19 ms is about 0.02, 0.15 and 0.45 % (the seed's Table 3): lateral forces of
# about -7, -22 and -41 kN (docs/verification.md, 2026-11-29).
LATERAL_CREEPAGE = {1: 0.0, 2: 0.003, 3: 0.011, 4: 0.021, 5: 0.011}

# The steady-state check's hold (--hold-creepage): the axle box carries the wheel inside this
# radius (the rim's inner surface is at 395 mm), and a flywheel's inertia about the axle keeps its
# spin: a 20 kN creep force changes it by 2e-7 of itself per ms.
HOLD_RADIUS = 0.385  # m
HOLD_INERTIA = 1.0e6  # kg m^2
# Along the axle, the hub's length (the default wheel's 180 mm about a = 20 mm): the half axle
# beyond it stays elastic, and the preload holds and loads the same nodes, so that it has no
# tilt from the axle's bending that a rigid start would snap out (2.9e-3 rad, 1.3 mm at the tread).
HOLD_HUB = (-0.071, 0.111)  # m

# The steady check's control (--tread cylinder): a tread without conicity at the running circle
# (the S1002 file's flange kept, lowered to meet it: cylinder_profile_text) on the rail upright
# and centred under it. The contact is then Hertz's on the crown's R300, with no spin and no
# change of rolling radius across the patch, so the half-space reference is not in doubt.
CYLINDER_PROFILE = os.path.join(HERE, "..", "..", "inputs", "profiles", "cylindrical_tread.prw")
CYLINDER_FLAT_TO = 0.02  # m: the tread is flat up to here towards the flange
TREADS = {
    "S1002": {"rolling_radius": ROLLING_RADIUS, "rail_offset": RAIL_OFFSET,
              "inclination": INCLINATION, "axis_height": AXIS_HEIGHT},
    "cylinder": {"rolling_radius": WHEEL_RADIUS, "rail_offset": 0.0, "inclination": 0.0,
                 "axis_height": WHEEL_RADIUS - 2e-5},  # the same 20 um first penetration
}

FULL = {
    "title": "full scale",
    "rail_length": 2.4, "start_x": 0.7, "zone": (0.39, 0.54),
    "zone_size": 0.001, "rail_size": 0.02, "head_size": 0.001, "section_size": 0.01,
    "wheel_size": 0.03, "tread_size": 0.002, "arc_size": 0.001, "approach_size": 0.004,
    "end_time": 0.019, "ramp": 0.006, "lateral_start": 0.016, "lateral_ramp": 5e-4,
    # The seed's 86 ns: 0.15 kg on 3,855 small elements (0.001 %; solids then 88 ns, not 50).
    # Every 0.25 ms from 14 ms; every 0.1 ms over 18-19 ms: eight instants of one period of the
    # creep force's strongest oscillation (about 1.25 kHz in case 1), the seed's Fig. 5; and 32
    # instants 0.25 us apart from 18.55 ms, in which a surface wave (2975 m/s) crosses the patch
    # a few times: the speed of the waves seen in the patch.
    "patch_times": sorted({round(0.014 + 0.00025 * k, 7) for k in range(21)}
                          | {round(0.018 + 0.0001 * k, 7) for k in range(11)}
                          | {round(0.01855 + 2.5e-7 * k, 10) for k in range(32)}),
    "mass_scaling": 8.6e-8,
    "mass_scaling_note": True,
    "modes": True, "sleepers": "solids", "transitions": (0.30, 0.12),
    # The softer side at f = 4: f = 2 gave r = 0.078 under the full preload (patch 5.9 x 9.5 mm,
    # docs/verification.md), so f = 4 about 0.039, below the warning's 0.05; its nodes made
    # heavier until its step is 1.5 x the solids' (0.99 kg on 29,184 nodes): 79 ns steps.
    "penalty": 4, "penalty_stiffness": "bulk modulus, softer side",
    "contact_mass_scaling": 1.3e-7,
    # About 1.7 h of two cores: a checkpoint every 10,000 steps (0.79 ms, 4 min), and the same
    # command resumes from it.
    "checkpoint": 10000,
}
DEMO = {
    "title": "demo scale",
    "rail_length": 1.2, "start_x": 0.45, "zone": (-0.005, 0.05),
    "zone_size": 0.004, "rail_size": 0.04, "head_size": 0.004, "section_size": 0.02,
    "wheel_size": 0.06, "tread_size": 0.004, "arc_size": 0.004,
    "end_time": 0.0016, "ramp": 5e-4, "lateral_start": 6e-4, "lateral_ramp": 1e-4,
    "patch_times": [0.0006, 0.001, 0.0013, 0.0016], "mass_scaling": 1.0e-7,
    # r = 0.040 at f = 15 (creep forces about 4 % low where the patch sticks), 78 ns contact
    # step; f = 1 on plain bulk modulus gave 0.49 at 95 ns (docs/verification.md).
    "transitions": (0.30, 0.12), "penalty": 15, "penalty_stiffness": "bulk modulus, softer side",
    # The contact's nodes made heavier until its step is 1.5 x the solids' 224 ns (no coupled
    # limit): 1.4 kg on 2,187 tread and rail-head nodes, 22,797 -> 7,945 steps; forces within
    # 0.2-3.5 % of the run without (docs/verification.md, "Demo: contact mass scaling").
    "contact_mass_scaling": 3.4e-7,
}

# Cases 1-4's Coulomb friction and case 5's falling friction (the seed's): static and dynamic
# coefficients and the decay (s/m).
COULOMB_FRICTION = 0.45
FALLING_FRICTION = (0.5, 0.32, 6.0)


def geometry(p):
    """The wheel's and rail's placement for the deck's tread (TREADS)."""
    return TREADS[p.get("tread", "S1002")]


def cylinder_profile_text():
    """The cylindrical tread as a SIMPACK wheel profile (mm): flat at the running circle from
    the field side to CYLINDER_FLAT_TO, then the S1002 file's points lowered and tilted so that
    height and slope meet the flat there (the flange's tip about 5 mm lower, still the highest
    point, far from the rail)."""
    sys.path.insert(0, HERE)
    import squeal_placement
    points = squeal_placement.wheel_profile()
    y1, dy = CYLINDER_FLAT_TO, 1e-4
    z1 = squeal_placement.interpolate(points, y1)
    slope = (squeal_placement.interpolate(points, y1 + dy) - z1) / dy
    flat = [(points[0][0] + k * (y1 - points[0][0]) / 40, 0.0) for k in range(40)]
    flange = [(y, z - z1 - slope * (y - y1)) for y, z in points if y >= y1]
    lines = ["! A cylindrical tread with the S1002 flange: written by",
             "! regression/scenes/make_squeal_decks.py (the steady check's control, --tread",
             "! cylinder) from MBench_S1002_v3.prw; y lateral (flange on +y), z radially out, mm.",
             "  header.begin", "    version = 1", "    type    = 1", "  header.end",
             "  spline.begin", "    units.len.f = 1000.", "    units.ang.f = 1.", "    point.begin"]
    lines += [f"      {1e3 * y:.6f} {1e3 * z:.6f}" for y, z in flat + flange]
    lines += ["    point.end", "  spline.end"]
    return "\n".join(lines) + "\n"


def falling_friction(case):
    """(mu_s, mu_d, decay) if \p case has falling friction, None if Coulomb."""
    return FALLING_FRICTION if case == 5 else None


def friction(case):
    if falling_friction(case):
        mu_s, mu_d, decay = falling_friction(case)
        return ('<Parameter name="Friction" type="string" value="velocity dependent"/>\n'
                f'<Parameter name="Static coefficient" type="double" value="{mu_s:g}"/>\n'
                f'<Parameter name="Dynamic coefficient" type="double" value="{mu_d:g}"/>\n'
                f'<Parameter name="Decay" type="double" value="{decay:g}"/>')
    return ('<Parameter name="Friction" type="string" value="coulomb"/>\n'
            f'<Parameter name="Friction coefficient" type="double" value="{COULOMB_FRICTION:g}"/>')


def lateral_motion(case, p):
    """Motion y of the axle box: at rest until lateral_start, the speed ramped up linearly over
    lateral_ramp (no jump in velocity, so no impulse), then constant."""
    v = LATERAL_CREEPAGE[case] * SPEED
    if v == 0:
        return None
    t1, tr = p["lateral_start"], p["lateral_ramp"]
    return (f"t &lt; {t1:g} ? 0 : (t &lt; {t1 + tr:g} ? {v / (2 * tr):.6g}*(t - {t1:g})^2 : "
            f"{v:.6g}*(t - {t1 + tr / 2:g}))")


def track_springs(seats, sleepers, bodies, rail_offset):
    """The explicit step's rail supports. "springs": each seat's nodes on pad and ballast in
    series to the ground, as the statics preload has them (the sleepers' mass left out), so the
    run starts in balance. "bodies": a sleeper point mass under each seat, the pad between them
    and the ballast below; the preload, which has no sleeper unknowns, then differs from it in
    how the pad resists the seat's rotation, and the run starts with a transient (appends the
    sleepers to \p bodies). "solids": each sleeper a coarse concrete solid, the pad a spring from
    the seat's nodes to the sleeper's top and the ballast below, the same in the preload, so the
    run starts in balance."""
    springs = []
    series = SEAT_VERTICAL
    # Two Kelvin elements in series, at frequencies well below kp / cp: each damper weighted by
    # the square of the other spring's share of the compliance.
    share = BALLAST["vertical"] / (PAD["vertical"] + BALLAST["vertical"])
    damping = PAD["damping"] * share**2 + BALLAST["damping"] * (1 - share)**2
    for k, x in enumerate(seats):
        seat = f"seat {k + 1}"
        if sleepers == "springs":
            springs.append(block(f"support {k + 1}", "\n".join([
                p_("End A", "string", seat),
                p_("Stiffness", "Array(double)", fmt([PAD["shear"], PAD["shear"], series])),
                p_("Damping", "Array(double)", fmt([PAD["damping"], PAD["damping"], damping]))]),
                0))
            continue
        name = f"sleeper {k + 1}"
        if sleepers == "solids":
            # The pad ties each seat node to the nearest node of the sleeper's top; the ballast
            # carries the sleeper's bottom, which is held sideways and along (Prescribed motion).
            springs.append(block(f"pad {k + 1}", "\n".join([
                p_("End A", "string", seat), p_("End B", "string", f"{name}.zmax"),
                p_("Stiffness", "Array(double)",
                   fmt([PAD["shear"], PAD["shear"], PAD["vertical"]])),
                p_("Damping", "Array(double)", fmt([PAD["damping"]] * 3))]), 0))
            springs.append(block(f"ballast {k + 1}", "\n".join([
                p_("End A", "string", f"{name}.zmin"),
                p_("Stiffness", "Array(double)", fmt([0, 0, BALLAST["vertical"]])),
                p_("Damping", "Array(double)", fmt([0, 0, BALLAST["damping"]]))]), 0))
            continue
        bodies.append(block(name, "\n".join([
            p_("Reference point", "Array(double)", fmt([x, rail_offset, -0.25])),
            p_("Mass", "double", f"{SLEEPER_MASS:g}"), p_("Fixed translations", "string", "xy"),
            p_("Weight", "bool", "false")]), 0))
        springs.append(block(f"pad {k + 1}", "\n".join([
            p_("End A", "string", seat), p_("End B", "string", name),
            p_("Stiffness", "Array(double)", fmt([PAD["shear"], PAD["shear"], PAD["vertical"]])),
            p_("Damping", "Array(double)", fmt([PAD["damping"]] * 3))]), 0))
        springs.append(block(f"ballast {k + 1}", "\n".join([
            p_("End A", "string", name),
            p_("Stiffness", "Array(double)", fmt([0, 0, BALLAST["vertical"]])),
            p_("Damping", "Array(double)", fmt([0, 0, BALLAST["damping"]]))]), 0))
    return springs


def sleeper_parts(seats, rail_offset):
    """The sleepers as box parts under the seats (--sleepers solids), and their blocks."""
    lx, ly, lz = SLEEPER_BOX["lengths"]
    parts = [block(f"sleeper {k + 1}", "\n".join([
        p_("Type", "string", "box"),
        block("Box", "\n".join([
            p_("Origin", "Array(double)", fmt([x - lx / 2, rail_offset - SLEEPER_BOX["field_side"],
                                               SLEEPER_BOX["top"] - lz])),
            p_("Lengths", "Array(double)", fmt([lx, ly, lz])),
            p_("Elements", "Array(int)", "{%d, %d, %d}" % SLEEPER_BOX["elements"]),
            p_("Block name", "string", "sleeper")]), 0)]), 0) for k, x in enumerate(seats)]
    return parts, [f"sleeper {k + 1}.sleeper" for k in range(len(seats))]


def wheel_modes(x0, axis_height):
    """The modal step of the wheel and half axle alone (the rail left out), clamped at the axle
    end as the axle box holds it: the modes the rim's spectra are matched to (the seed's Table
    4), from the very mesh that rolls. The refined arc breaks the wheel's symmetry, so doublets
    split: by up to 0.35 % in frequency, 0.7 % in eigenvalue, at demo scale."""
    return "\n".join([
        p_("Module", "string", "modal"),
        p_("Blocks", "Array(string)", "{wheel.wheel, wheel.axle}"),
        p_("Frequency band", "Array(double)", "{20, 2500}"),
        p_("Doublet tolerance", "double", "2e-2"),
        block("Supports", block("axle box", p_("Node set", "string", "wheel.axle_end"), 0), 0),
        block("Classification", p_("Axisymmetric", "bool", "true") + "\n" +
              p_("Axis origin", "Array(double)", fmt([x0, 0, axis_height])), 0)])


def refined_arc(p):
    """The wheel's refined arc (degrees): every material point of the tread that touches the rail
    in the run, from the lowest point (270, the start) to the one that leaves the zone, plus a
    patch length on either side. Coarse slices there would be chords whose sag (L^2 / 8R: 0.24 mm
    for 30 mm) exceeds the contact's 20 um penetration, so the wheel would touch nowhere or bump.
    The arc's ends are whole slices away from 270, so that a slice boundary, and the nodes the
    preload rests on, lie on the lowest point."""
    slice_deg = math.degrees(p["arc_size"] / WHEEL_RADIUS)
    r0 = geometry(p)["rolling_radius"]
    margin = math.degrees(0.012 / r0)
    if p.get("approach_size"):
        # Only what rolls through the zone, entered LEAD_IN (2 ms) before it so that the change
        # from the approach's slices has passed (docs/verification.md#squeal-scene);
        # approach_arc() leads to it.
        return (270 + math.degrees((p["zone"][0] - LEAD_IN) / r0) - margin,
                270 + math.degrees(p["zone"][1] / r0) + margin)
    before = min(0.0, math.degrees(p["zone"][0] / r0)) - margin
    after = math.degrees(p["zone"][1] / r0) + margin
    start = 270 - math.ceil(-before / slice_deg) * slice_deg
    count = math.ceil((270 + after - start) / slice_deg)
    return (start, start + count * slice_deg)


def approach_arc(p, arc):
    """With an approach size (the full-scale decks), the path the tread rolls before the zone:
    from a patch length behind the lowest point to the refined arc, meshed at approach_size
    (4 mm: chords sag 4 um, a fifth of the contact's penetration) instead of the arc's 1 mm,
    which halves the wheel's elements. None without."""
    if not p.get("approach_size"):
        return None
    return (270 - math.degrees(0.012 / geometry(p)["rolling_radius"]), arc[1])


def tread_box(arc):
    """A box (wheel part coordinates) around the tread faces from the lowest point (the contact at
    the start) to the end of the refined arc: only they can touch the rail in the run, so only
    they are searched for contact."""
    lo, hi = (math.radians(a) for a in arc)
    r_in, r_out, margin = 0.40, 0.52, 0.01
    return [r_in * math.cos(lo) - margin, r_out * math.cos(hi) + margin, -1, 1,
            r_out * math.sin(lo) - margin, r_in * math.sin(hi) + margin]


def fmt(values):
    return "{" + ", ".join(f"{v:.9g}" for v in values) + "}"


def sleeper_positions(length):
    count = int(math.floor(length / SLEEPER_SPACING + 1e-9))
    first = (length - (count - 1) * SLEEPER_SPACING) / 2
    return [first + k * SLEEPER_SPACING for k in range(count)]


def p_(name, kind, value):
    return f'<Parameter name="{name}" type="{kind}" value="{value}"/>'


def block(name, body, indent):
    pad = " " * indent
    inner = "\n".join(pad + "  " + line for line in body.split("\n"))
    return f'{pad}<ParameterList name="{name}">\n{inner}\n{pad}</ParameterList>'


def deck(case, p, sleepers=True):
    x0 = p["start_x"]
    zone = (x0 + p["zone"][0], x0 + p["zone"][1])
    place = geometry(p)
    omega = SPEED / place["rolling_radius"]
    arc = refined_arc(p)
    approach = approach_arc(p, arc)
    seats = sleeper_positions(p["rail_length"])
    series = SEAT_VERTICAL
    motion = lateral_motion(case, p)
    hold = p.get("hold_creepage")
    spin = omega * (1 + (hold or 0))
    carried = "wheel.axle_end" if hold is None else "wheel.hub"  # what the axle box holds
    L = []
    L.append("<ParameterList name=\"railfe\">")
    L.append("  " + p_("Title", "string", f"Squeal rolling scene, case {case} ({p['title']})"))
    node_sets = []
    for k, x in enumerate(seats):
        node_sets.append(block(f"seat {k + 1}", p_("Box", "Array(double)", fmt(
            [x - PAD_LENGTH / 2, x + PAD_LENGTH / 2, -1, 1, -1, 1])) + "\n" +
            p_("Within", "string", "rail.foot_bottom"), 0))
    rail = "\n".join([
        p_("Type", "string", "rail"),
        block("Rail", "\n".join([
            p_("Profile", "string", "54E1"), p_("Length", "double", p["rail_length"]),
            p_("Solution zone", "Array(double)", fmt(zone)),
            p_("Zone element size", "double", p["zone_size"]),
            p_("Element size", "double", p["rail_size"]),
            p_("Head element size", "double", p["head_size"]),
            p_("Section element size", "double", p["section_size"])]), 0),
        p_("Rotation axis", "Array(double)", "{1, 0, 0}"),
        p_("Rotation angle", "double", f"{place['inclination']:.16g}"),
        p_("Translation", "Array(double)", fmt([0, place["rail_offset"], 0]))])
    rim = (place["rolling_radius"] - 0.03, -0.06, 0.0)  # field-side rim face, ahead of the axle
    wheel = "\n".join([
        p_("Type", "string", "wheel"),
        block("Wheel", "\n".join([
            p_("Half axle", "bool", "true"), p_("Element size", "double", p["wheel_size"])] + ([
            p_("Profile file", "string", os.path.abspath(CYLINDER_PROFILE))]
            if p.get("tread") == "cylinder" else []) + [
            p_("Tread element size", "double", p["tread_size"]),
            p_("Refined arc", "Array(double)", "{%.15g, %.15g}" % arc),
            p_("Arc element size", "double", p["arc_size"])] + ([
            p_("Approach arc", "Array(double)", "{%.15g, %.15g}" % approach),
            p_("Approach element size", "double", p["approach_size"])] if approach else []) + ([
            p_("Transition radii", "Array(double)", fmt(p["transitions"]))]
            if p.get("transitions") else [])),
            0),
        block("Node sets", "\n".join([
            block("all", p_("Box", "Array(double)", "{-1, 1, -1, 1, -1, 1}"), 0),
            block("rim point", p_("Point", "Array(double)", fmt(rim)), 0)] + ([
            block("hub cylinder", p_("Cylinder", "Array(double)",
                                     fmt([0, 0, 0, 0, 1, 0,
                                          p.get("hold_radius") or HOLD_RADIUS])), 0),
            block("hub", p_("Box", "Array(double)", fmt([-1, 1, *HOLD_HUB, -1, 1])) + "\n" +
                  p_("Within", "string", "hub cylinder"), 0)]
            if hold is not None else []) + ([
            block("rim behind", p_("Point", "Array(double)", fmt((-rim[0],) + rim[1:])), 0)]
            if p.get("kinematics") else [])), 0),
        block("Side sets", block("rolling tread", p_("Box", "Array(double)", fmt(
            tread_box((approach or arc)[:1] + arc[1:]))) + "\n" +
            p_("Within", "string", "tread"), 0), 0),
        p_("Translation", "Array(double)", fmt([x0, 0, place["axis_height"]]))])
    solid_sleepers = p.get("sleepers") == "solids"
    sleepers, sleeper_blocks = (sleeper_parts(seats, place["rail_offset"]) if solid_sleepers
                                else ([], []))
    mesh = "\n".join([
        p_("Type", "string", "parts"),
        block("Parts", "\n".join([block("rail", rail, 0), block("wheel", wheel, 0)] + sleepers),
              0),
        block("Node sets", "\n".join(node_sets), 0)])
    L.append(block("Mesh", mesh, 2))
    materials = [block("steel", "\n".join([
        p_("Young's modulus", "double", "210e9"), p_("Poisson's ratio", "double", "0.3"),
        p_("Density", "double", "7850"),
        p_("Blocks", "Array(string)", "{rail.rail, wheel.wheel, wheel.axle}")]), 0)]
    if solid_sleepers:
        materials.append(block("concrete", "\n".join([
            p_("Young's modulus", "double", f"{CONCRETE['E']:g}"),
            p_("Poisson's ratio", "double", f"{CONCRETE['nu']:g}"),
            p_("Density", "double", f"{CONCRETE['density']:g}"),
            p_("Blocks", "Array(string)", "{" + ", ".join(sleeper_blocks) + "}")]), 0))
    L.append(block("Materials", "\n".join(materials), 2))
    contact_common = "\n".join([
        p_("Slave side set", "string", "wheel.rolling tread"),
        p_("Master side set", "string", "rail.running_surface"),
        p_("Penalty factor", "double", f"{p.get('penalty', 1):g}")] +
        ([p_("Penalty stiffness", "string", p["penalty_stiffness"])]
         if p.get("penalty_stiffness", "bulk modulus") != "bulk modulus" else []))
    ends = lambda extra: "\n".join(
        block(n, p_("Node set", "string", s) + extra, 0)
        for n, s in (("rail start", "rail.start_face"), ("rail end", "rail.end_face")))
    held_xy = "\n" + p_("Components", "string", "xy")
    # Statics: the pad and the ballast in series to the ground (a sleeper's weight only presses
    # the ballast; the explicit step leaves it out), shear stiffness of the pad alone.
    static_springs = "\n".join(
        block(f"seat {k + 1}", p_("Node set", "string", f"seat {k + 1}") + "\n" + p_(
            "Stiffness", "Array(double)", fmt([PAD["shear"], PAD["shear"], series])), 0)
        for k in range(len(seats)))
    held_sleepers = ""
    if solid_sleepers:
        # The explicit step's pads and ballast, stiffness only.
        static_springs = "\n".join(
            block(f"pad {k + 1}", "\n".join([
                p_("Node set", "string", f"seat {k + 1}"),
                p_("To node set", "string", f"sleeper {k + 1}.zmax"),
                p_("Stiffness", "Array(double)",
                   fmt([PAD["shear"], PAD["shear"], PAD["vertical"]]))]), 0) + "\n" +
            block(f"ballast {k + 1}", "\n".join([
                p_("Node set", "string", f"sleeper {k + 1}.zmin"),
                p_("Stiffness", "Array(double)", fmt([0, 0, BALLAST["vertical"]]))]), 0)
            for k in range(len(seats)))
        held_sleepers = "\n" + "\n".join(
            block(f"sleeper {k + 1}", p_("Node set", "string", f"sleeper {k + 1}.zmin") + held_xy,
                  0) for k in range(len(seats)))
    preload = "\n".join([
        p_("Module", "string", "statics"), p_("Gravity", "Array(double)", "{0, 0, -9.81}"),
        p_("Contact tolerance", "double", "5e-4"),
        block("Solid", p_("Integration", "string", "one point"), 0),
        block("Linear solver", p_("Method", "string", "cholmod"), 0),
        block("Displacements", ends(held_xy) + "\n" + block("axle box", p_(
            "Node set", "string", carried) + "\n" + p_("Components", "string", "xy"), 0)
            + held_sleepers, 0),
        block("Nodal forces", block("sprung mass", p_("Node set", "string", carried) +
                                    "\n" + p_("Total force", "Array(double)",
                                              fmt([0, 0, -SPRUNG_WEIGHT])), 0), 0),
        block("Centrifugal loads", block("rolling wheel", "\n".join([
            p_("Node set", "string", "wheel.all"),
            p_("Angular velocity", "Array(double)", fmt([0, omega, 0])),
            p_("Axis point", "Array(double)", fmt([x0, 0, place["axis_height"]]))]), 0), 0),
        block("Springs", static_springs, 0),
        block("Contact pairs", block("wheel-rail", contact_common, 0), 0)])
    axle_box = [p_("Node set", "string", "wheel.axle_end"),
                p_("Velocity", "Array(double)", fmt([SPEED, 0, 0])),
                p_("Angular velocity", "Array(double)", fmt([0, omega, 0])),
                p_("Fixed rotations", "string", "xz")]
    if hold is not None:
        # The steady-state check's hold: the box carries the hub and web (not the rim, not the
        # axle beyond the hub) at the rolling speed and, through a flywheel's inertia, a
        # constant spin.
        axle_box = [p_("Node set", "string", carried),
                    p_("Reference point", "Array(double)", fmt([x0, 0, place["axis_height"]])),
                    p_("Inertia", "Array(double)", fmt([0, HOLD_INERTIA, 0])),
                    p_("Angular velocity", "Array(double)", fmt([0, spin, 0])),
                    p_("Motion x", "string", f"{SPEED!r} * t"),
                    p_("Fixed rotations", "string", "xz")]
    axle_box.append(p_("Motion y", "string", motion) if motion else
                    p_("Fixed translations", "string", "y"))
    bodies = [block("axle box", "\n".join(axle_box), 0),
              block("sprung mass", "\n".join([
                  p_("Reference point", "Array(double)", fmt([x0, 0.75, 1.2])),
                  p_("Mass", "double", f"{SPRUNG_MASS:g}"),
                  p_("Velocity", "Array(double)", fmt([SPEED, 0, 0])),
                  p_("Fixed translations", "string", "y")]), 0)]
    springs = [block("primary suspension", "\n".join([
        p_("End A", "string", "axle box"), p_("End B", "string", "sprung mass"),
        p_("Stiffness", "Array(double)", "{1e7, 0, 1.15e6}"),
        p_("Damping", "Array(double)", "{1e4, 0, 2.5e3}")]), 0)]
    springs += track_springs(seats, p.get("sleepers", "springs"), bodies, place["rail_offset"])
    histories = [block(n, p_("Node set", "string", "wheel.rim point") + "\n" +
                       p_("Quantity", "string", "velocity") + "\n" + p_("Component", "string", c), 0)
                 for n, c in (("rim vx", "x"), ("rim vy", "y"), ("rim vz", "z"))]
    histories += [block(n, p_("Body", "string", b) + "\n" + p_("Component", "string", c) +
                        ("\n" + p_("Quantity", "string", q) if q else ""), 0)
                  for n, b, c, q in (("axle y", "axle box", "y", None),
                                     ("axle z", "axle box", "z", None),
                                     ("axle spin", "axle box", "y", "angular velocity"),
                                     ("sprung z", "sprung mass", "z", None))]
    if p.get("kinematics"):
        # What the creepage is measured from: two rim points at axle height, ahead and behind
        # (their velocities and where they are: the wheel's turning and its centre's speed),
        # and the axle box's speed (the axle's far end, which lags the wheel as the axle bends).
        histories += [block(n, p_(k, "string", s) + "\n" + p_("Component", "string", c) +
                            "\n" + p_("Quantity", "string", q), 0)
                      for n, k, s, c, q in (
                          ("axle vx", "Body", "axle box", "x", "velocity"),
                          ("rim ux", "Node set", "wheel.rim point", "x", "displacement"),
                          ("rim behind vx", "Node set", "wheel.rim behind", "x", "velocity"),
                          ("rim behind vz", "Node set", "wheel.rim behind", "z", "velocity"),
                          ("rim behind ux", "Node set", "wheel.rim behind", "x", "displacement"))]
    # The preload is steady in the axle's frame: its deformation starts moving with the rolling
    # (the convected start), not at rest under a wheel that already rolls.
    roll = [p_("Module", "string", "explicit"), p_("Start from", "string", "preload"),
            p_("Preload frame velocity", "Array(double)", fmt([SPEED, 0, 0])),
            p_("End time", "double", f"{p['end_time']:g}"),
            p_("Gravity", "Array(double)", "{0, 0, -9.81}")]
    if p["mass_scaling"]:
        roll.append(p_("Mass scaling step", "double", f"{p['mass_scaling']:g}"))
    roll += [
        block("Initial velocity", block("wheel", "\n".join([
            p_("Node set", "string", "wheel.all"),
            p_("Translation", "Array(double)", fmt([SPEED, 0, 0])),
            p_("Angular velocity", "Array(double)", fmt([0, spin, 0])),
            p_("Axis point", "Array(double)", fmt([x0, 0, place["axis_height"]]))]), 0), 0),
        block("Prescribed motion", ends(held_xy) + held_sleepers, 0),
        block("Discrete parts", "\n".join([
            block("Rigid bodies", "\n".join(bodies), 0),
            block("Springs", "\n".join(springs), 0)] + ([
            block("Moments", block("driving torque", "\n".join([
                p_("Body", "string", "axle box"),
                p_("Moment", "Array(double)", fmt([0, p.get("torque", TORQUE), 0])),
                p_("Function", "string", f"min(t / {p['ramp']:g}, 1)")]), 0), 0)]
            if p.get("torque", TORQUE) else [])), 0),
        block("Contact pairs", block("wheel-rail", "\n".join([contact_common] + (
            [p_("Mass scaling step", "double", f"{p['contact_mass_scaling']:g}")]
            if p.get("contact_mass_scaling") else []) + [
            p_("Damping fraction", "double", "0.1"), friction(case),
            p_("Patch times", "Array(double)", fmt(
                [t for t in p["patch_times"] if t <= p["end_time"]] or [p["end_time"]]))]), 0),
            0),
    ]
    if p.get("checkpoint"):
        roll.append(block("Checkpoint", "\n".join([
            p_("Interval", "int", str(p["checkpoint"])), p_("Restart", "bool", "true")]), 0))
    roll += [
        block("Output", "\n".join([
            p_("Energy interval", "int", "100"), p_("History interval", "int", "10"),
            block("Histories", "\n".join(histories), 0)]), 0)]
    steps = [block("modes", wheel_modes(x0, place["axis_height"]), 0)] if p.get("modes") else []
    steps += [block("preload", preload, 0), block("roll", "\n".join(roll), 0)]
    L.append(block("Steps", "\n".join(steps), 2))
    L.append("</ParameterList>")
    return header(case, p, seats, zone, arc, motion) + "\n".join(L) + "\n"


def header(case, p, seats, zone, arc, motion):
    what = {1: "no lateral motion", 2: "small lateral motion", 3: "medium lateral motion",
            4: "large lateral motion", 5: "medium lateral motion with falling friction"}[case]
    law = ("velocity-dependent friction mu = 0.32 + 0.18 exp(-6 s/m |v_slip|)" if case == 5
           else "Coulomb friction mu 0.45")
    lateral = (f"from {p['lateral_start'] * 1e3:g} ms the axle box moves sideways (towards the "
               f"flange, +y), its speed ramped over {p['lateral_ramp'] * 1e3:g} ms to "
               f"{LATERAL_CREEPAGE[case] * SPEED * 1e3:.4g} mm/s (rigid lateral creepage "
               f"{LATERAL_CREEPAGE[case] * 100:g} %)" if motion else
               "the axle box held sideways")
    name = "squeal_demo" if p is DEMO else f"squeal_case{case}"
    return f"""<!--
  Squeal rolling scene (Yang & Li 2019), case {case}: {what}, {law}. {p['title'].capitalize()}.
  Written by regression/scenes/make_squeal_decks.py: change the script, not this file.

  Model: {tread_text(p)} with half its axle rolls at 100 km/h on a {p['rail_length']:g} m 54E1
  rail from its EN 13674-1 drawing, {rail_text(p)}. Rail: {p['zone_size'] * 1e3:g} mm elements over the solution zone x = {zone[0]:.3f}-{zone[1]:.3f} m, graded to
  {p['rail_size'] * 1e3:g} mm; wheel: {p['arc_size'] * 1e3:g} mm over the arc {arc[0]:.1f}-{arc[1]:.1f} deg that rolls through the zone,{approach_text(p, arc)}{transitions_text(p)}
  {p['tread_size'] * 1e3:g} mm at the tread, {p['wheel_size'] * 1e3:g} mm elsewhere. Track: rail seats at {SLEEPER_SPACING:g} m
  ({len(seats)}), each on a pad ({PAD['vertical'] / 1e6:g} MN/m, {PAD['damping'] / 1e3:g} kN s/m; shear {PAD['shear'] / 1e6:g} MN/m) and ballast ({BALLAST['vertical'] / 1e6:g} MN/m,
  {BALLAST['damping'] / 1e3:g} kN s/m) {sleeper_text(p)};
  rail ends held sideways and along. Car body and bogie: {SPRUNG_MASS:g} kg on the primary
  suspension (1.15 MN/m, 2.5 kN s/m) over the axle box, a rigid body carrying the axle's end.
  {modes_text(p)}Step "preload": statics under gravity, the sprung weight and the wheel's centrifugal load at
  the rolling speed ({preload_support_text(p)}), the wheel pressed into the rail
  (frictionless): wheel load 111 kN. Only the tread faces that roll over the rail are searched.{penalty_text(p)}
  Step "roll": explicit from the preload, wheel at 100 km/h and omega = V / {geometry(p)['rolling_radius']} m;{element_scaling_text(p)}
  {torque_text(p)};
  {lateral}; {law}; {p['end_time'] * 1e3:g} ms.
  Run:      railfe inputs/scenes/{name}.xml      (mpirun -np 2 ... for two ranks){checkpoint_text(p)}
  Look at:  roll_contact_wheel-rail.csv (forces), roll_contact_wheel-rail_patch_*.png (patches),
            roll_histories.csv (rim velocity, axle box), roll.exo (ParaView).
  Charts:   python3 regression/charts/contact_force_history.py DIR/roll_contact_wheel-rail.csv{trust_text(case, p)}
-->
"""


def tread_text(p):
    if p.get("tread") == "cylinder":
        return "a cylindrical tread (920 mm, S1002's flange; the steady check's control)"
    return "an S1002 wheel (920 mm)"


def rail_text(p):
    if p.get("tread") == "cylinder":
        return "upright, its centre under the running circle"
    return "inclined 1:40, its centre 2.5 mm outboard of the running\n  circle"


def trust_text(case, p):
    """What survives a change of step and penalty, for the case where the method is known to
    fail (falling friction at full scale: squeal_case5_full_stability.py)."""
    if case != 5 or p is DEMO:
        return ""
    return ("\n  Trust:    the forces (to 0.4 % at half the step and a quarter of the penalty), their"
            "\n            content below 5 kHz, stick at the leading edge and where the slip lies;"
            "\n            not the creep force above 40 kHz (penalty-friction chatter) nor single"
            "\n            nodes' slip speeds (docs/verification.md, Case 5 at full scale).")


def checkpoint_text(p):
    if not p.get("checkpoint"):
        return ""
    return (f"\n            A checkpoint every {p['checkpoint']:,} steps: after an interruption the same "
            f"command,\n            on the same number of ranks, resumes the roll from it.")


def approach_text(p, arc):
    approach = approach_arc(p, arc)
    if not approach:
        return ""
    return (f"\n  {p['approach_size'] * 1e3:g} mm over the approach {approach[0]:.1f}-{arc[0]:.1f} "
            f"deg rolled before it,")


def penalty_text(p):
    if p.get("penalty_stiffness", "bulk modulus") == "bulk modulus":
        return ""
    scaling = p.get("contact_mass_scaling")
    return (f"\n  Contact: penalty factor {p.get('penalty', 1):g} on the softer of wheel node and "
            "rail face (its step stays near\n  the solids'); the summary reports how much its "
            "springs soften the creep forces." + (
                f"\n  Its nodes are made heavier until its step is {scaling * 1e9:g} ns (Mass "
                "scaling step; the summary reports the\n  mass added)." if scaling else ""))


def element_scaling_text(p):
    if not p.get("mass_scaling_note"):  # a safety net that scales nothing: not worth a line
        return ""
    return (f"\n  elements whose step is below {p['mass_scaling'] * 1e9:g} ns made heavier (Mass "
            "scaling step; the summary reports the mass\n  added);")


def transitions_text(p):
    if not p.get("transitions"):
        return ""
    radii = " and ".join(f"{r * 1e3:g}" for r in p["transitions"])
    return (f"\n  its slices coarsening threefold below r = {radii} mm (Transition radii: the "
            f"hub and axle\n  keep the step that the arc's slices would cut to a tenth),")


def torque_text(p):
    torque = p.get("torque", TORQUE)
    if not torque:
        return "no driving torque (free rolling)"
    if torque == TORQUE:
        return (f"driving torque {TORQUE / 1e3:g} kN m ramped over {p['ramp'] * 1e3:g} ms "
                f"(traction coefficient about 0.27)")
    return f"driving torque {torque / 1e3:g} kN m ramped over {p['ramp'] * 1e3:g} ms"


def modes_text(p):
    if not p.get("modes"):
        return ""
    return ("Step \"modes\": the wheel and half axle alone, clamped at the axle end, every mode\n"
            "  from 20 to 2500 Hz (the rim spectra's peaks are matched to them).\n  ")


def sleeper_text(p):
    if p.get("sleepers", "springs") == "springs":
        return "in series to the ground (sleeper mass left out: the run starts in balance)"
    if p["sleepers"] == "solids":
        lx, ly, lz = SLEEPER_BOX["lengths"]
        return (f"below a sleeper, a concrete solid of {math.prod(SLEEPER_BOX['elements'])} hex8\n"
                f"  ({lx:g} x {ly:g} x {lz:g} m, its bottom held sideways and along)")
    return (f"in series to the ground (sleepers as {SLEEPER_MASS:g} kg point masses held sideways "
            f"and along)")


def preload_support_text(p):
    if p.get("sleepers") == "solids":
        return "the pads and ballast of the explicit step, stiffness only"
    return "pad and ballast in series"


def shipped():
    decks = {f"squeal_case{c}.xml": deck(c, FULL) for c in range(1, 6)}
    decks["squeal_demo.xml"] = deck(3, DEMO)
    decks["cylindrical_tread.prw"] = cylinder_profile_text()  # in inputs/profiles
    return decks


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--case", type=int, choices=range(1, 6))
    parser.add_argument("--scale", choices=("full", "demo"), default="full")
    parser.add_argument("--output")
    parser.add_argument("--sleepers", choices=("springs", "bodies", "solids"))
    parser.add_argument("--modes", action="store_true", default=None,
                        help="add the wheel's modal step (the full-scale decks have it)")
    parser.add_argument("--kinematics", action="store_true", default=None,
                        help="also record a second rim point, behind the axle, the rim points' "
                             "displacements along x and the axle box's speed (the creepage is "
                             "measured from them)")
    parser.add_argument("--torque", type=float,
                        help="driving torque (N m; 0: none, free rolling)")
    parser.add_argument("--zone-end", type=float,
                        help="the rail's solution zone ends this far ahead of the wheel's start "
                             "(m; the refined arc follows; demo 0.05, full 0.54)")
    parser.add_argument("--zone-start", type=float,
                        help="the rail's solution zone starts this far ahead of the wheel's "
                             "start (m; demo -0.005, full 0.39)")
    parser.add_argument("--transitions", type=float, nargs="*",
                        help="the wheel's Transition radii (m; none: uniform slices through "
                             "hub and axle; full 0.30 0.12)")
    parser.add_argument("--hold-creepage", type=float,
                        help="the steady-state check: the axle box carries hub and web at the "
                             "rolling speed and spins them at (1 + this) x free rolling, with no "
                             "torque (give --torque 0 too)")
    parser.add_argument("--hold-radius", type=float,
                        help="with --hold-creepage: the axle box carries the wheel inside this "
                             "radius (m; default 0.385, the rim's inner surface is at 0.395)")
    parser.add_argument("--penalty", type=float,
                        help="the contact's Penalty factor in the roll step (default 1)")
    parser.add_argument("--penalty-stiffness", choices=["bulk modulus",
                                                        "bulk modulus, softer side"],
                        help="the contact's Penalty stiffness (default: the deck's default, "
                             "bulk modulus)")
    parser.add_argument("--contact-mass-scaling", type=float,
                        help="the contact pair's Mass scaling step in the roll step (s; 0: "
                             "none; demo 3.4e-7)")
    parser.add_argument("--patch-times", type=float, nargs="+",
                        help="times at which the contact patch is written (s)")
    for key in ("zone_size", "head_size", "tread_size", "arc_size", "approach_size",
                "rail_length", "end_time",
                "mass_scaling", "start_x"):
        parser.add_argument("--" + key.replace("_", "-"), type=float)
    parser.add_argument("--section-size", type=float,
                        help="the rail section's element size away from its running surface "
                             "(m; demo 0.02, full 0.01): how finely the head is meshed below the "
                             "20 mm the head size grades over")
    parser.add_argument("--wheel-size", type=float,
                        help="the wheel's element size away from its tread (m; demo 0.06, "
                             "full 0.03): the same for the rim")
    parser.add_argument("--tread", choices=sorted(TREADS),
                        help="the wheel's tread: S1002 on the rail inclined 1:40 (default), or "
                             "the steady check's control, a cylinder on the rail upright "
                             "(inputs/profiles/cylindrical_tread.prw)")
    args = parser.parse_args()
    if args.hold_radius is not None and (args.hold_creepage is None or args.hold_radius <= 0):
        parser.error("--hold-radius needs --hold-creepage and a radius > 0 (m)")
    variant = sorted(k for k, v in vars(args).items()
                     if v is not None and k not in ("check", "case", "scale"))
    if not args.case and variant:  # the shipped decks take none of them
        parser.error("--" + ", --".join(k.replace("_", "-") for k in variant) +
                     ": a study variant's options; give --case too")
    if args.case:
        p = dict(FULL if args.scale == "full" else DEMO)
        for key in list(p) + ["sleepers", "modes", "torque", "kinematics", "approach_size",
                              "transitions", "penalty", "penalty_stiffness",
                              "contact_mass_scaling", "hold_creepage", "hold_radius", "tread"]:
            value = getattr(args, key, None)
            if value is not None:
                p[key] = value
        if args.zone_end is not None:
            p["zone"] = (p["zone"][0], args.zone_end)
        if args.zone_start is not None:
            p["zone"] = (args.zone_start, p["zone"][1])
        text = deck(args.case, p)
        open(args.output, "w").write(text) if args.output else sys.stdout.write(text)
        return 0
    stale = []
    for name, text in shipped().items():
        path = CYLINDER_PROFILE if name == "cylindrical_tread.prw" else os.path.join(SCENES, name)
        if args.check:
            if not os.path.exists(path) or open(path).read() != text:
                stale.append(name)
        else:
            open(path, "w").write(text)
    if stale:
        print("out of date (run regression/scenes/make_squeal_decks.py): " + ", ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
