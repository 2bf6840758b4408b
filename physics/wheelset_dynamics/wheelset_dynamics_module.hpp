#pragma once
/// \file
/// The "wheelset dynamics" module: one rigid wheelset on its axle-box suspension running on two
/// rigid rails at constant speed, with the implicit wheel–rail contact element
/// (contact/enforcement/wheel_rail_contact.hpp) at the tread and flange of each wheel, internal
/// nodes tied to the rails by Lagrange multipliers, HHT-α in time from the static balance. It
/// is the element's proving ground: kinematic oscillation (Klingel), critical speed (Wickens),
/// flange contact; vehicles on flexible track use the same element in the implicit module.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor wheelset_dynamics_module();

}  // namespace railfe
