#pragma once
/// \file
/// The "contact patch" module: one wheel-rail contact patch (Hertz geometry, normal load,
/// materials, creepages, friction) evaluated by several theories side by side: Kalker's linear
/// theory, Shen-Hedrick-Elkins, FASTSIM and the exact steady-rolling solver. Forces, maximum
/// pressure, patch size and evaluation time per theory and case; traction fields and maps. The
/// cases give the creepages, or the forces (the exact solver then finds the creepages: the
/// inverse problem, contact_patch_inverse.hpp). No mesh.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor contact_patch_module();

}  // namespace railfe
