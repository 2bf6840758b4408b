#include "physics/elements/point_mass.hpp"

#include <algorithm>
#include <stdexcept>

#include "physics/elements/rigid_link.hpp"

namespace railfe {

Matrix6 point_mass_matrix(double mass, const Eigen::Matrix3d& inertia,
                          const Eigen::Vector3d& offset) {
  if (!(mass >= 0))
    throw std::invalid_argument("a point mass must not be negative");
  const double scale = std::max(1.0, inertia.norm());
  if (!((inertia - inertia.transpose()).norm() <= 1e-12 * scale) ||
      !(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues().minCoeff() >=
        -1e-12 * scale))
    throw std::invalid_argument(
        "a point mass's inertia tensor must be symmetric positive semi-definite");
  Matrix6 centre = Matrix6::Zero();
  centre.topLeftCorner<3, 3>() = mass * Eigen::Matrix3d::Identity();
  centre.bottomRightCorner<3, 3>() = inertia;
  const Matrix6 t = rigid_link_matrix(offset);
  return t.transpose() * centre * t;
}

Eigen::Matrix3d inertia_to_global(const Eigen::Matrix3d& local, const Eigen::Matrix3d& axes) {
  check_rotation(axes);
  return axes.transpose() * local * axes;
}

}  // namespace railfe
