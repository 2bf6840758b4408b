#pragma once
/// \file
/// The "vehicle dynamics" module: a vehicle from the mesh (beams, point masses, spring–dampers
/// and rigid links; the vehicle mesh generator builds the usual car body, two bogies and four
/// wheelsets) running on rigid rails at constant speed, each wheelset node carrying the
/// implicit wheel–rail contact element at the tread and flange of both wheels; dense HHT-α from
/// the static balance, the internal nodes eliminated on the rails
/// (framework/solvers/prescribed_saddle_point_solver.hpp).

#include "framework/app/module.hpp"

namespace railfe {

/// The module's descriptor for the registry.
ModuleDescriptor vehicle_dynamics_module();

}  // namespace railfe
