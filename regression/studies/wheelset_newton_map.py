#!/usr/bin/python3
"""Where the implicit wheel-rail contact fails: an S1002 wheelset on 60E1 (the deck of
wheelset_speed_accuracy.py, creep-force table) runs over a 12 m cosine lateral irregularity of both rails, for a
grid of speeds and amplitudes, with four settings of the method:
  default       lookup table (jump prediction, narrowed search), trust-region search,
                Newton with line search
  no table      every part searched whole, no jump prediction
  plain search  the contact-point search without its trust region
  plain Newton  Newton without line search
Each run either finishes or stops with its reason (Newton, contact search, other); the map shows
which, with the flange contacts, the peak Y/Q and the most Newton iterations in a step.

Usage: wheelset_newton_map.py RAILFE [--out DIR] [--quick]
Writes DIR/wheelset_newton_map.csv and .png (default docs/img).
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile

from wheelset_speed_accuracy import deck as study_deck

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


SETTINGS = {
    "default": dict(table="true", search="trust-region", line_search="true"),
    "no table": dict(table="false", search="trust-region", line_search="true"),
    "plain search": dict(table="true", search="plain Newton", line_search="true"),
    "plain Newton": dict(table="true", search="trust-region", line_search="false"),
}


def run(railfe, work, setting, speed, amplitude):
    name = "%s_%g_%g" % (setting.replace(" ", "_"), speed, amplitude)
    deck = os.path.join(work, name + ".xml")
    with open(deck, "w") as f:
        f.write(study_deck(speed=speed, amplitude=amplitude, end=30.0 / speed,
                           **SETTINGS[setting]))
    out = os.path.join(work, name)
    done = subprocess.run([railfe, deck, "--output", out, "--quiet"], capture_output=True,
                          text=True)
    row = dict(setting=setting, speed=speed, amplitude=amplitude, status="ok", reason="",
               flange_contacts=0, peak_y_over_q=float("nan"), most_iterations=float("nan"))
    if done.returncode != 0:
        message = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "?"
        row["status"] = ("newton" if "Newton did not converge" in message else
                         "search" if "contact search" in message else "other")
        row["reason"] = message[:200]
    suffix = "" if done.returncode == 0 else ".part"
    events = os.path.join(out, "run_contact_events.csv" + suffix)
    if os.path.exists(events):
        row["flange_contacts"] = sum(1 for r in csv.DictReader(open(events))
                                     if r["event"] == "flange contact")
    contacts = os.path.join(out, "run_contacts.csv" + suffix)
    if os.path.exists(contacts):
        peak = 0.0
        for r in csv.DictReader(open(contacts)):
            peak = max(peak, abs(float(r["right_Y_over_Q"])), abs(float(r["left_Y_over_Q"])))
        row["peak_y_over_q"] = peak
    if done.returncode == 0:
        summary = json.load(open(os.path.join(out, "summary.json")))
        section = next(v for k, v in summary.items() if "wheelset dynamics" in k)
        row["most_iterations"] = section["most Newton iterations in a step"]
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("railfe")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "img"))
    parser.add_argument("--quick", action="store_true", help="a 2 x 3 grid")
    parser.add_argument("--replot", action="store_true",
                        help="draw the chart from DIR/wheelset_newton_map.csv without running")
    args = parser.parse_args()
    if args.replot:
        rows = [dict(setting=r["setting"], speed=float(r["speed_m_per_s"]),
                     amplitude=float(r["amplitude_m"]), status=r["status"],
                     flange_contacts=int(r["flange_contacts"]),
                     peak_y_over_q=float(r["peak_Y_over_Q"]))
                for r in csv.DictReader(open(os.path.join(args.out, "wheelset_newton_map.csv")))]
        chart(rows, args.out)
        return
    speeds = [20, 40] if args.quick else [10, 20, 30, 40, 50]
    amplitudes = [0.004, 0.010, 0.016] if args.quick else [0.002, 0.004, 0.006, 0.008, 0.010,
                                                           0.012, 0.014, 0.016]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for setting in SETTINGS:
            for speed in speeds:
                for amplitude in amplitudes:
                    rows.append(run(args.railfe, work, setting, speed, amplitude))
                    r = rows[-1]
                    print("%-12s %2g m/s %4.1f mm: %-6s flange %3d, Y/Q %.2f, iterations %s %s"
                          % (setting, speed, 1e3 * amplitude, r["status"],
                             r["flange_contacts"], r["peak_y_over_q"], r["most_iterations"],
                             r["reason"][:80]))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "wheelset_newton_map.csv"), "w") as f:
        writer = csv.writer(f)
        writer.writerow(["setting", "speed_m_per_s", "amplitude_m", "status", "flange_contacts",
                         "peak_Y_over_Q", "most_newton_iterations", "reason"])
        for r in rows:
            writer.writerow([r["setting"], r["speed"], r["amplitude"], r["status"],
                             r["flange_contacts"], "%.4g" % r["peak_y_over_q"],
                             r["most_iterations"], r["reason"]])
    chart(rows, args.out)


def chart(rows, out):
    """The map, one panel per setting."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(SETTINGS), figsize=(4 * len(SETTINGS), 4.2), sharey=True)
    style = {"ok": ("o", "C2"), "newton": ("X", "C3"), "search": ("s", "C4"),
             "other": ("D", "k")}
    for ax, setting in zip(axes, SETTINGS):
        for r in (r for r in rows if r["setting"] == setting):
            marker, colour = style[r["status"]]
            face = colour if r["status"] != "ok" or r["flange_contacts"] else "none"
            ax.plot(1e3 * r["amplitude"], r["speed"], marker, color=colour, mfc=face, ms=10)
            if r["status"] == "ok" and r["peak_y_over_q"] == r["peak_y_over_q"]:
                ax.annotate("%.2f" % r["peak_y_over_q"], (1e3 * r["amplitude"], r["speed"]),
                            fontsize=6, xytext=(0, 7), textcoords="offset points", ha="center")
        ax.set_title(setting, fontsize=10)
        ax.set_xlabel("lateral irregularity amplitude (mm)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("speed (m/s)")
    handles = [plt.Line2D([], [], ls="", marker="o", color="C2", mfc="none",
                          label="finished, tread only"),
               plt.Line2D([], [], ls="", marker="o", color="C2", label="finished, flange contact"),
               plt.Line2D([], [], ls="", marker="X", color="C3", label="stopped: Newton"),
               plt.Line2D([], [], ls="", marker="s", color="C4", label="stopped: contact search"),
               plt.Line2D([], [], ls="", marker="D", color="k", label="stopped: other")]
    fig.legend(handles=handles, fontsize=8, loc="lower center", ncol=5)
    fig.suptitle("S1002 wheelset over a 12 m lateral irregularity, dt = 1 ms: where each setting "
                 "fails (numbers: peak Y/Q)", fontsize=10)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(os.path.join(out, "wheelset_newton_map.png"), dpi=120)


if __name__ == "__main__":
    main()
