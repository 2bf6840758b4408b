#pragma once
/// \file
/// A point mass with rotary inertia on a 6-DOF node: the 6 × 6 mass matrix, optionally with the
/// centre of mass away from the node (small rotations).

#include "physics/elements/element_frame.hpp"

namespace railfe {

/// Mass matrix (6 × 6, global axes) of \p mass (kg) with inertia tensor \p inertia (kg m²,
/// global axes, about the centre of mass) whose centre lies at \p offset from the node:
/// Tᵀ diag(m I, J) T with T = rigid_link_matrix(offset), which is [m I, −m[r]×; m[r]×,
/// J − m [r]×²] (parallel axes). Throws std::invalid_argument for a negative mass or an
/// inertia that is not symmetric positive semi-definite.
Matrix6 point_mass_matrix(double mass, const Eigen::Matrix3d& inertia,
                          const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

/// Global components Rᵀ J R of an inertia tensor \p local given in the frame \p axes (rows the
/// local axes; checked with check_rotation()).
Eigen::Matrix3d inertia_to_global(const Eigen::Matrix3d& local, const Eigen::Matrix3d& axes);

}  // namespace railfe
