#pragma once
/// \file
/// Rigid links, linearized: a slave point at offset r from a 6-DOF master node moves with the
/// master's small rotation, u_s = u_m + θ_m × r (and θ_s = θ_m for a 6-DOF slave). The
/// equations come as coefficients on the master's components, one equation per slave component,
/// in the shape of framework/assembly/linear_constraints.hpp's MultipointConstraint (slave DOF,
/// (master DOF, coefficient) pairs, offset 0) once the DOF map names the global DOFs.

#include <utility>
#include <vector>

#include "physics/elements/element_frame.hpp"

namespace railfe {

/// The 3 × 6 matrix C with u_s = C (u_m, θ_m): [I, −[r]×], [r]× the cross-product matrix of
/// \p offset (r = x_slave − x_master, m).
Eigen::Matrix<double, 3, 6> rigid_link_translation(const Eigen::Vector3d& offset);

/// The 6 × 6 matrix that moves a 6-DOF master's motion to a point at \p offset:
/// (u_s, θ_s) = T (u_m, θ_m), T = [I, −[r]×; 0, I]. Also moves loads back: f_m = Tᵀ f_s.
Matrix6 rigid_link_matrix(const Eigen::Vector3d& offset);

/// One linear constraint of a rigid link: slave component = Σ coefficient · master component.
struct RigidLinkEquation {
  int slave_component = 0;                      ///< 0..2 translations, 3..5 rotations
  std::vector<std::pair<int, double>> masters;  ///< (master component 0..5, coefficient ≠ 0)
};

/// The equations of a slave at \p offset from its master: \p slave_components = 3 (a solid
/// node: translations only) or 6 (a beam or body node: rotations too). Zero coefficients are
/// left out (a component of r that is exactly zero). Throws std::invalid_argument for another
/// \p slave_components.
std::vector<RigidLinkEquation> rigid_link_equations(const Eigen::Vector3d& offset,
                                                    int slave_components);

}  // namespace railfe
