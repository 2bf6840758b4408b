#!/usr/bin/python3
"""Studies of the lateral train-structure interaction scene (issue 19), from its four decks
(inputs/scenes/lateral_structure_*.xml):

  models   the online model (search, creep-force table) against the offline-table model
           (DIASTARS approach: offline table, Kalker linear saturated by Shen-Hedrick-Elkins) in
           each case: where no flange touches (up to the first flange contact of either run),
           the largest difference in the car body's lateral acceleration and in the first
           wheelset's lateral displacement, against their peaks; after it, the peak Y/Q, the
           peak lateral wheel force and the flange impacts of each. Writes
           docs/data/lateral_structure_models.csv.
  steps    the BS 20 m case (online model) at dt 2, 1, 0.5 and 0.25 ms: peak lateral wheel
           force, peak Y/Q and peak and RMS car-body lateral acceleration against the wall time
           of the time steps (the speed-against-accuracy chart of the scene). Writes
           docs/data/lateral_structure_steps.csv and docs/img/lateral_structure_steps.png.

Run from the repository root: /usr/bin/python3 regression/studies/lateral_structure_studies.py
{models|steps|theories|sweep|all} [build/bin/railfe]

  theories BS 20 m at dt 1 ms with each creep theory (online search) and the offline-table model,
           against the table model at dt 0.25 ms: errors in peak lateral force and car-body
           acceleration against wall time. Writes docs/data/lateral_structure_theories.csv and
           docs/img/lateral_structure_theories.png.

  sweep    BS 20 m (online model) at 200-350 km/h and amplitudes of 8-32 mm: peak Y/Q, wheel
           unloading and car-body acceleration, or where the run stopped (Newton failed, a
           wheelset left the rails). Writes docs/data/lateral_structure_sweep.csv and
           docs/img/lateral_structure_sweep.png.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASES = ["bs20", "bs40", "ts20", "ts40"]


def deck_text(case):
    return open(os.path.join(ROOT, "inputs", "scenes", "lateral_structure_%s.xml" % case)).read()


def run(railfe, text, work, name, check=True):
    """Runs the deck \p text; returns its results directory, or None when the run failed and
    \p check is false (its FAILED.txt then says why)."""
    deck = os.path.join(work, name + ".xml")
    with open(deck, "w") as f:
        f.write(text.replace('<Parameter name="Compare with step" type="string" value="online"/>',
                             ""))
    out = os.path.join(work, name)
    done = subprocess.run([railfe, deck, "--output", out, "--quiet"], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL)
    if done.returncode != 0:
        if check:
            raise RuntimeError("railfe failed on " + deck)
        return None
    return out


def table(path):
    rows = list(csv.DictReader(open(path)))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def section(out, step):
    summary = json.load(open(os.path.join(out, "summary.json")))
    return summary["Step %s (vehicle dynamics)" % step]


def first_flange(out, step):
    w = table(os.path.join(out, step + "_wheels.csv"))
    flags = [k for k in w if k.endswith("_flange")]
    for i, t in enumerate(w["time_s"]):
        if any(w[k][i] > 0 for k in flags):
            return t
    return w["time_s"][-1]


def models(railfe, work):
    rows = []
    for case in CASES:
        out = run(railfe, deck_text(case), work, case)
        limit = min(first_flange(out, "online"), first_flange(out, "offline"))
        a = {s: table(os.path.join(out, s + "_points.csv")) for s in ("online", "offline")}
        y = {s: table(os.path.join(out, s + "_wheelsets.csv")) for s in ("online", "offline")}
        key = "floor_above_rear_bogie_ay_m_per_s2"
        before = [i for i, t in enumerate(a["online"]["time_s"]) if t < limit]
        d_ay = max(abs(a["online"][key][i] - a["offline"][key][i]) for i in before)
        peak_ay = max(abs(a["online"][key][i]) for i in before)
        d_y = max(abs(y["online"]["w1_y_m"][i] - y["offline"]["w1_y_m"][i]) for i in before)
        peak_y = max(abs(y["online"]["w1_y_m"][i]) for i in before)
        s = {m: section(out, m) for m in ("online", "offline")}
        rows.append([case.upper(), "%.3f" % limit, "%.4g" % d_ay, "%.4g" % peak_ay,
                     "%.4g" % (1e3 * d_y), "%.4g" % (1e3 * peak_y)] +
                    ["%.4g" % s[m]["peak derailment quotient Y/Q"] for m in ("online", "offline")] +
                    ["%.4g" % (s[m]["peak lateral wheel force [N]"] / 1e3)
                     for m in ("online", "offline")] +
                    ["%d" % s[m]["flange impacts"] for m in ("online", "offline")])
    path = os.path.join(ROOT, "docs", "data", "lateral_structure_models.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "first_flange_contact_s", "max_diff_car_body_ay_m_per_s2",
                    "peak_car_body_ay_m_per_s2", "max_diff_w1_y_mm", "peak_w1_y_mm",
                    "peak_Y_over_Q_online", "peak_Y_over_Q_offline", "peak_Y_kN_online",
                    "peak_Y_kN_offline", "flange_impacts_online", "flange_impacts_offline"])
        w.writerows(rows)
    for r in rows:
        print(", ".join(r))


def steps(railfe, work):
    text = deck_text("bs20")
    online = text[:text.index('    <ParameterList name="offline">')] + "  </ParameterList>\n</ParameterList>\n"
    rows, failed = [], []
    for dt in (0.002, 0.001, 0.0005, 0.00025):
        deck = online.replace('<Parameter name="Time step" type="double" value="0.001"/>',
                              '<Parameter name="Time step" type="double" value="%g"/>' % dt)
        out = run(railfe, deck, work, "dt%g" % dt, check=False)
        if out is None:
            failure = open(os.path.join(work, "dt%g" % dt, "FAILED.txt")).read()
            at = failure.split("from t = ")[1].split(" s")[0] if "from t = " in failure else "?"
            print("dt %g ms: Newton failed in the step from t = %s s" % (dt * 1e3, at))
            failed.append((dt * 1e3, at))
            continue
        s = section(out, "online")
        rows.append([dt * 1e3, s["peak lateral wheel force [N]"] / 1e3,
                     s["peak derailment quotient Y/Q"],
                     s["peak lateral acceleration at floor_above_rear_bogie [m/s^2]"],
                     s["RMS lateral acceleration at floor_above_rear_bogie [m/s^2]"],
                     s["flange impacts"], s["Newton iterations per step"],
                     s["wall time of the time steps (with their output) [s]"]])
    path = os.path.join(ROOT, "docs", "data", "lateral_structure_steps.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_step_ms", "peak_lateral_wheel_force_kN", "peak_Y_over_Q",
                    "peak_car_body_ay_m_per_s2", "rms_car_body_ay_m_per_s2", "flange_impacts",
                    "newton_iterations_per_step", "wall_time_of_time_steps_s"])
        for r in rows:
            w.writerow(["%g" % r[0]] + ["%.6g" % v for v in r[1:]])
        for dt, at in failed:  # a run that stopped: Newton did not converge there
            w.writerow(["%g" % dt, "", "", "", "", "", "", "Newton failed at t = %s s" % at])
    ref = rows[-1]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for column, label, marker in ((1, "peak lateral wheel force", "o"), (2, "peak Y/Q", "s"),
                                  (3, "peak car-body ay", "^"), (4, "RMS car-body ay", "v")):
        errors = [abs(r[column] - ref[column]) / abs(ref[column]) * 100 for r in rows[:-1]]
        axes[0].loglog([r[0] for r in rows[:-1]], [max(e, 1e-3) for e in errors], marker + "-",
                       label=label)
        axes[1].semilogx([r[7] for r in rows[:-1]], errors, marker + "-", label=label)
    axes[0].set_xlabel("time step (ms)")
    axes[0].set_ylabel("difference from dt = 0.25 ms (%)")
    axes[1].set_xlabel("wall time of the 2.5 s run (s, one core)")
    axes[1].set_ylabel("difference from dt = 0.25 ms (%)")
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    for r in rows[:-1]:
        axes[1].annotate("%g ms" % r[0], (r[7], 0), fontsize=7)
    title = "BS 20 m at 300 km/h, online model: accuracy against time step and wall time"
    for dt, at in failed:
        title += "\n(dt = %g ms: Newton failed in the step from t = %s s, the first flange impact)" % (
            dt, at)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "lateral_structure_steps.png"), dpi=110)
    for r in rows:
        print(", ".join("%.5g" % v for v in r))


def theories(railfe, work):
    """BS 20 m at dt 1 ms: each creep theory with the online search, and the offline-table model,
    against the reference (online search, creep-force table, dt 0.25 ms): error in the peak
    lateral wheel force and the car body's peak lateral acceleration against wall time."""
    text = deck_text("bs20")
    online = text[:text.index('    <ParameterList name="offline">')] + "  </ParameterList>\n</ParameterList>\n"
    table_line = '<Parameter name="Table half range" type="double" value="0.0073"/>'

    def variant(theory, geometry="online search", dt=0.001):
        deck = online.replace(table_line, table_line +
                              '<Parameter name="Creep theory" type="string" value="%s"/>'
                              '<Parameter name="Geometry" type="string" value="%s"/>' % (
                                  theory, geometry))
        return deck.replace('<Parameter name="Time step" type="double" value="0.001"/>',
                            '<Parameter name="Time step" type="double" value="%g"/>' % dt)

    def measures(out):
        s = section(out, "online")
        return (s["peak lateral wheel force [N]"] / 1e3,
                s["peak lateral acceleration at floor_above_rear_bogie [m/s^2]"],
                s["wall time of the time steps (with their output) [s]"])

    ref = measures(run(railfe, variant("table", dt=0.00025), work, "reference"))
    cases = [("table", "online search"), ("linear", "online search"),
             ("shen-hedrick-elkins", "online search"), ("polach", "online search"),
             ("fastsim", "online search"), ("shen-hedrick-elkins", "offline table")]
    rows = []
    for theory, geometry in cases:
        name = (theory + "_" + geometry).replace(" ", "_")
        out = run(railfe, variant(theory, geometry), work, name, check=False)
        if out is None:
            rows.append([theory, geometry, "", "", "", "failed"])
            continue
        force, ay, wall = measures(out)
        rows.append([theory, geometry, "%.3f" % (100 * (force - ref[0]) / ref[0]),
                     "%.3f" % (100 * (ay - ref[1]) / ref[1]), "%.4f" % wall, "ran"])
        print(rows[-1])
    path = os.path.join(ROOT, "docs", "data", "lateral_structure_theories.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["creep_theory", "geometry", "peak_lateral_force_error_percent",
                    "peak_car_body_ay_error_percent", "wall_time_of_time_steps_s", "outcome"])
        w.writerow(["table", "online search (reference, dt 0.25 ms)", "0", "0",
                    "%.4f" % ref[2], "ran"])
        w.writerows(rows)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for k, r in enumerate(r for r in rows if r[5] == "ran"):
        label = r[0] + (" (offline table)" if r[1] == "offline table" else "")
        for ax, col in ((axes[0], 2), (axes[1], 3)):
            ax.plot(float(r[4]), abs(float(r[col])), "o", color="C%d" % k, label=label)
    axes[0].set_ylabel("|error| in peak lateral wheel force (%)")
    axes[1].set_ylabel("|error| in peak car-body lateral acceleration (%)")
    for ax in axes:
        ax.set_xlabel("wall time of the 2.5 s run (s, one core, dt 1 ms)")
        ax.set_yscale("log")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle("BS 20 m at 300 km/h: creep theories and contact models against the table "
                 "model at dt 0.25 ms", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "lateral_structure_theories.png"), dpi=110)


def sweep(railfe, work):
    """BS 20 m (online model) over amplitudes and speeds: peak Y/Q and wheel unloading, or where
    the run stopped (Newton failed, or a wheelset left the rails)."""
    text = deck_text("bs20")
    online = text[:text.index('    <ParameterList name="offline">')] + "  </ParameterList>\n</ParameterList>\n"
    rows = []
    for kmh in (200, 250, 300, 350):
        for mm in (8, 12, 16, 20, 24, 32):
            deck = online.replace('<Parameter name="Amplitude" type="double" value="0.008"/>',
                                  '<Parameter name="Amplitude" type="double" value="%g"/>' % (mm / 1e3))
            deck = deck.replace('<Parameter name="Speed" type="double" value="83.33333333"/>',
                                '<Parameter name="Speed" type="double" value="%.8g"/>' % (kmh / 3.6))
            name = "v%d_a%d" % (kmh, mm)
            out = run(railfe, deck, work, name, check=False)
            if out is None:
                failure = open(os.path.join(work, name, "FAILED.txt")).read()
                at = failure.split("from t = ")[1].split(" s")[0] if "from t = " in failure else "?"
                rows.append([kmh, mm, "", "", "", "Newton failed at t = %s s" % at])
                continue
            s = section(out, "online")
            left = [k for k in s if k.endswith("left the rails at [s]")]
            outcome = ("%s at %.3f s" % (left[0].replace(" [s]", ""), s[left[0]]) if left
                       else "ran 2.5 s")
            rows.append([kmh, mm, "%.4g" % s["peak derailment quotient Y/Q"],
                         "%.4g" % s["peak wheel unloading dQ/Q"],
                         "%.4g" % s["peak lateral acceleration at floor_above_rear_bogie [m/s^2]"],
                         outcome])
            print(rows[-1])
    path = os.path.join(ROOT, "docs", "data", "lateral_structure_sweep.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["speed_km_per_h", "amplitude_mm", "peak_Y_over_Q", "peak_unloading_dQ_over_Q",
                    "peak_car_body_ay_m_per_s2", "outcome"])
        w.writerows(rows)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for k, kmh in enumerate((200, 250, 300, 350)):
        ok = [r for r in rows if r[0] == kmh and r[2] != ""]
        bad = [r for r in rows if r[0] == kmh and (r[2] == "" or "left" in r[5])]
        for ax, col in ((axes[0], 2), (axes[1], 3)):
            ax.plot([r[1] for r in ok], [float(r[col]) for r in ok], "o-", color="C%d" % k,
                    label="%d km/h" % kmh)
            for r in bad:
                ax.plot(r[1], 0, "x", color="C%d" % k, ms=10, mew=2)
    axes[0].axhline(0.8, color="k", ls=":", lw=0.8)
    axes[0].set_ylabel("peak derailment quotient Y/Q")
    axes[1].set_ylabel("peak wheel unloading ΔQ/Q")
    for ax in axes:
        ax.set_xlabel("structure deviation amplitude (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("BS 20 m, online model: safety indices against amplitude and speed "
                 "(x on the axis: the run stopped, Newton failed or a wheelset left the rails)",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "img", "lateral_structure_sweep.png"), dpi=110)


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else "all"
    railfe = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "build", "bin", "railfe")
    with tempfile.TemporaryDirectory() as work:
        if what in ("models", "all"):
            models(railfe, work)
        if what in ("steps", "all"):
            steps(railfe, work)
        if what in ("theories", "all"):
            theories(railfe, work)
        if what in ("sweep", "all"):
            sweep(railfe, work)


if __name__ == "__main__":
    main()
