// The rotation of the explicit rigid bodies (physics/explicit/rigid_rotation.hpp) against closed
// forms nobody here wrote: the torque-free axisymmetric body precesses in its own axes at
// Ω_p = (C − A)/A ω_3 (Landau & Lifshitz, Mechanics, §33), so the scheme's error must fall as Δt²;
// a free body conserves its spatial angular momentum to round-off and its kinetic energy to the
// Newton tolerance, with R orthonormal, over 10⁵ steps; a hinge off the principal axes turns at
// L_z / I_zz exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/explicit/rigid_rotation.hpp"

namespace railfe {
namespace {

constexpr std::array<bool, 3> kFree{false, false, false};

TEST(RigidRotation, FreeBodyConservesMomentumEnergyAndOrthonormality) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(1, 2, 3).asDiagonal();
  const RigidRotation rotation(inertia, kFree);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d L0 = rotation.momentum(R, Eigen::Vector3d(0.1, 10, 0.1));
  const double energy = rotation.kinetic_energy(R, rotation.angular_velocity(R, L0));
  double worst_energy = 0, worst_orthonormality = 0;
  for (int step = 0; step < 100000; ++step) {
    rotation.drift(5e-3, L0, R);
    worst_energy = std::max(
        worst_energy,
        std::abs(rotation.kinetic_energy(R, rotation.angular_velocity(R, L0)) / energy - 1));
    worst_orthonormality =
        std::max(worst_orthonormality,
                 (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst_energy, 1e-13);
  EXPECT_LT(worst_orthonormality, 1e-15);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
}

// Body-frame angular velocity of the axisymmetric top after time t, both ways.
double precession_error(double dt) {
  const double A = 1, C = 2.5, w3 = 4, w_perp = 3;
  const Eigen::Matrix3d inertia = Eigen::Vector3d(A, A, C).asDiagonal();
  const RigidRotation rotation(inertia, kFree);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d L = rotation.momentum(R, Eigen::Vector3d(w_perp, 0, w3));
  const double end = 1.0;
  const int steps = static_cast<int>(std::lround(end / dt));
  for (int step = 0; step < steps; ++step)
    rotation.drift(dt, L, R);
  const Eigen::Vector3d body = R.transpose() * rotation.angular_velocity(R, L);
  // Ω_p = (C − A)/A ω₃; in the body the transverse ω turns the other way: ω̇₁ = −Ω_p ω₂.
  const double precession = (C - A) / A * w3;
  const Eigen::Vector3d exact(w_perp * std::cos(precession * end),
                              w_perp * std::sin(precession * end), w3);
  return (body - exact).norm();
}

TEST(RigidRotation, SecondOrderAgainstTheAxisymmetricTop) {
  const double coarse = precession_error(1e-2), fine = precession_error(5e-3),
               finest = precession_error(2.5e-3);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.05);
  EXPECT_NEAR(std::log2(fine / finest), 2.0, 0.05);
  EXPECT_LT(finest, 1e-3);
}

TEST(RigidRotation, HingeOffThePrincipalAxesTurnsAtMomentumOverAxialInertia) {
  Eigen::Matrix3d inertia;
  inertia << 0.058875, -0.019625, -0.019625, -0.019625, 0.058875, -0.019625, -0.019625, -0.019625,
      0.058875;
  const RigidRotation rotation(inertia, {true, true, false});
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d L = Eigen::Vector3d::Zero();
  rotation.kick(Eigen::Vector3d(0.3, -0.2, 0.05), L);  // only the free z component counts
  EXPECT_EQ(L, Eigen::Vector3d(0, 0, 0.05));
  const Eigen::Vector3d w = rotation.angular_velocity(R, L);
  EXPECT_NEAR(w[2], 0.05 / 0.058875, 1e-15);
  EXPECT_EQ(w[0], 0.0);
  EXPECT_EQ(w[1], 0.0);
  for (int step = 0; step < 1000; ++step)
    rotation.drift(1e-3, L, R);
  const double angle = std::atan2(R(1, 0), R(0, 0));
  EXPECT_NEAR(angle, 0.05 / 0.058875, 1e-13);
  EXPECT_NEAR(R(2, 2), 1.0, 1e-15);
  EXPECT_NEAR(rotation.angular_velocity(R, L)[2], 0.05 / 0.058875, 1e-14);
}

TEST(RigidRotation, AngularAccelerationIsEulersEquation) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(1, 2, 3).asDiagonal();
  const RigidRotation rotation(inertia, kFree);
  const Eigen::Matrix3d R = rotation_of(Eigen::Vector3d(0.3, -0.4, 0.5));
  const Eigen::Vector3d w(1, 2, 3), M(0.5, -1, 2);
  const Eigen::Matrix3d spatial = R * inertia * R.transpose();
  const Eigen::Vector3d alpha = rotation.angular_acceleration(R, w, M);
  EXPECT_LT((spatial * alpha + w.cross(spatial * w) - M).norm(), 1e-13);
  EXPECT_LT((rotation.angular_velocity(R, rotation.momentum(R, w)) - w).norm(), 1e-14);
}

}  // namespace
}  // namespace railfe
