#pragma once
/// \file
/// The modal module: natural frequencies and mass-normalized mode shapes of hex8 solids,
/// K φ = ω² M φ, by block Krylov–Schur on the shift-inverted problem (Anasazi), with every
/// returned pair checked and, for bodies of revolution, classified as wheel modes are named.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor modal_module();

}  // namespace railfe
