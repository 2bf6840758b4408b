#include "physics/contact_geometry/wheelset_on_track_module.hpp"

#include "physics/common/profile_geometry.hpp"
#include "physics/contact_geometry/wheelset_on_track_step.hpp"

namespace railfe {

namespace {

ParameterSpec pose_parameters() {
  ParameterSpec spec("A wheelset position relative to the centred one.");
  spec.required_real("Lateral shift", "Wheelset centre's shift to the right.", "m",
                     Range::closed(-0.05, 0.05));
  spec.real("Yaw", 0,
            "Rotation about the vertical, z down (positive turns the axle's right end back).",
            "rad", Range::closed(-0.1, 0.1));
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
