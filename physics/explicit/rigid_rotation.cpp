#include "physics/explicit/rigid_rotation.hpp"

#include <cmath>
#include <string>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d s;
  s << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
  return s;
}

// The Cayley map (I − X/2)⁻¹ (I + X/2) of the skew matrix X of w: a rotation by 2 atan(|w|/2).
Eigen::Matrix3d cayley(const Eigen::Vector3d& w) {
  const Eigen::Matrix3d half = 0.5 * skew(w);
  return (Eigen::Matrix3d::Identity() - half).inverse() * (Eigen::Matrix3d::Identity() + half);
}

constexpr int kMaxIterations = 100;

}  // namespace

Eigen::Matrix3d rotation_of(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-300)
    return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

Eigen::Matrix3d orthonormalised(const Eigen::Matrix3d& matrix) {
  return 0.5 * matrix * (3 * Eigen::Matrix3d::Identity() - matrix.transpose() * matrix);
}

RigidRotation::RigidRotation(const Eigen::Matrix3d& inertia, const std::array<bool, 3>& locked)
    : inertia_(inertia), locked_(locked) {
  n_free_ =
      3 - static_cast<int>(locked[0]) - static_cast<int>(locked[1]) - static_cast<int>(locked[2]);
  inverse_inertia_ = Eigen::Matrix3d::Zero();
  if (n_free_ == 3)
    inverse_inertia_ = inertia.inverse();
}

Eigen::Vector3d RigidRotation::solve_free(const Eigen::Matrix3d& matrix,
                                          const Eigen::Vector3d& rhs) const {
  Eigen::Vector3d result = Eigen::Vector3d::Zero();
  if (n_free_ == 0)
    return result;
  if (n_free_ == 3)
    return matrix.ldlt().solve(rhs);
  int free[3], k = 0;
  for (int d = 0; d < 3; ++d)
    if (!locked_[d])
      free[k++] = d;
  Eigen::MatrixXd reduced(k, k);
  Eigen::VectorXd b(k);
  for (int i = 0; i < k; ++i) {
    b[i] = rhs[free[i]];
    for (int j = 0; j < k; ++j)
      reduced(i, j) = matrix(free[i], free[j]);
  }
  const Eigen::VectorXd x = reduced.ldlt().solve(b);
  for (int i = 0; i < k; ++i)
    result[free[i]] = x[i];
  return result;
}

Eigen::Vector3d RigidRotation::angular_velocity(const Eigen::Matrix3d& rotation,
                                                const Eigen::Vector3d& momentum) const {
  if (n_free_ == 3)
    return rotation * (inverse_inertia_ * (rotation.transpose() * momentum));
  return solve_free(rotation * inertia_ * rotation.transpose(), momentum);
}

Eigen::Vector3d RigidRotation::angular_acceleration(const Eigen::Matrix3d& rotation,
                                                    const Eigen::Vector3d& angular_velocity,
                                                    const Eigen::Vector3d& moment) const {
  const Eigen::Matrix3d spatial = rotation * inertia_ * rotation.transpose();
  return solve_free(spatial, moment - angular_velocity.cross(spatial * angular_velocity));
}

Eigen::Vector3d RigidRotation::momentum(const Eigen::Matrix3d& rotation,
                                        const Eigen::Vector3d& angular_velocity) const {
  return rotation * (inertia_ * (rotation.transpose() * angular_velocity));
}

void RigidRotation::kick(const Eigen::Vector3d& impulse, Eigen::Vector3d& momentum) const {
  for (int d = 0; d < 3; ++d)
    if (!locked_[d])
      momentum[d] += impulse[d];
}

double RigidRotation::kinetic_energy(const Eigen::Matrix3d& rotation,
                                     const Eigen::Vector3d& angular_velocity) const {
  return 0.5 * angular_velocity.dot(momentum(rotation, angular_velocity));
}

void RigidRotation::drift(double dt, const Eigen::Vector3d& momentum,
                          Eigen::Matrix3d& rotation) const {
  if (n_free_ == 0 || dt == 0)
    return;
  if (n_free_ == 3)
    free_drift(dt, momentum, rotation);
  else
    constrained_drift(dt, momentum, rotation);
  rotation = orthonormalised(rotation);
}

void RigidRotation::free_drift(double dt, const Eigen::Vector3d& momentum,
                               Eigen::Matrix3d& rotation) const {
  // Body-frame momentum Π; the midpoint Π̄ = ½(Π_n + Π_n+1) solves
  // Π̄ = Π_n + ½Δt Π̄ × I⁻¹Π̄ (Newton), then Π_n+1 = cay(−Δt Ω̄) Π_n and R_n+1 = R_n cay(Δt Ω̄):
  // R_n+1 Π_n+1 = R_n Π_n, so L is untouched.
  const Eigen::Vector3d start = rotation.transpose() * momentum;
  const double h = 0.5 * dt;
  Eigen::Vector3d mid = start;
  const double scale = std::max(start.norm(), 1e-300);
  for (int iteration = 0;; ++iteration) {
    if (iteration == kMaxIterations)
      throw RunError("the rigid-body rotation did not converge in " +
                     std::to_string(kMaxIterations) +
                     " Newton iterations (a time step far beyond the body's rotation period)");
    const Eigen::Vector3d omega = inverse_inertia_ * mid;
    const Eigen::Vector3d residual = mid - start - h * mid.cross(omega);
    const Eigen::Matrix3d jacobian =
        Eigen::Matrix3d::Identity() - h * (skew(mid) * inverse_inertia_ - skew(omega));
    const Eigen::Vector3d correction = jacobian.partialPivLu().solve(residual);
    mid -= correction;
    if (correction.norm() <= 1e-15 * scale)
      break;
  }
  rotation = rotation * cayley(dt * (inverse_inertia_ * mid));
}

void RigidRotation::constrained_drift(double dt, const Eigen::Vector3d& momentum,
                                      Eigen::Matrix3d& rotation) const {
  // Turn about the free axes with the angular velocity of the midpoint orientation: on the free
  // axes L is conserved (the locked axes' reaction has no component there). A hinge's inertia
  // about its axis does not change as it turns, so one iteration is exact there.
  const Eigen::Matrix3d start = rotation;
  Eigen::Vector3d omega = angular_velocity(start, momentum);
  const double scale = std::max(omega.norm(), 1e-300);
  for (int iteration = 0;; ++iteration) {
    if (iteration == kMaxIterations)
      throw RunError("the rigid-body rotation about its free axes did not converge in " +
                     std::to_string(kMaxIterations) +
                     " iterations (a time step far beyond the body's rotation period)");
    const Eigen::Vector3d next = angular_velocity(rotation_of(0.5 * dt * omega) * start, momentum);
    const double change = (next - omega).norm();
    omega = next;
    if (change <= 1e-14 * scale)
      break;
  }
  rotation = rotation_of(dt * omega) * start;
}

}  // namespace railfe
