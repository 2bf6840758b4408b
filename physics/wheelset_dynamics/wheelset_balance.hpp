#pragma once
/// \file
/// The static balance of a wheelset on its rails: the vertical position and roll at which the
/// Hertz forces of both wheels carry the weight and the axle load, the lateral position and
/// yaw held where the deck puts them. Dynamics starts from it, so the run starts quiet.

#include <vector>

#include "physics/wheelset_dynamics/wheelset_system.hpp"

namespace railfe {

/// How the balance ended.
struct WheelsetBalance {
  int iterations = 0;   ///< Newton iterations
  double residual = 0;  ///< |vertical and roll residual| at the end (N, N m)
  double weight = 0;    ///< the load carried (N)
};

/// Moves u[2] (vertical) and u[3] (roll) of \p u, whose other entries hold the pose and the
/// internal nodes' rail offsets, until the contact forces balance the external ones (creep
/// forces off). Starts from the rigid contact of the profiles. Throws RunError when the
/// wheelset cannot be placed (no contact found) or Newton fails.
WheelsetBalance balance_wheelset(WheelsetSystem& system, const WheelRailGeometry& geometry,
                                 std::vector<double>& u);

}  // namespace railfe
