#include "physics/elements/element_frame.hpp"

#include <algorithm>
#include <cmath>

namespace railfe {

Eigen::Matrix3d beam_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& orientation) {
  const Eigen::Vector3d axis = b - a;
  const double length = axis.norm();
  if (!(length > 1e-12 * std::max(a.norm(), b.norm())) || !(length > 0))
    throw std::invalid_argument("beam of zero length (its two nodes coincide)");
  const Eigen::Vector3d x = axis / length;
  const Eigen::Vector3d normal = orientation - orientation.dot(x) * x;
  if (!(normal.norm() > 1e-6 * orientation.norm()))
    throw std::invalid_argument(
        "beam orientation vector is zero or parallel to the beam: it must define the local y "
        "axis");
  const Eigen::Vector3d y = normal.normalized();
  Eigen::Matrix3d axes;
  axes.row(0) = x;
  axes.row(1) = y;
  axes.row(2) = x.cross(y);
  return axes;
}

void check_rotation(const Eigen::Matrix3d& axes) {
  const double error = (axes * axes.transpose() - Eigen::Matrix3d::Identity()).norm();
  if (!(error < 1e-9) || !(axes.determinant() > 0))
    throw std::invalid_argument(
        "local frame is not a rotation: its rows must be orthonormal and right-handed");
}

}  // namespace railfe
