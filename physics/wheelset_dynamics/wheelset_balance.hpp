#pragma once
/// \file
/// The static balance of a wheelset on its rails: the vertical position and roll at which the
/// Hertz forces of both wheels carry the weight and the axle load, the lateral position and
/// yaw held where the deck puts them. Dynamics starts from it, so the run starts quiet.

#include <vector>

#include "framework/time/sparse_system.hpp"
#include "physics/wheelset_dynamics/rail_beams.hpp"
#include "physics/wheelset_dynamics/wheelset_system.hpp"

namespace railfe {

/// How the balance ended.
struct WheelsetBalance {
  int iterations = 0;   ///< Newton iterations
  double residual = 0;  ///< |vertical and roll residual| at the end (N, N m)
  double weight = 0;    ///< the load carried (N)
};

/// Moves u[2] (vertical) and u[3] (roll) of \p u, whose other entries hold the pose and the
/// internal nodes' rail offsets, until the contact forces balance the external ones: creep
/// forces off, or with \p rolling those of steady rolling at the system's spin. Starts from the
/// rigid contact of the profiles. Throws RunError when the wheelset cannot be placed (no contact
/// found) or Newton fails.
WheelsetBalance balance_wheelset(WheelsetSystem& system, const WheelRailGeometry& geometry,
                                 std::vector<double>& u, bool rolling = false);

/// The static balance on flexible rails, by rounds: balance_wheelset() on the rails' present
/// shape, then the rails under that balance's contact forces, until the rails under the contacts
/// move by less than 1e-13 m between rounds (a few rounds: the wheel loads hardly depend on the
/// rails' shape). With \p rolling the rails take the contact forces of steady rolling at the
/// system's spin, creep forces included (the spin creepage of a coned tread pushes each rail
/// sideways), so that rolling starts quiet; the system is left rolling. \p u holds the rails'
/// unknowns (\p structure's), then the wheelset's; \p structure is left factored for K. Throws
/// RunError as balance_wheelset() does, or when the rounds do not settle.
WheelsetBalance balance_on_rail_beams(WheelsetSystem& system, const WheelRailGeometry& geometry,
                                      BeamRails& rails, SparseLinearSystem& structure,
                                      std::vector<double>& u, bool rolling);

}  // namespace railfe
