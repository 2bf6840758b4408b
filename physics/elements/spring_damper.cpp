#include "physics/elements/spring_damper.hpp"

#include <stdexcept>

namespace railfe {

void check_spring_damper(const SpringDamper& spring) {
  for (int i = 0; i < 6; ++i)
    if (!(spring.stiffness[i] >= 0) || !(spring.damping[i] >= 0))
      throw std::invalid_argument("spring-damper stiffness and damping must not be negative");
  check_rotation(spring.axes);
}

Matrix6 spring_block(const std::array<double, 6>& values, const Eigen::Matrix3d& axes) {
  const Matrix6 local = Vector6(Eigen::Map<const Vector6>(values.data())).asDiagonal();
  return to_global<6>(local, axes);
}

Matrix12 two_node_matrix(const Matrix6& block) {
  Matrix12 m;
  m << block, -block, -block, block;
  return m;
}

Vector6 spring_local_force(const SpringDamper& spring, const Vector6& relative_u,
                           const Vector6& relative_v) {
  const Vector6 du = to_local<6>(relative_u, spring.axes);
  const Vector6 dv = to_local<6>(relative_v, spring.axes);
  const Eigen::Map<const Vector6> k(spring.stiffness.data()), c(spring.damping.data());
  return k.cwiseProduct(du) + c.cwiseProduct(dv);
}

Vector12 spring_internal_force(const SpringDamper& spring, const Vector12& u, const Vector12& v) {
  const Vector6 local =
      spring_local_force(spring, u.tail<6>() - u.head<6>(), v.tail<6>() - v.head<6>());
  const Vector6 on_b = to_global<6>(local, spring.axes);  // the force that holds b against a
  Vector12 f;
  for (int i = 0; i < 6; ++i) {  // element-wise: GCC 12 warns falsely on Eigen's AVX-512 copy
    f(i) = -on_b(i);
    f(i + 6) = on_b(i);
  }
  return f;
}

Vector6 ground_spring_internal_force(const SpringDamper& spring, const Vector6& u,
                                     const Vector6& v) {
  return to_global<6>(spring_local_force(spring, u, v), spring.axes);
}

Eigen::Vector3d spring_translational_force(const SpringDamper& spring,
                                           const Eigen::Vector3d& stretch,
                                           const Eigen::Vector3d& rate) {
  const Eigen::Map<const Eigen::Vector3d> k(spring.stiffness.data()), c(spring.damping.data());
  const Eigen::Vector3d local =
      k.cwiseProduct(spring.axes * stretch) + c.cwiseProduct(spring.axes * rate);
  return spring.axes.transpose() * local;
}

double spring_translational_energy(const SpringDamper& spring, const Eigen::Vector3d& stretch) {
  const Eigen::Map<const Eigen::Vector3d> k(spring.stiffness.data());
  const Eigen::Vector3d local = spring.axes * stretch;
  return 0.5 * local.dot(k.cwiseProduct(local));
}

double spring_translational_power(const SpringDamper& spring, const Eigen::Vector3d& rate) {
  const Eigen::Map<const Eigen::Vector3d> c(spring.damping.data());
  const Eigen::Vector3d local = spring.axes * rate;
  return local.dot(c.cwiseProduct(local));
}

}  // namespace railfe
