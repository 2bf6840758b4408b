#pragma once
/// \file
/// The static balance of a vehicle on rigid rails: every wheelset placed on its rails, then the
/// vertical-plane unknowns moved until the Hertz forces and the suspensions carry the weight.
/// What the balance moves: the bodies' lateral and vertical positions, roll and pitch, and the
/// wheelsets' vertical position and roll; longitudinal positions, yaw, the wheelsets' spin and
/// their lateral positions stay where the deck puts them (nothing but creep holds them, and
/// there is none at rest). Dynamics starts from it, so the run starts quiet.

#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "physics/wheelset_dynamics/vehicle_system.hpp"

namespace railfe {

/// How the balance ended.
struct VehicleBalance {
  int iterations = 0;   ///< Newton iterations
  double residual = 0;  ///< largest force or moment residual at the end (N, N m)
  double weight = 0;    ///< the vehicle's weight (N)
};

/// Balances \p system at \p u, whose internal nodes already hold their rails' offsets (see the
/// file comment), with the creep forces off. Throws RunError when a wheelset cannot be placed
/// (no rigid contact at its lateral position) or Newton fails.
VehicleBalance balance_vehicle(VehicleSystem& system, const WheelRailGeometry& geometry,
                               std::vector<double>& u);

}  // namespace railfe
