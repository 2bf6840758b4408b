#!/usr/bin/env python3
"""Contact geometry studies on the S1002 wheel and the 60E1 rail 1:40 (Manchester benchmark
profiles), run through the railfe-contact-geometry tool:

stability   where the online search breaks. Right wheel, shifts 0 to 15 mm, in the rigid pose
            of a 0.01 mm table. Four searches per shift: plain Newton or trust region, started
            from the centred contact or from a 0.25 mm table. A search is correct when it returns
            a valid point at the table's contact (rail y within 1 nm).
resolution  speed against accuracy of the rigid contact table, for table steps from 1 mm to
            5 um: build time against the error of the linearly interpolated rolling radius
            difference (median and RMS over 15 001 shifts, against a 2 um table) and of the
            flange contact shift. The median shows the smooth stretches (second order in the
            step); the RMS is set by the contact jumps, which interpolation smears over one step.

conicity    equivalent conicity by the kinematic wavelength and by EN 15302's linear regression
            (Annex C) side by side, amplitudes 0.5 to 8 mm, through railfe's wheelset-on-track
            scene: a 1:40 cone on 300 mm crowns (the answer is the cone's slope, corrected for
            the roll of the rigid wheelset), S1002 on 60E1 1:40 (flange contact from 6.3 mm) and
            the measured worn pair (worn_high_mileage on site_b_hr).

    /usr/bin/python3 regression/studies/contact_geometry_studies.py \
        [stability|resolution|conicity|all] [build/bin/railfe-contact-geometry] [build/bin/railfe]

Writes docs/data/<study>.csv and docs/img/<study>.png.
"""
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def data_paths(name):
    """The CSV and PNG a study writes."""
    return (os.path.join(ROOT, "docs", "data", name + ".csv"),
            os.path.join(ROOT, "docs", "img", name + ".png"))


def stability_chart(tool):
    csv_path, png = data_paths("contact_search_stability")
    subprocess.run([tool, "stability", csv_path], check=True)
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    flange = min(float(r["shift_mm"]) for r in rows if r["part"] == "flange")
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True, sharey=True)
    for ax, (method, start) in zip(axes.flat, [("plain Newton", "centred"), ("plain Newton", "table"),
                                              ("trust region", "centred"), ("trust region", "table")]):
        mine = [r for r in rows if r["method"] == method and r["start"] == start]
        good = [r for r in mine if r["correct"] == "1"]
        bad = [r for r in mine if r["correct"] == "0"]
        ax.scatter([float(r["shift_mm"]) for r in good], [int(r["iterations"]) for r in good], s=6,
                   color="tab:green", label=f"correct ({len(good)})")
        for status, colour in [("part boundary", "tab:orange"), ("not converged", "tab:red"),
                               ("not a minimum", "tab:purple"), ("converged", "tab:blue")]:
            these = [r for r in bad if r["status"] == status]
            if these:
                label = "another minimum" if status == "converged" else status
                ax.scatter([float(r["shift_mm"]) for r in these], [int(r["iterations"]) for r in these],
                           s=10, marker="x", color=colour, label=f"{label} ({len(these)})")
        ax.axvline(flange, color="grey", lw=0.8, ls="--")
        ax.set_title(f"{method}, {start} start ({len(good)}/{len(mine)} correct)", fontsize=10)
        ax.set_yscale("log")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    for ax in axes[1]:
        ax.set_xlabel("lateral shift towards the right flange (mm)")
    for ax in axes[:, 0]:
        ax.set_ylabel("Newton iterations")
    fig.suptitle(f"Online contact search, S1002 on 60E1 1:40 (dashed: flange contact from {flange:.2f} mm)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


def resolution_chart(tool):
    csv_path, png = data_paths("contact_table_resolution")
    subprocess.run([tool, "resolution", csv_path], check=True)
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    time = [float(r["build_s"]) for r in rows]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for column, label, style in [("delta_r_median_error_m", "Δr, median error", "o-"),
                                 ("delta_r_rms_error_m", "Δr, RMS error (contact jumps)", "s-"),
                                 ("flange_shift_error_m", "flange contact shift error", "^-")]:
        ax.loglog(time, [max(float(r[column]), 1e-12) for r in rows], style, label=label)
    for r, t in zip(rows, time):
        ax.annotate(f"{1e3 * float(r['resolution_m']):g} mm", (t, float(r["delta_r_median_error_m"])),
                    textcoords="offset points", xytext=(4, -10), fontsize=7)
    ax.axvline(1.0, color="grey", ls="--", lw=0.8)
    ax.text(0.95, 1e-3, "issue: 1 s for\n3000 shifts ", fontsize=8, va="top", ha="right")
    ax.set_xlabel("table build time, one core (s)")
    ax.set_ylabel("error (m)")
    ax.set_title("Contact table, S1002 on 60E1 1:40, ±15 mm: build time against accuracy")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


# The pairs of the conicity study: name, Profiles parameters, Track parameters, deck-relative
# paths resolved against inputs/.
CONICITY_PAIRS = [
    ("1:40 cone on 300 mm crowns",
     {"Rail": "profiles/circ_r300.prr", "Wheel": "verification/wheelset_cone_on_crown/cone_wheel.txt"},
     {"Gauge": 1.31884813001241}),
    ("S1002 on 60E1 1:40", {}, {}),
    ("worn wheel on worn rail",
     {"Rail": "profiles/site_b_hr.prr", "Wheel": "profiles/worn_high_mileage.prw",
      "Wheel mirrored": True, "Wheel running point": 0.070, "Rail canted": False}, {}),
]
AMPLITUDES = [0.0005 * k for k in range(1, 17)]


def parameter(name, value):
    kind = "bool" if isinstance(value, bool) else "double" if isinstance(value, float) else "string"
    text = ("true" if value else "false") if isinstance(value, bool) else value
    return f'<Parameter name="{name}" type="{kind}" value="{text}"/>'


def conicity_deck(profiles, track):
    inputs = os.path.join(ROOT, "inputs")
    profile_lines = "".join(parameter(k, os.path.join(inputs, v) if k in ("Rail", "Wheel") else v)
                            for k, v in profiles.items())
    track_lines = "".join(parameter(k, v) for k, v in track.items())
    amplitudes = ", ".join(f"{a:g}" for a in AMPLITUDES)
    return f"""<ParameterList name="railfe"><ParameterList name="Steps"><ParameterList name="conicity">
  <Parameter name="Module" type="string" value="wheelset on track"/>
  <ParameterList name="Profiles">{profile_lines}</ParameterList>
  <ParameterList name="Track">{track_lines}</ParameterList>
  <Parameter name="Table half range" type="double" value="0.012"/>
  <Parameter name="Table resolution" type="double" value="1e-5"/>
  <Parameter name="Conicity amplitudes" type="Array(double)" value="{{{amplitudes}}}"/>
  <Parameter name="Conicity method" type="string" value="linear regression"/>
  <Parameter name="Chart" type="bool" value="false"/>
</ParameterList></ParameterList></ParameterList>
"""


def conicity_chart(railfe):
    csv_path, png = data_paths("conicity_methods")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for index, (name, profiles, track) in enumerate(CONICITY_PAIRS):
            deck = os.path.join(work, f"pair{index}.xml")
            with open(deck, "w") as f:
                f.write(conicity_deck(profiles, track))
            output = os.path.join(work, f"pair{index}")
            subprocess.run([railfe, deck, "--output", output, "--quiet"], check=True)
            with open(os.path.join(output, "conicity_conicity.csv")) as f:
                for r in csv.DictReader(f):
                    rows.append({"pair": name, "amplitude_m": r["amplitude_m"],
                                 "kinematic_conicity": r["kinematic_conicity"],
                                 "regression_conicity": r["regression_conicity"],
                                 "reaches_flange": r["reaches_flange"]})
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.5))
    for ax, (name, _, _) in zip(axes, CONICITY_PAIRS):
        mine = [r for r in rows if r["pair"] == name]
        amplitude = [1e3 * float(r["amplitude_m"]) for r in mine]
        # Empty where dr does not restore the wheelset (no kinematic oscillation).
        kinematic = [(a, float(r["kinematic_conicity"])) for a, r in zip(amplitude, mine)
                     if r["kinematic_conicity"]]
        ax.plot([a for a, _ in kinematic], [g for _, g in kinematic], "o-",
                label="kinematic wavelength")
        if not kinematic:
            ax.text(0.5, 0.5, "no kinematic oscillation:\nΔr does not restore (hollow tread)",
                    transform=ax.transAxes, ha="center", fontsize=8)
        ax.plot(amplitude, [float(r["regression_conicity"]) for r in mine], "s--",
                label="linear regression (EN 15302 Annex C)")
        flange = [a for a, r in zip(amplitude, mine) if r["reaches_flange"] == "1"]
        if flange:
            ax.axvspan(min(flange), max(amplitude), color="grey", alpha=0.15,
                       label="amplitude reaches the flange")
        ax.set_title(name, fontsize=10)
        ax.ticklabel_format(axis="y", useOffset=False)
        ax.set_xlabel("amplitude ŷ (mm)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("equivalent conicity tan γe")
    axes[1].legend(fontsize=8, loc="upper center")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", csv_path, png)


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "all"
    tool = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "build", "bin", "railfe-contact-geometry")
    if which in ("stability", "all"):
        stability_chart(tool)
    if which in ("resolution", "all"):
        resolution_chart(tool)
    if which in ("conicity", "all"):
        conicity_chart(sys.argv[3] if len(sys.argv) > 3 else os.path.join(ROOT, "build", "bin", "railfe"))


if __name__ == "__main__":
    main()
