#include "physics/wheelset_dynamics/wheelset_dynamics_module.hpp"

#include "physics/common/profile_geometry.hpp"
#include "physics/wheelset_dynamics/time_stepping.hpp"
#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"
#include "physics/wheelset_dynamics/wheelset_dynamics_step.hpp"
#include "physics/wheelset_dynamics/wheelset_track.hpp"

namespace railfe {

namespace {

ParameterSpec wheelset_parameters() {
  ParameterSpec spec("The rigid wheelset.");
  spec.real("Mass", 1500, "m.", "kg", Range::positive());
  spec.real("Roll inertia", 800, "About the track's x axis.", "kg m^2", Range::positive());
  spec.real("Spin inertia", 100, "About the axle.", "kg m^2", Range::positive());
  spec.real("Yaw inertia", 800, "About the vertical.", "kg m^2", Range::positive());
  spec.real("Axle load", 0,
            "Vertical force on the axle boxes besides the wheelset's weight (the share of bogie "
            "and car body).",
            "N", Range::non_negative());
  spec.real("Gravity", 9.81, "g.", "m/s^2", Range::non_negative());
  spec.real("Cant", 0,
            "Cant of the track, positive with the left rail raised: the weight and the axle load "
            "(vertical in the world) get a share sin(cant) along the track's y, to the right.",
            "rad", Range::closed(-0.15, 0.15));
  return spec;
}

ParameterSpec suspension_parameters() {
  ParameterSpec spec("Springs and dampers of each axle box to a frame running at Speed.");
  spec.real_array("Stiffness", {0, 0, 0}, "Per axle box along x, y, z.", "N/m", 3,
                  Range::non_negative());
  spec.real_array("Damping", {0, 0, 0}, "Per axle box along x, y, z.", "N s/m", 3,
                  Range::non_negative());
  spec.real("Half spacing", 1.0, "Lateral distance of each axle box from the centre.", "m",
            Range::positive());
  spec.real("Frame yaw", 0,
            "Yaw of the running frame: the springs hold the wheelset at this angle of attack "
            "(positive turns the axle's right end back, steering the right wheel into its rail).",
            "rad", Range::closed(-0.1, 0.1));
  return spec;
}

ParameterSpec wheelset_dynamics_parameters() {
  ParameterSpec spec(
      "A rigid wheelset on its suspension running on rigid rails or rail beams on seats: Hertz "
      "normal contact, creep "
      "forces and online contact search at tread and flange of each wheel, contact forces as "
      "Lagrange multipliers, HHT-alpha from the static balance.");
  spec.sublist("Profiles", profile_parameters(), "Profile files.");
  spec.sublist("Track", track_parameters(), "Track and wheelset dimensions.");
  spec.sublist("Wheelset", wheelset_parameters(), "Mass and loads.");
  spec.sublist("Suspension", suspension_parameters(), "Primary suspension.");
  spec.sublist("Contact", contact_parameters(), "The contact element.");
  spec.sublist("Rails", track_rail_parameters(), "Rigid rails, or a beam per rail on rail seats.");
  spec.real("Start", 0, "Position along the track at t = 0 (the irregularities' s).", "m");
  add_time_stepping_parameters(
      spec,
      "HHT alpha in [-1/3, 0] (beta = (1-alpha)^2/4, gamma = (1-2 alpha)/2). The default "
      "damps the internal nodes' and the Hertz springs' highest modes, which the rails' "
      "irregularities drive step to step; 0 (the average-acceleration rule, no numerical "
      "damping) can leave Newton stalled there (docs/theory.md).",
      false);
  spec.real("Initial lateral shift", 0, "Wheelset's lateral displacement at t = 0 (right).", "m");
  spec.real("Initial yaw", 0, "Wheelset's yaw at t = 0.", "rad");
  spec.real("Initial lateral velocity", 0, "Wheelset's lateral velocity at t = 0.", "m/s");
  add_irregularity_parameters(spec);
  spec.text(
      "Lateral force", "",
      "Lateral force on the wheelset centre (N, to the right) as a function of time t (s), "
      "e.g. '100e3*t/2' for a slow push ('' = none); the static balance is taken without it.");
  spec.flag("Chart", true,
            "Draw <step>_chart.png (shift, yaw, wheel forces and Y/Q against time) from the "
            "histories.");
  return spec;
}

}  // namespace

ModuleDescriptor wheelset_dynamics_module() {
  ModuleDescriptor module;
  module.name = "wheelset dynamics";
  module.summary =
      "A rigid wheelset on rigid rails or rail beams with the implicit wheel-rail contact element "
      "(Hertz, "
      "creep forces, online search, Lagrange multipliers), HHT-alpha from the static balance.";
  module.parameters = wheelset_dynamics_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<WheelsetDynamicsStep>(parameters);
  };
  module.needs_mesh = false;
  return module;
}

}  // namespace railfe
