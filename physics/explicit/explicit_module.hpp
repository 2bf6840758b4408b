#pragma once
/// \file
/// The explicit dynamics module: central-difference time integration of hex8 solids (one-point
/// with hourglass control, or full integration; total-Lagrangian St. Venant–Kirchhoff, objective
/// under large rotation) with lumped masses, rigid bodies, point masses and spring–dampers,
/// loads and prescribed motion as functions of time, bulk viscosity and Rayleigh mass damping.
/// The step is chosen from each element's stable step (and the springs'), a fixed step above
/// the limit is refused, and a run whose energy balance fails stops with a clear message.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor explicit_module();

}  // namespace railfe
