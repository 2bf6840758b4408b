#pragma once
/// \file
/// The "wheelset on track" module: rigid wheel-rail contact geometry of a wheelset on a
/// straight track (contact/geometry) for a list of poses, the rigid contact table over a range
/// of lateral shifts, the rolling radius difference and the equivalent conicity (EN 15302).
/// It needs no mesh.

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor wheelset_on_track_module();

}  // namespace railfe
