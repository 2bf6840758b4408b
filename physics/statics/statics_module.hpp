#pragma once
/// \file
/// The statics module: linear elastostatics of hex8 solids under gravity, surface loads and nodal
/// forces, with prescribed displacements and tied node sets. Writes displacement, reaction and
/// stress fields, probe and reaction CSVs, and leaves the displacement in the model
/// ("displacement") so a later step can start from static equilibrium.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's registration record.
ModuleDescriptor statics_module();

}  // namespace railfe
