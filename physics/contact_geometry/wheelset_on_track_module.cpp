#include "physics/contact_geometry/wheelset_on_track_module.hpp"

#include "physics/contact_geometry/wheelset_on_track_step.hpp"

namespace railfe {

namespace {

ParameterSpec profile_parameters() {
  ParameterSpec spec("Profile files and their checks.");
  spec.text("Rail", "",
            "Rail profile, right rail, y to the field side, z down (SIMPACK .prr, MiniProf .ban "
            "or two-column text in mm), relative to the deck; empty = the Manchester "
            "benchmark's 60E1 (canted 1:40).");
  spec.text("Wheel", "",
            "Wheel profile, y from the running point towards the flange, z radially outwards "
            "(SIMPACK .prw, MiniProf .whl or two-column text in mm); empty = the benchmark's "
            "S1002.");
  spec.flag("Wheel mirrored", false,
            "The wheel file's y runs towards the field side (as many measured profiles, from the "
            "flange back, list it).");
  spec.real("Wheel running point", 0,
            "The wheel file's y of the running point (the nominal rolling radius), before "
            "mirroring.",
            "m");
  spec.flag("Rail mirrored", false, "The rail file's y runs towards the gauge side.");
  spec.flag("Rail canted", true,
            "The rail profile is already drawn at the track's inclination (as the benchmark's "
            "is); false rotates it by Track/Inclination.");
  spec.integer("Smoothing passes", 0,
               "[1 2 1]/4 filter passes on z before the zig-zag and kink checks (measured "
               "profiles).",
               Range::at_least(0));
  spec.real("Kink angle", 20, "One turn of the point list sharper than this is refused.", "degree",
            Range::open(0.0, 180.0));
  spec.real("Zig-zag angle", 10,
            "Two opposite turns in a row both sharper than this are refused (noise).", "degree",
            Range::open(0.0, 180.0));
  return spec;
}

ParameterSpec track_parameters() {
  ParameterSpec spec("Track and wheelset dimensions.");
  // Ranges span the world's gauges (600 mm to 1676 mm) and wheels (tram to locomotive), so
  // a value in the wrong unit is refused here rather than failing the contact search later.
  spec.real("Gauge", 1.435, "Between the rails' gauge points.", "m", Range::closed(0.5, 2.0));
  spec.real("Gauge point depth", 0.014, "Depth of the gauge point below the top of rail.", "m",
            Range::closed(0.001, 0.05));
  spec.real("Inclination", 1.0 / 40, "Rail cant, tan of the angle towards the track centre.", "",
            Range::closed(0.0, 0.2));
  spec.real("Back to back", 1.360, "Between the wheels' flange back faces; within 0.2 m of Gauge.",
            "m", Range::closed(0.4, 1.9));
  spec.real("Flange back", 0.070, "The wheel profile's y of the flange back face.", "m",
            Range::closed(0.0, 0.2));
  spec.real("Nominal radius", 0.46, "Rolling radius at the wheel profile's y = 0.", "m",
            Range::closed(0.1, 1.0));
  return spec;
}

ParameterSpec pose_parameters() {
  ParameterSpec spec("A wheelset position relative to the centred one.");
  spec.required_real("Lateral shift", "Wheelset centre's shift to the right.", "m",
                     Range::closed(-0.05, 0.05));
  spec.real("Yaw", 0, "Rotation about the vertical (the axle's right end forward).", "rad",
            Range::closed(-0.1, 0.1));
  spec.flag("Rigid", true,
            "Solve the vertical position and roll so both wheels just touch; false uses Vertical "
            "and Roll as given (gaps and penetrations are reported).");
  spec.real("Vertical", 0, "Wheelset centre's shift down (Rigid false).", "m",
            Range::closed(-0.05, 0.05));
  spec.real("Roll", 0,
            "Rotation about the track axis, positive lowers the right wheel (Rigid "
            "false).",
            "rad", Range::closed(-0.1, 0.1));
  return spec;
}

ParameterSpec wheelset_on_track_parameters() {
  ParameterSpec spec(
      "Rigid wheel-rail contact geometry: contact points for a list of poses, the contact "
      "table, rolling radius difference and equivalent conicity.");
  spec.sublist("Profiles", profile_parameters(), "Profile files.");
  spec.sublist("Track", track_parameters(), "Track and wheelset.");
  spec.named_sublists(
      "Poses", pose_parameters(),
      "Wheelset poses: each row of <step>_contacts.csv is one contact (or search) of "
      "one wheel in one pose.");
  spec.real("Table half range", 0.015, "The table covers lateral shifts -range to +range.", "m",
            Range::closed_open(1e-4, 0.05));
  spec.real("Table resolution", 1e-4, "Step between the table's shifts.", "m",
            Range::closed(1e-6, 1e-3));
  spec.integer("Check samples", 100,
               "Per row and part, sampled points that look for a lower gap minimum than the one "
               "tracked (contact jumps); 0 = none.",
               Range::at_least(0));
  spec.real_array("Conicity amplitudes", {0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.007, 0.008},
                  "Amplitudes of the kinematic motion for the equivalent conicity (EN 15302); "
                  "at most Table half range.",
                  "m", 0, Range::positive());
  spec.choice(
      "Conicity method", "kinematic wavelength",
      {{"kinematic wavelength",
        "EN 15302 Annex B: the wavelength of the nonlinear kinematic motion, integrated "
        "over one period"},
       {"linear regression",
        "EN 15302 Annex C: least-squares line through dr over a harmonic motion"}},
      "Which route gives equivalent_conicity and the summary; <step>_conicity.csv lists both.");
  spec.real("Vertical load", 0,
            "Per wheelset, downwards: the poses are also solved elastically (Hertzian patches, "
            "<step>_elastic_contacts.csv); 0 = rigid geometry only.",
            "N", Range::closed(0.0, 1e7));
  spec.real("Young's modulus", 210e9, "Of wheel and rail (elastic poses).", "Pa",
            Range::closed(1e9, 1e13));
  spec.real("Poisson's ratio", 0.28, "Of wheel and rail (elastic poses).", "",
            Range::closed_open(0.0, 0.5));
  spec.flag("Chart", true,
            "Draw <step>_geometry.png: profiles with contact points, rolling radius difference and "
            "contact angles against the shift (needs python3 with matplotlib).");
  return spec;
}

}  // namespace

ModuleDescriptor wheelset_on_track_module() {
  ModuleDescriptor module;
  module.name = "wheelset on track";
  module.summary = "rigid wheel-rail contact geometry, contact table and equivalent conicity";
  module.parameters = wheelset_on_track_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<WheelsetOnTrackStep>(parameters);
  };
  module.needs_mesh = false;
  return module;
}

}  // namespace railfe
