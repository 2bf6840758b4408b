// Spring–dampers, point masses and rigid links against independent checks: a spring's matrix
// has the component stiffnesses as eigenvalues along its local axes and no force under rigid
// translation; a point mass off its node has the kinetic energy of a rigid body (Steiner's
// parallel axes); a rigid link's slave follows an exact finite rotation (Rodrigues) to second
// order, and a load carried by a link twists a cantilever as statics says (T = e P).
#include <gtest/gtest.h>

#include <stdexcept>

#include "physics/elements/beam_element.hpp"
#include "physics/elements/point_mass.hpp"
#include "physics/elements/rigid_link.hpp"
#include "physics/elements/spring_damper.hpp"
#include "physics/tests/beam_test_data.hpp"

namespace railfe {
namespace {

Eigen::Matrix3d some_rotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
}

SpringDamper some_spring() {
  SpringDamper s;
  s.stiffness = {1e6, 2e6, 3e5, 4e3, 5e3, 6e3};
  s.damping = {10, 20, 30, 0.4, 0.5, 0.6};
  s.axes = some_rotation();
  return s;
}

TEST(SpringDamper, ActsAlongItsLocalAxes) {
  const SpringDamper s = some_spring();
  const Matrix6 ground = spring_block(s.stiffness, s.axes);
  for (int i = 0; i < 6; ++i) {
    Vector6 u = Vector6::Zero();
    u.segment<3>(i < 3 ? 0 : 3) = s.axes.row(i % 3).transpose();
    EXPECT_LT((ground * u - s.stiffness[i] * u).norm(), 1e-9 * s.stiffness[i]) << i;
    Vector6 local = Vector6::Zero();
    local(i) = s.stiffness[i] * 1e-3 + s.damping[i] * 2e-3;
    EXPECT_LT((spring_local_force(s, 1e-3 * u, 2e-3 * u) - local).norm(), 1e-9 * local.norm());
  }
}

TEST(SpringDamper, TwoNodeForcesBalanceAndVanishUnderTranslation) {
  const SpringDamper s = some_spring();
  const Matrix12 k = spring_stiffness(s), c = spring_damping(s);
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  Vector12 u, v;
  u << 1e-3, 2e-3, -1e-3, 1e-4, 0, 2e-4, -2e-3, 1e-3, 5e-4, 0, 3e-4, -1e-4;
  v = 10 * u.reverse();
  const Vector12 f = spring_internal_force(s, u, v);
  EXPECT_LT((f - (k * u + c * v)).norm(), 1e-12 * f.norm());
  EXPECT_LT((f.head<6>() + f.tail<6>()).norm(), 1e-12 * f.norm());
  Vector12 same;
  same << u.head<6>(), u.head<6>();
  EXPECT_LT((k * same).norm(), 1e-9);
  // To the ground: the node's own motion, the matrices of one node.
  const Vector6 ground = ground_spring_internal_force(s, u.head<6>(), v.head<6>());
  EXPECT_LT(
      (ground - (ground_spring_stiffness(s) * u.head<6>() + ground_spring_damping(s) * v.head<6>()))
          .norm(),
      1e-12 * ground.norm());
  SpringDamper bad = s;
  bad.stiffness[2] = -1;
  EXPECT_THROW(check_spring_damper(bad), std::invalid_argument);
  bad = s;
  bad.axes(0, 0) = 2;
  EXPECT_THROW(check_spring_damper(bad), std::invalid_argument);
}

TEST(PointMass, OffsetMassHasTheKineticEnergyOfARigidBody) {
  const double m = 350;
  const Eigen::Matrix3d inertia =
      inertia_to_global(Eigen::Vector3d(20, 35, 50).asDiagonal(), some_rotation());
  const Eigen::Vector3d r(0.4, -0.3, 1.2);
  const Matrix6 mass = point_mass_matrix(m, inertia, r);
  EXPECT_LT((mass - mass.transpose()).norm(), 1e-12 * mass.norm());
  const Eigen::Vector3d v(1.5, -0.2, 0.7), w(0.3, 0.8, -0.4);
  Vector6 x;
  x << v, w;
  const Eigen::Vector3d centre_velocity = v + w.cross(r);
  const double energy = m * centre_velocity.squaredNorm() + w.dot(inertia * w);
  EXPECT_NEAR(x.dot(mass * x) / energy, 1, 1e-13);
  // Steiner: the rotational block is J + m (|r|² I − r rᵀ).
  const Eigen::Matrix3d steiner =
      inertia + m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  EXPECT_LT((mass.bottomRightCorner<3, 3>() - steiner).norm(), 1e-12 * steiner.norm());
  // The principal values survive the rotation to global axes.
  const Eigen::Vector3d principal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();
  EXPECT_LT((principal - Eigen::Vector3d(20, 35, 50)).norm(), 1e-12);
  EXPECT_THROW(point_mass_matrix(-1, inertia), std::invalid_argument);
  EXPECT_THROW(point_mass_matrix(m, -inertia), std::invalid_argument);
}

TEST(RigidLink, SlaveFollowsASmallFiniteRotation) {
  const Eigen::Vector3d r(0.5, -1.0, 2.0), um(1e-3, -2e-3, 3e-3);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1, -0.6).normalized();
  const double angle = 1e-6;
  const Eigen::Vector3d exact =
      um + (Eigen::AngleAxisd(angle, axis).toRotationMatrix() - Eigen::Matrix3d::Identity()) * r;
  Vector6 master;
  master << um, angle * axis;
  const Eigen::Vector3d linear = rigid_link_translation(r) * master;
  EXPECT_LT((linear - exact).norm(), 1e-11);  // second order: angle² |r|
  // The equations say the same, one slave component at a time.
  for (int components : {3, 6}) {
    const std::vector<RigidLinkEquation> eqs = rigid_link_equations(r, components);
    ASSERT_EQ(static_cast<int>(eqs.size()), components);
    for (const RigidLinkEquation& eq : eqs) {
      double value = 0;
      for (auto [component, coefficient] : eq.masters)
        value += coefficient * master(component);
      const double expected =
          eq.slave_component < 3 ? linear(eq.slave_component) : master(eq.slave_component);
      EXPECT_NEAR(value, expected, 1e-15) << eq.slave_component;
    }
  }
  // Zero offset components give no coefficient: u_x of a slave straight above the master does
  // not depend on θ_x.
  const std::vector<RigidLinkEquation> above = rigid_link_equations({0, 0, 1}, 3);
  EXPECT_EQ(above[0].masters.size(), 2u);  // u_x and θ_y
  EXPECT_EQ(above[2].masters.size(), 1u);  // u_z only
  EXPECT_THROW(rigid_link_equations(r, 4), std::invalid_argument);
}

TEST(RigidLink, EccentricLoadTwistsACantilever) {
  // A tip load P along z at offset e along y from the tip of a cantilever along x: the link
  // moves it to the tip as P and T = e P, so the tip twists by e P L / (G J) and deflects by
  // P L³/(3EI) + P L/(G A_z).
  const BeamSection section = rectangle_section(0.1, 0.2, test::kPoisson);
  const BeamMaterial steel = test::steel();
  const double L = 2, P = 1e3, e = 0.5;
  const BeamElement beam({0, 0, 0}, {L, 0, 0}, {0, 1, 0}, steel, section);
  Eigen::Vector3d force(0, 0, P);
  Vector6 at_slave;
  at_slave << force, Eigen::Vector3d::Zero();
  const Vector6 at_tip = rigid_link_matrix({0, e, 0}).transpose() * at_slave;
  const Vector6 tip = beam.stiffness().bottomRightCorner<6, 6>().ldlt().solve(at_tip);
  EXPECT_NEAR(tip(3) / (e * P * L / (steel.shear_modulus * section.torsion)), 1, 1e-10);
  EXPECT_NEAR(tip(2) / (P * L * L * L / (3 * test::kYoung * section.iy) +
                        P * L / (steel.shear_modulus * section.shear_area_z)),
              1, 1e-10);
}

}  // namespace
}  // namespace railfe
