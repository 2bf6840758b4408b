#include "physics/wheelset_dynamics/vehicle_dynamics_module.hpp"

#include "physics/common/profile_geometry.hpp"
#include "physics/wheelset_dynamics/time_stepping.hpp"
#include "physics/wheelset_dynamics/vehicle_dynamics_step.hpp"
#include "physics/wheelset_dynamics/vehicle_structure.hpp"
#include "physics/wheelset_dynamics/vehicle_sweep.hpp"
#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"

namespace railfe {

namespace {

ParameterSpec structure_deviation_parameters() {
  ParameterSpec spec(
      "A lateral displacement of the structure under the track (two spans), which the rails "
      "follow on their pads: added to the Lateral irregularity.");
  spec.choice("Shape", "none",
              {{"none", "no deviation"},
               {"bending", "two consecutive spans bent: the pier between them moved by Amplitude"},
               {"translation", "one span rotated from 0 to Amplitude, the next translated by it"}},
              "The structure's displacement.");
  spec.real("Start", 0, "Track position s where the first span begins.", "m");
  spec.real("Span", 20, "Span length.", "m", Range::positive());
  spec.real("Amplitude", 0.008, "Largest lateral displacement of the structure (right).", "m",
            Range::closed(-0.2, 0.2));
  spec.real("Pad stiffness", 4.6e7,
            "Lateral stiffness of the rail fastenings per metre of rail (the published 4.6e4 "
            "kN/m per m).",
            "N/m^2", Range::positive());
  spec.real("Rail lateral inertia", 509e-8,
            "The rail's second moment of area about its vertical axis (JIS 60 kg: 509 cm^4).",
            "m^4", Range::positive());
  spec.real("Rail Young's modulus", 2.1e11, "Of the rail.", "Pa", Range::positive());
  spec.only_when("Shape", {"bending", "translation"},
                 {"Start", "Span", "Amplitude", "Pad stiffness", "Rail lateral inertia",
                  "Rail Young's modulus"});
  return spec;
}

ParameterSpec vehicle_dynamics_parameters() {
  ParameterSpec spec(
      "A vehicle from the mesh (Mesh/Type vehicle, or any mesh of beams, point masses, "
      "spring-dampers and rigid links in track axes: x forward, y right, z down) on rigid rails: "
      "the implicit wheel-rail contact element at tread and flange of each wheel of every "
      "wheelset node, optionally over girders (Structure), contact forces as Lagrange multipliers, "
      "HHT-alpha from the static "
      "balance.");
  spec.sublist("Profiles", profile_parameters(), "Profile files.");
  spec.sublist("Track", track_parameters(), "Track and wheelset dimensions.");
  spec.sublist("Contact", contact_parameters(), "The contact element.");
  spec.text("Wheelsets", "wheelsets",
            "Node set of the wheelset centres (each a node of its own, not carried by a rigid "
            "link; its six motions are the wheelset's), in any order: their x coordinates place "
            "them along the track.");
  spec.text_array("Measuring points", {},
                  "Node sets whose nodes' displacements and accelerations (lateral, vertical) go "
                  "to <step>_points.csv, e.g. {floor_above_rear_bogie}.");
  spec.real("Start", 0,
            "Track position s of the mesh's x = 0 at t = 0 (a wheelset at x runs over the "
            "irregularities at s = Start + x + Speed t).",
            "m");
  add_time_stepping_parameters(
      spec,
      "HHT alpha in [-1/3, 0] (beta = (1-alpha)^2/4, gamma = (1-2 alpha)/2). 0 is the "
      "average-acceleration rule of the published runs (no numerical damping), but it "
      "leaves the contacts' internal nodes free to ring at the step's Nyquist frequency: "
      "on 1:40 cones at 52.8 m/s and 1 ms the wheelsets' lateral acceleration alternated "
      "in sign step to step, Newton needed 3, then 11 iterations and failed after 1.5 s; "
      "-0.05 damps it (2.1 iterations) and 0 with 0.5 ms steps also runs "
      "(docs/verification.md#vehicle).",
      true);
  spec.real("Gravity", 9.81, "g, along +z (down).", "m/s^2", Range::non_negative());
  add_irregularity_parameters(spec);
  spec.sublist("Structure deviation", structure_deviation_parameters(),
               "A displaced structure under the track (the published bending and translation "
               "shapes).");
  spec.sublist("Structure", vehicle_structure_parameters(),
               "What carries the track: rigid, or girders that deflect under the vehicle.");
  spec.sublist("Sweep", vehicle_sweep_parameters(),
               "Many cases of this step over speeds, spans and amplitudes, in parallel over the "
               "MPI ranks.");
  spec.real("Y/Q window", 2,
            "Track length of the sliding mean of each wheel's Y/Q reported beside its peak "
            "(UIC 518 takes 2 m): a lifted wheel's instantaneous Y/Q says little.",
            "m", Range::positive());
  spec.flag("Chart", true,
            "Draw <step>_chart.png (deviation, car body lateral acceleration at the first "
            "measuring point, the first wheelset's lateral motion and wheel forces with its "
            "flange impacts) from the histories.");
  spec.text("Compare with step", "",
            "An earlier vehicle dynamics step of this deck (another model of the same run): the "
            "chart draws its histories dashed beside this step's.");
  spec.only_when("Chart", {"true"}, {"Compare with step"});
  return spec;
}

}  // namespace

ModuleDescriptor vehicle_dynamics_module() {
  ModuleDescriptor module;
  module.name = "vehicle dynamics";
  module.summary =
      "A vehicle of the mesh on rigid rails with the implicit wheel-rail contact element at "
      "every wheelset, HHT-alpha from the static balance.";
  module.parameters = vehicle_dynamics_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<VehicleDynamicsStep>(parameters);
  };
  module.needs_mesh = true;
  return module;
}

}  // namespace railfe
