#!/usr/bin/env python3
"""Where explicit penalty contact is stable, where it blows up and where it is stable but wrong
(issue 15, "Stability where the method fails"): the Hertz line contact of
inputs/verification/contact_hertz_cylinder (a steel half-cylinder, R = 0.1 m, pressed on a steel
block by P' = 4e6 N/m in plane strain, force ramped over 0.3 ms and held to 0.6 ms with Rayleigh
mass damping, the contact zone mass-scaled 16 x) on a coarse mesh, contact-zone elements
h = 0.25 mm (inputs/meshes/hertz_cylinder.geo with -setnumber h 0.25e-3; b/h = 8.4; --size for
another), one-point elements (the module's default), bulk-modulus penalty, swept over
  penalty factor f      0.1 ... 100
  fixed Time step dt    r = dt / dt_c = 0.5 ... 2, dt_c = 2 sqrt(m_r / k) the contact's
                        critical step that railfe reports (one automatic probe run per f),
                        and, where the solids' stable step dt_s is the smaller, dt = 0.6 and
                        0.9 dt_s
with Allow unstable step true and the energy balance checked every 50 steps. Each run with dt
above railfe's stable limit (the smaller of the solids' and the contact's) is also run without
Allow unstable step and must be refused naming what sets the limit. Each run is classed as
  stable       completed, max |energy_error| < 0.05, contact force at the end within 2 % of
               P' t, largest penetration below 15 % of delta_b = b^2 / (2 R);
  wrong        completed but one of those fails: penetration (the penalty's Winkler layer:
               g / delta_b = E* h / (2 f K b), the lambda of docs/verification.md's Hertz
               convergence, where p0 errs by about -0.4 % - 0.34 lambda, so 15 % is about 5 %
               low in p0), contact force, or energy (chatter);
  blew up      stopped with exit 2 and 'growing without bound' (detected);
  undetected   completed with |energy_error| >= 0.5 or a non-finite result and no warning that the
               energy balance did not close (must never happen);
  other        anything else.
b = sqrt(4 P' R / (pi E*)) = 2.10093 mm, so delta_b = 22.07 um, the separation of the undeformed
profiles at the patch edge: the part of the Hertz approach that shapes the pressure (the whole
2-D approach also holds a logarithm of the bodies' size and is not defined for half-spaces).

    /usr/bin/python3 regression/studies/contact_stability_map.py [build/bin/railfe]
        [--work DIR] [--jobs N] [--replot]

Writes docs/data/contact_stability_map.csv and docs/img/contact_stability_map.png (the map:
penalty factor against dt / dt_c). About 6 minutes with --jobs 2 on 2 free cores.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.lines  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from explicit_stability import run_explicit  # noqa: E402
from railfe_runs import csv_rows  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "inputs", "verification", "contact_hertz_cylinder", "deck.xml")
GEO = os.path.join(ROOT, "inputs", "meshes", "hertz_cylinder.geo")
CSV = os.path.join(ROOT, "docs", "data", "contact_stability_map.csv")
PNG = os.path.join(ROOT, "docs", "img", "contact_stability_map.png")

SIZE = 0.25e-3  # m, contact-zone elements (the coarsest of the Hertz convergence study)
FACTORS = [0.1, 0.3, 1, 3, 10, 30, 100]
RATIOS = [0.5, 0.6, 0.7, 0.75, 0.8, 0.85, 0.9, 1.0, 1.1, 1.5, 2.0]
SOLID_FRACTIONS = [0.6, 0.9]
PAIR = "hertz"

YOUNG, POISSON, RADIUS = 210e9, 0.3, 0.1
LOAD = 4e6 * 1e-3  # N on the 1 mm slice
E_STAR = YOUNG / (2 * (1 - POISSON**2))
B_HERTZ = math.sqrt(4 * 4e6 * RADIUS / (math.pi * E_STAR))
DELTA_B = B_HERTZ**2 / (2 * RADIUS)
PENETRATION_LIMIT = 0.15  # of DELTA_B
FORCE_LIMIT = 0.02
ENERGY_LIMIT = 0.05
UNDETECTED_ERROR = 0.5


def mesh_file(work, size):
    path = os.path.join(work, f"hertz_cylinder_h{size * 1e3:g}mm.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "h", repr(size), "-o",
                        path, GEO], check=True, capture_output=True)
    return path


def deck_text(mesh, factor, time_step=None, allow=True, end_time=None):
    """The case's deck on `mesh` with penalty factor `factor`, one-point elements, the energy
    checked every 50 steps; a fixed `time_step` (with Allow unstable step `allow`) or the
    automatic step at safety 0.6 (the case's); `end_time` if given."""
    text = re.sub(r"<!--.*?-->\s*", "", open(DECK).read(), flags=re.S)
    swaps = [('value="../../meshes/hertz_cylinder.msh"', f'value="{mesh}"'),
             ('name="Penalty factor" type="double" value="1"',
              f'name="Penalty factor" type="double" value="{factor!r}"'),
             ('name="Integration" type="string" value="full"',
              'name="Integration" type="string" value="one point"'),
             ('name="Energy interval" type="int" value="500"',
              'name="Energy interval" type="int" value="50"'),
             ('name="History interval" type="int" value="500"',
              'name="History interval" type="int" value="50"')]
    if time_step is not None:
        swaps.append(('<Parameter name="Safety factor" type="double" value="0.6"/>',
                      f'<Parameter name="Time step" type="double" value="{time_step!r}"/>' +
                      ('<Parameter name="Allow unstable step" type="bool" value="true"/>'
                       if allow else "")))
    if end_time is not None:
        swaps.append(('name="End time" type="double" value="6e-4"',
                      f'name="End time" type="double" value="{end_time!r}"'))
        swaps.append(('name="Patch times" type="Array(double)" value="{6e-4}"',
                      f'name="Patch times" type="Array(double)" value="{{{end_time!r}}}"'))
    for old, new in swaps:
        assert old in text, old
        text = text.replace(old, new)
    return text


def probe(railfe, mesh, factor, work):
    """One automatic step of the model: (solids' stable step, contact critical step) in s."""
    run = run_explicit(railfe, work, f"probe_f{factor:g}", deck_text(mesh, factor, end_time=2e-7),
                       "press")
    section = run["section"]
    if not section:
        raise RuntimeError(f"probe f {factor:g} failed: {run['message']}")
    return section["solids' stable step at end [s]"], section["contact critical step [s]"]


def classify(run):
    """(outcome, reason) of a run with Allow unstable step (see the module docstring)."""
    code, message = run["exit"], run["message"]
    if code == 2 and "growing without bound" in message:
        return "blew up", ""
    if code != 0:
        return "other", message
    errors = [abs(float(r["energy_error"])) for r in run["energy"]]
    warned = "energy balance did not close" in message
    if not all(math.isfinite(e) for e in errors) or (max(errors) >= UNDETECTED_ERROR and
                                                     not warned):
        return "undetected", f"energy error {max(errors):.3g}"
    contact = csv_rows(os.path.join(run["results"], "press_contact_hertz.csv"))
    penetration = max(float(r["max_penetration_m"]) for r in contact)
    force = float(contact[-1]["normal_force_N"]) / LOAD - 1
    reasons = []
    if penetration > PENETRATION_LIMIT * DELTA_B:
        reasons.append(f"penetration {penetration / DELTA_B:.0%} of delta_b")
    if abs(force) > FORCE_LIMIT:
        reasons.append(f"force {force:+.1%}")
    if max(errors) >= ENERGY_LIMIT:
        reasons.append(f"energy error {max(errors):.2g}" + (" (warned)" if warned else ""))
    return ("wrong" if reasons else "stable"), "; ".join(reasons)


def measure(railfe, mesh, work, factor, ratio, solid_step, contact_step):
    """Runs one (f, r) point; returns its CSV row."""
    dt = ratio * contact_step
    limit = min(solid_step, contact_step)
    name = f"f{factor:g}_r{ratio:.4g}"
    run = run_explicit(railfe, work, name, deck_text(mesh, factor, dt), "press")
    outcome, reason = classify(run)
    row = {"penalty_factor": factor, "step_over_contact_critical": ratio, "time_step_s": dt,
           "contact_critical_step_s": contact_step, "solid_stable_step_s": solid_step,
           "step_over_stable_limit": dt / limit, "outcome": outcome, "reason": reason,
           "exit_status": run["exit"], "steps": "", "max_penetration_over_delta_b": "",
           "force_error": "", "max_abs_energy_error": "", "names_pair": "", "refusal": "",
           "message": run["message"].replace(",", ";")}
    found = re.search(r"\(step (\d+)\)", run["message"])
    row["steps"] = int(found.group(1)) if found else run["section"].get("steps", "")
    if run["energy"]:
        row["max_abs_energy_error"] = max(abs(float(r["energy_error"])) for r in run["energy"])
    if run["exit"] == 0:
        contact = csv_rows(os.path.join(run["results"], "press_contact_hertz.csv"))
        row["max_penetration_over_delta_b"] = max(
            float(r["max_penetration_m"]) for r in contact) / DELTA_B
        row["force_error"] = float(contact[-1]["normal_force_N"]) / LOAD - 1
    if outcome == "blew up":
        row["names_pair"] = f"contact pair '{PAIR}'" in run["message"]
    if dt > limit * (1 + 1e-9):
        # Without the override the same deck must be refused before the first step.
        refused = run_explicit(railfe, work, name + "_refused", deck_text(mesh, factor, dt, False),
                               "press")
        setter = f"contact pair '{PAIR}'" if contact_step <= solid_step else "element"
        ok = (refused["exit"] == 2 and "above the stable limit" in refused["message"] and
              f"set by {setter}" in refused["message"])
        row["refusal"] = "refused" if ok else "NOT REFUSED: " + refused["message"][:200]
    print(f"f {factor:g} r {ratio:g}: {outcome} {reason} {row['refusal']}", flush=True)
    return row


def write_csv(rows):
    os.makedirs(os.path.dirname(CSV), exist_ok=True)
    with open(CSV, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


STYLES = {"stable": ("o", "tab:green", "stable"),
          "wrong": ("^", "tab:orange", "stable but wrong (penetration > 15 % of b²/2R, force "
                    "off P′t by > 2 %, or energy error > 5 %)"),
          "blew up": ("x", "tab:red", "blew up: detected and stopped"),
          "undetected": ("s", "magenta", "diverged undetected"),
          "other": ("d", "k", "other failure")}


def plot(rows):
    fig, ax = plt.subplots(figsize=(9, 7))
    for outcome, (marker, colour, _) in STYLES.items():
        points = [(float(r["step_over_contact_critical"]), float(r["penalty_factor"]))
                  for r in rows if r["outcome"] == outcome]
        if points:
            ax.scatter(*zip(*points), marker=marker, color=colour, s=60, zorder=3)
    # The solids' limit in these coordinates: dt_s / dt_c(f), dt_c proportional to 1/sqrt(f).
    by_factor = {}
    for r in rows:
        by_factor[float(r["penalty_factor"])] = (float(r["solid_stable_step_s"]) /
                                                 float(r["contact_critical_step_s"]))
    factors = sorted(by_factor)
    ax.plot([by_factor[f] for f in factors], factors, "-", color="tab:blue", lw=1.5)
    ax.axvline(1.0, color="k", lw=1.2, ls="--")
    # The observed limit: per f the largest stable-or-wrong ratio below the first blow-up.
    limits = []
    for f in factors:
        runs = sorted((r for r in rows if float(r["penalty_factor"]) == f),
                      key=lambda r: float(r["step_over_contact_critical"]))
        last_ok = None
        for r in runs:
            if r["outcome"] == "blew up":
                break
            last_ok = float(r["step_over_contact_critical"])
        if last_ok is not None:
            limits.append((last_ok, f))
    if limits:
        ax.plot(*zip(*limits), ":", color="tab:green", lw=1.5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks([0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0])
    ax.get_xaxis().set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.get_yaxis().set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.set_xlim(0.08, 2.3)
    ax.set_ylim(0.07, 150)
    ax.set_xlabel("fixed step / contact critical step  dt / [2√(m_r/k)(√(1+ζ²) − ζ)]")
    ax.set_ylabel("penalty factor f (bulk-modulus form, k = f K A²/V)")
    ax.set_title("Explicit penalty contact, Hertz cylinder at h = 0.25 mm: stability map")
    ax.grid(True, which="both", alpha=0.3)
    handles = [matplotlib.lines.Line2D([], [], marker=m, color=c, ls="", label=label)
               for outcome, (m, c, label) in STYLES.items()
               if any(r["outcome"] == outcome for r in rows)]
    handles += [matplotlib.lines.Line2D([], [], color="k", ls="--",
                                        label="contact critical step, damped (railfe's limit)"),
                matplotlib.lines.Line2D([], [], color="tab:blue",
                                        label="solids' stable step (railfe's limit)"),
                matplotlib.lines.Line2D([], [], color="tab:green", ls=":",
                                        label="largest step that did not blow up")]
    fig.legend(handles=handles, fontsize=8, loc="lower center", ncol=2, frameon=False)
    fig.tight_layout(rect=(0, 0.16, 1, 1))
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("railfe", nargs="?", default=os.path.join(ROOT, "build", "bin", "railfe"))
    parser.add_argument("--work", default="/tmp/contact_stability_map")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--replot", action="store_true")
    parser.add_argument("--size", type=float, default=SIZE, help="contact-zone element size (m)")
    parser.add_argument("--only", type=float, nargs="+", default=None,
                        help="run these penalty factors only and replace their rows in the CSV")
    args = parser.parse_args()
    if args.replot:
        plot(csv_rows(CSV))
        return 0
    railfe = os.path.abspath(args.railfe)
    os.makedirs(args.work, exist_ok=True)
    mesh = mesh_file(args.work, args.size)
    factors = args.only or FACTORS
    steps = {f: probe(railfe, mesh, f, args.work) for f in factors}
    for f, (solid, contact) in steps.items():
        print(f"f {f:g}: solids' step {solid:.4g} s, contact critical step {contact:.4g} s")
    # Where the solids set the limit (small f) the ratios above lie beyond it: add 0.6 and 0.9 of
    # the solids' step (0.6 is the case's safety factor).
    points = [(f, r) for f in factors for r in RATIOS]
    points += [(f, s * steps[f][0] / steps[f][1]) for f in factors for s in SOLID_FRACTIONS
               if steps[f][0] < steps[f][1]]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(lambda p: measure(railfe, mesh, args.work, p[0], p[1], *steps[p[0]]),
                             points))
    if args.only:
        kept = [r for r in csv_rows(CSV) if float(r["penalty_factor"]) not in factors]
        rows = sorted(kept + rows, key=lambda r: (float(r["penalty_factor"]),
                                                  float(r["step_over_contact_critical"])))
    write_csv(rows)
    plot(csv_rows(CSV))
    bad = [r for r in rows if r["outcome"] in ("undetected", "other") or
           r["refusal"].startswith("NOT") or r["names_pair"] in (False, "False") and
           float(r["step_over_contact_critical"]) > 1 and
           float(r["contact_critical_step_s"]) <= float(r["solid_stable_step_s"])]
    for r in bad:
        print("PROBLEM:", r)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
