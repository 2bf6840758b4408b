#!/usr/bin/python3
"""Speed against accuracy of the implicit wheel-rail contact element: an S1002 wheelset on 60E1
rails (100 kN axle load, axle-box springs 10/5 MN/m, lateral dampers 20 kN s/m) runs at
30 m/s over a 4 mm, 12 m cosine lateral irregularity of both rails. For each creep theory
(table, linear, Shen-Hedrick-Elkins, Polach, FASTSIM), with yaw neglected in the contact search
(the seed's choice) or exact, and for the table at three time steps, the run gives the peak
lateral wheel-rail force |Y| and the peak lateral wheelset displacement; their errors against
the reference (table, exact yaw, dt = 0.25 ms) are charted against wall time.

Usage: wheelset_speed_accuracy.py RAILFE [--out DIR]
Writes DIR/wheelset_speed_accuracy.csv and .png (default docs/img).
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))

DECK = """<ParameterList name="railfe">
  <ParameterList name="Steps">
    <ParameterList name="run">
      <Parameter name="Module" type="string" value="wheelset dynamics"/>
      <ParameterList name="Wheelset">
        <Parameter name="Axle load" type="double" value="100e3"/>
      </ParameterList>
      <ParameterList name="Suspension">
        <Parameter name="Stiffness" type="Array(double)" value="{{10e6, 5e6, 0}}"/>
        <Parameter name="Damping" type="Array(double)" value="{{0, 20e3, 0}}"/>
        <Parameter name="Half spacing" type="double" value="1.0"/>
      </ParameterList>
      <ParameterList name="Contact">
        <Parameter name="Creep theory" type="string" value="{theory}"/>
        <Parameter name="Yaw" type="string" value="{yaw}"/>
        <Parameter name="Lookup table" type="bool" value="{table}"/>
        <Parameter name="Search" type="string" value="{search}"/>
      </ParameterList>
      <Parameter name="Line search" type="bool" value="{line_search}"/>
      <Parameter name="Alpha" type="double" value="-0.05"/>
      <Parameter name="Speed" type="double" value="{speed}"/>
      <Parameter name="Lateral irregularity" type="string"
                 value="{amplitude}*(1-cos(2*_pi*(x-6)/12))/2*(x&gt;6)*(x&lt;18)"/>
      <Parameter name="End time" type="double" value="{end}"/>
      <Parameter name="Time step" type="double" value="{step}"/>
      <Parameter name="Chart" type="bool" value="false"/>
      <Parameter name="History interval" type="double" value="0"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def deck(theory="table", yaw="neglected", step=0.001, speed=30, amplitude=0.004, end=1.0,
         table="true", search="trust-region", line_search="true"):
    """The study's deck (also wheelset_newton_map.py's) with the settings given."""
    return DECK.format(theory=theory, yaw=yaw, step=step, speed=speed, amplitude=amplitude,
                       end=end, table=table, search=search, line_search=line_search)


def run(railfe, work, theory, yaw, step):
    name = "%s_%s_%g" % (theory, yaw, step)
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(deck(theory, yaw, step))
    out = os.path.join(work, name)
    subprocess.run([railfe, path, "--output", out, "--quiet"], check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    section = next(v for k, v in summary.items() if "wheelset dynamics" in k)
    peak_force = peak_shift = 0.0
    for row in csv.DictReader(open(os.path.join(out, "run_contacts.csv"))):
        peak_force = max(peak_force, abs(float(row["right_Y_N"])), abs(float(row["left_Y_N"])))
    for row in csv.DictReader(open(os.path.join(out, "run_wheelset.csv"))):
        peak_shift = max(peak_shift, abs(float(row["y_m"])))
    return dict(theory=theory, yaw=yaw, step=step, wall=section["wall time [s]"],
                iterations=section["Newton iterations per step"], force=peak_force,
                shift=peak_shift)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("railfe")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "img"))
    args = parser.parse_args()
    cases = [("table", "exact", 0.00025)]
    cases += [(t, y, 0.001) for t in ("table", "linear", "shen-hedrick-elkins", "polach",
                                      "fastsim") for y in ("neglected", "exact")]
    cases += [("table", "neglected", 0.002), ("table", "neglected", 0.0005)]
    with tempfile.TemporaryDirectory() as work:
        rows = [run(args.railfe, work, *case) for case in cases]
    reference = rows[0]
    for r in rows:
        r["force_error"] = r["force"] / reference["force"] - 1
        r["shift_error"] = r["shift"] / reference["shift"] - 1
        print("%-20s %-9s dt %.2g ms: |Y| %.1f N (%+.3f %%), y %.4f mm (%+.3f %%), %.2f s, "
              "%.2f it/step" % (r["theory"], r["yaw"], 1e3 * r["step"], r["force"],
                                100 * r["force_error"], 1e3 * r["shift"],
                                100 * r["shift_error"], r["wall"], r["iterations"]))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "wheelset_speed_accuracy.csv"), "w") as f:
        f.write("theory,yaw,time_step_s,wall_time_s,newton_iterations_per_step,"
                "peak_lateral_force_N,peak_lateral_shift_m,force_error,shift_error\n")
        for r in rows:
            f.write("%s,%s,%g,%.6g,%.6g,%.10g,%.10g,%.6g,%.6g\n" % (
                r["theory"], r["yaw"], r["step"], r["wall"], r["iterations"], r["force"],
                r["shift"], r["force_error"], r["shift_error"]))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    markers = {"table": "o", "linear": "s", "shen-hedrick-elkins": "^", "polach": "D",
               "fastsim": "v"}
    for ax, key, label in ((axes[0], "force_error", "peak lateral force |Y|"),
                           (axes[1], "shift_error", "peak lateral wheelset shift")):
        for r in rows[1:]:
            colour = "C0" if r["yaw"] == "neglected" else "C1"
            face = colour if r["step"] == 0.001 else "none"
            ax.plot(r["wall"], max(abs(r[key]), 1e-6) * 100, markers[r["theory"]],
                    color=colour, mfc=face, ms=7)
            if r["step"] != 0.001:
                ax.annotate("dt %g ms" % (1e3 * r["step"]), (r["wall"], abs(r[key]) * 100),
                            fontsize=7, xytext=(4, 4), textcoords="offset points")
        ax.set_xlabel("wall time of 1 s simulated (s)")
        ax.set_ylabel("|error| against table, exact yaw, dt 0.25 ms (%)")
        ax.set_yscale("log")
        ax.set_title(label, fontsize=10)
        ax.grid(alpha=0.3, which="both")
    handles = [plt.Line2D([], [], ls="", marker=m, color="gray", label=t)
               for t, m in markers.items()]
    handles += [plt.Line2D([], [], ls="", marker="o", color="C0", label="yaw neglected"),
                plt.Line2D([], [], ls="", marker="o", color="C1", label="yaw exact"),
                plt.Line2D([], [], ls="", marker="o", color="gray", mfc="none",
                           label="other time steps (table, yaw neglected)")]
    axes[1].legend(handles=handles, fontsize=7, loc="best")
    fig.suptitle("S1002 wheelset over a 4 mm lateral irregularity at 30 m/s: speed against "
                 "accuracy (1e-4 % drawn for exact agreement)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "wheelset_speed_accuracy.png"), dpi=120)


if __name__ == "__main__":
    main()
