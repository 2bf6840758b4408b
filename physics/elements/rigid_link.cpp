#include "physics/elements/rigid_link.hpp"

#include <stdexcept>

namespace railfe {

Eigen::Matrix<double, 3, 6> rigid_link_translation(const Eigen::Vector3d& offset) {
  Eigen::Matrix3d cross;                // [r]×, so that [r]× a = r × a
  cross << 0, -offset.z(), offset.y(),  //
      offset.z(), 0, -offset.x(),       //
      -offset.y(), offset.x(), 0;
  Eigen::Matrix<double, 3, 6> c;
  c << Eigen::Matrix3d::Identity(), -cross;  // θ × r = −r × θ
  return c;
}

Matrix6 rigid_link_matrix(const Eigen::Vector3d& offset) {
  Matrix6 t = Matrix6::Identity();
  t.topRows<3>() = rigid_link_translation(offset);
  return t;
}

std::vector<RigidLinkEquation> rigid_link_equations(const Eigen::Vector3d& offset,
                                                    int slave_components) {
  if (slave_components != 3 && slave_components != 6)
    throw std::invalid_argument("a rigid link's slave has 3 or 6 components");
  const Matrix6 t = rigid_link_matrix(offset);
  std::vector<RigidLinkEquation> equations(slave_components);
  for (int i = 0; i < slave_components; ++i) {
    equations[i].slave_component = i;
    for (int j = 0; j < 6; ++j)
      if (t(i, j) != 0)
        equations[i].masters.emplace_back(j, t(i, j));
  }
  return equations;
}

}  // namespace railfe
