#pragma once
/// \file
/// Matrix types and local frames of the structural elements (beams, spring–dampers, point
/// masses, rigid links). A node of these elements carries six DOFs in the order
/// u_x, u_y, u_z, θ_x, θ_y, θ_z (small rotations, right-handed); a two-node element's vectors
/// are node-major (node a's six, then node b's). A frame is a rotation matrix whose rows are the
/// local x, y, z axes in global components, so that v_local = axes · v_global.

#include <stdexcept>

#include <Eigen/Dense>

namespace railfe {

/// 6 × 6 matrix of one 6-DOF node.
using Matrix6 = Eigen::Matrix<double, 6, 6>;
/// Vector of one 6-DOF node.
using Vector6 = Eigen::Matrix<double, 6, 1>;
/// 12 × 12 matrix of a two-node element.
using Matrix12 = Eigen::Matrix<double, 12, 12>;
/// Vector of a two-node element.
using Vector12 = Eigen::Matrix<double, 12, 1>;

/// Local axes of a beam from \p a to \p b: x along b − a, y the part of \p orientation normal
/// to x, z = x × y (rows of the returned matrix). Throws std::invalid_argument when a and b
/// coincide or when \p orientation is zero or parallel to the beam (its part normal to x must
/// exceed 1e-6 |orientation|).
Eigen::Matrix3d beam_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& orientation);

/// Checks that \p axes is a proper rotation (orthonormal rows, determinant +1) within 1e-9;
/// throws std::invalid_argument otherwise. For frames given by users (spring–dampers, inertia).
void check_rotation(const Eigen::Matrix3d& axes);

/// Global components of a matrix given in local components: Tᵀ A T with T the block diagonal
/// of N / 3 copies of \p axes (N = 6 for one node, 12 for two).
template <int N>
Eigen::Matrix<double, N, N> to_global(const Eigen::Matrix<double, N, N>& local,
                                      const Eigen::Matrix3d& axes) {
  static_assert(N % 3 == 0, "blocks of three");
  Eigen::Matrix<double, N, N> result;
  for (int i = 0; i < N; i += 3)
    for (int j = 0; j < N; j += 3)
      result.template block<3, 3>(i, j) =
          axes.transpose() * local.template block<3, 3>(i, j) * axes;
  return result;
}

/// Local components of a vector given in global components: T v (see to_global()).
template <int N>
Eigen::Matrix<double, N, 1> to_local(const Eigen::Matrix<double, N, 1>& global,
                                     const Eigen::Matrix3d& axes) {
  static_assert(N % 3 == 0, "blocks of three");
  Eigen::Matrix<double, N, 1> result;
  for (int i = 0; i < N; i += 3)
    result.template segment<3>(i) = axes * global.template segment<3>(i);
  return result;
}

/// Global components of a vector given in local components: Tᵀ v (see to_global()).
template <int N>
Eigen::Matrix<double, N, 1> to_global(const Eigen::Matrix<double, N, 1>& local,
                                      const Eigen::Matrix3d& axes) {
  return to_local<N>(local, Eigen::Matrix3d(axes.transpose()));
}

}  // namespace railfe
