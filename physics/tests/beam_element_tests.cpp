// The 3-D beam element against closed forms: rigid-body modes, symmetry and rank, cantilever
// tip deflections with and without shear (Timoshenko: δ = PL³/(3EI) + PL/(GA_s)), torsion,
// stretching, section forces from statics, and the mass matrices against Przemieniecki's
// published Euler–Bernoulli and Timoshenko coefficients and rigid-body inertia.
#include <gtest/gtest.h>

#include <stdexcept>

#include "physics/elements/beam_element.hpp"
#include "physics/tests/beam_test_data.hpp"

namespace railfe {
namespace {

using test::inclined_direction;
using test::inclined_orientation;
using test::inclined_start;
using test::steel;

constexpr double kLength = 1.2;

// A stocky rectangle: over L = 1.2 m shear adds 5 % to the tip deflection along z, 43 % along y.
BeamSection stocky() {
  return rectangle_section(0.12, 0.3, test::kPoisson);
}

BeamElement inclined_beam(const BeamSection& section, double length = kLength) {
  return BeamElement(inclined_start(), inclined_start() + length * inclined_direction(),
                     inclined_orientation(), steel(), section);
}

// Nodal motion of a rigid body: translation t and small rotation θ about point p.
Vector12 rigid_motion(const BeamElement& beam, const Eigen::Vector3d& t, const Eigen::Vector3d& th,
                      const Eigen::Vector3d& p) {
  const Eigen::Vector3d x[2] = {inclined_start(),
                                inclined_start() + beam.length() * inclined_direction()};
  Vector12 u;
  for (int n = 0; n < 2; ++n)
    u.segment<6>(6 * n) << t + th.cross(x[n] - p), th;
  return u;
}

TEST(BeamElement, AxesFollowTheOrientationVector) {
  const BeamElement beam = inclined_beam(stocky());
  const Eigen::Matrix3d& r = beam.axes();
  EXPECT_NEAR((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14);
  EXPECT_NEAR((r.row(0).transpose() - inclined_direction()).norm(), 0, 1e-14);
  EXPECT_NEAR(r.row(1).dot(inclined_orientation().cross(inclined_direction())), 0, 1e-14);
  EXPECT_GT(r.row(1).dot(inclined_orientation()), 0);
  EXPECT_NEAR(r.determinant(), 1, 1e-14);
}

TEST(BeamElement, StiffnessIsSymmetricWithExactlySixRigidBodyModes) {
  const Matrix12 k = inclined_beam(stocky()).stiffness();
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
  const Eigen::VectorXd eigen = Eigen::SelfAdjointEigenSolver<Matrix12>(k).eigenvalues();
  for (int i = 0; i < 6; ++i)
    EXPECT_LT(std::abs(eigen(i)), 1e-12 * eigen(11)) << i;
  EXPECT_GT(eigen(6), 1e-6 * eigen(11));
}

TEST(BeamElement, RigidBodyMotionGivesNoForce) {
  const BeamElement beam = inclined_beam(stocky());
  const Vector12 u = rigid_motion(beam, {1e-3, -2e-3, 5e-4}, {2e-3, -1e-3, 3e-3}, {4, -1, 2});
  const double scale = beam.stiffness().norm() * u.norm();
  EXPECT_LT(beam.end_forces(u).norm(), 1e-13 * scale);
  EXPECT_LT(beam.internal_force(u).norm(), 1e-13 * scale);
}

// Displacements of a cantilever of n elements along the inclined axis, clamped at its start,
// under the nodal load \p load (6 components, global) at its tip; returns the tip's 6 components.
Vector6 cantilever_tip(const BeamSection& section, int n, const Vector6& load) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(6 * (n + 1), 6 * (n + 1));
  for (int e = 0; e < n; ++e) {
    const Eigen::Vector3d a = inclined_start() + kLength * e / n * inclined_direction();
    const Eigen::Vector3d b = inclined_start() + kLength * (e + 1) / n * inclined_direction();
    k.block<12, 12>(6 * e, 6 * e) +=
        BeamElement(a, b, inclined_orientation(), steel(), section).stiffness();
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * n);
  f.tail<6>() = load;
  const Eigen::VectorXd u = k.bottomRightCorner(6 * n, 6 * n).ldlt().solve(f);
  return u.tail<6>();
}

// Tip load along local axis \p axis (1 = y, 2 = z): the tip's local deflection and rotation
// against Timoshenko's closed form, for one and for five elements.
void check_cantilever_bending(const BeamSection& section, int axis) {
  const BeamElement beam = inclined_beam(section);
  const Eigen::Matrix3d& r = beam.axes();
  const double P = 1e4, E = test::kYoung, G = steel().shear_modulus, L = kLength;
  const double inertia = axis == 1 ? section.iz : section.iy;
  const double shear_area = axis == 1 ? section.shear_area_y : section.shear_area_z;
  const double deflection = P * L * L * L / (3 * E * inertia) + P * L / (G * shear_area);
  // θ_z = dv/dx but θ_y = −dw/dx.
  const double rotation = (axis == 1 ? 1 : -1) * P * L * L / (2 * E * inertia);
  Vector6 load = Vector6::Zero();
  load.head<3>() = P * r.row(axis).transpose();
  for (int n : {1, 5}) {
    const Vector6 tip = cantilever_tip(section, n, load);
    const Eigen::Vector3d u = r * tip.head<3>(), th = r * tip.tail<3>();
    EXPECT_NEAR(u(axis) / deflection, 1, 1e-10) << "n " << n;
    EXPECT_NEAR(th(3 - axis) / rotation, 1, 1e-10) << "n " << n;
    EXPECT_NEAR(u(3 - axis), 0, 1e-12 * deflection);
    EXPECT_NEAR(u(0), 0, 1e-12 * deflection);
  }
}

TEST(BeamElement, CantileverTipMatchesTimoshenkoWithShear) {
  const BeamSection section = stocky();
  check_cantilever_bending(section, 1);
  check_cantilever_bending(section, 2);
  // The shear term is a real share of the deflection here (tolerance 1e-10), so a missing one
  // would fail.
  const double bending = kLength * kLength * kLength / (3 * test::kYoung * section.iy);
  const double shear = kLength / (steel().shear_modulus * section.shear_area_z);
  EXPECT_GT(shear / bending, 0.04);
}

TEST(BeamElement, CantileverTipMatchesEulerBernoulliWithoutShear) {
  const BeamSection section = euler_bernoulli(stocky());
  check_cantilever_bending(section, 1);
  check_cantilever_bending(section, 2);
}

TEST(BeamElement, TorsionAndStretchingMatchClosedForms) {
  const BeamSection section = stocky();
  const Eigen::Matrix3d r = inclined_beam(section).axes();
  const double T = 3e3, N = 5e5, L = kLength;
  Vector6 load;
  load << N * r.row(0).transpose(), T * r.row(0).transpose();
  const Vector6 tip = cantilever_tip(section, 3, load);
  EXPECT_NEAR((r * tip.tail<3>())(0) / (T * L / (steel().shear_modulus * section.torsion)), 1,
              1e-10);
  EXPECT_NEAR((r * tip.head<3>())(0) / (N * L / (test::kYoung * section.area)), 1, 1e-10);
}

TEST(BeamElement, SectionForcesMatchStatics) {
  // One element clamped at a, tip load P along local z and a torque T at b.
  const BeamSection section = stocky();
  const BeamElement beam = inclined_beam(section);
  const Eigen::Matrix3d& r = beam.axes();
  const double P = 1e4, T = 2e3, L = kLength;
  Vector6 load;
  load << P * r.row(2).transpose(), T * r.row(0).transpose();
  Vector12 u = Vector12::Zero();
  u.tail<6>() = cantilever_tip(section, 1, load);
  const BeamSectionForces s = beam.section_forces(u);
  // N, Vy, Vz, T, My, Mz: constant shear P, torque T, and M_y from −P L at a to 0 at b.
  Vector6 at_a, at_b;
  at_a << 0, 0, P, T, -P * L, 0;
  at_b << 0, 0, P, T, 0, 0;
  EXPECT_LT((s[0] - at_a).norm(), 1e-8 * P * L);
  EXPECT_LT((s[1] - at_b).norm(), 1e-8 * P * L);
}

// The local bending block of plane (w, θ) DOFs; \p sign −1 for θ_y = −dw/dx.
Eigen::Matrix4d bending_block(const Matrix12& m, const int dofs[4], double sign) {
  const double s[4] = {1, sign, 1, sign};
  Eigen::Matrix4d b;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      b(i, j) = s[i] * s[j] * m(dofs[i], dofs[j]);
  return b;
}

TEST(BeamElement, EulerBernoulliMassIsTheClassicalConsistentMass) {
  // ρAL/420 [156, 22L, 54, −13L; ...] and, for the rotary inertia, ρI/(30L) [36, 3L, −36, 3L;
  // ...] (Przemieniecki 1968, Archer 1963).
  const BeamSection section = euler_bernoulli(stocky());
  const double L = kLength, rho = test::kDensity;
  const Eigen::Vector3d a = inclined_start(), b = a + L * inclined_direction();
  const BeamElement with(a, b, inclined_orientation(), steel(), section, true);
  const BeamElement without(a, b, inclined_orientation(), steel(), section, false);
  Eigen::Matrix4d translation, rotary;
  translation << 156, 22 * L, 54, -13 * L, 22 * L, 4 * L * L, 13 * L, -3 * L * L, 54, 13 * L, 156,
      -22 * L, -13 * L, -3 * L * L, -22 * L, 4 * L * L;
  rotary << 36, 3 * L, -36, 3 * L, 3 * L, 4 * L * L, -3 * L, -L * L, -36, -3 * L, 36, -3 * L, 3 * L,
      -L * L, -3 * L, 4 * L * L;
  translation *= rho * section.area * L / 420;
  const int xy[4] = {1, 5, 7, 11}, xz[4] = {2, 4, 8, 10};
  const Matrix12 m0 = without.local_mass(BeamMass::consistent);
  const Matrix12 m1 = with.local_mass(BeamMass::consistent);
  for (auto [dofs, sign, inertia] :
       {std::tuple{xy, 1.0, section.iz}, std::tuple{xz, -1.0, section.iy}}) {
    EXPECT_LT((bending_block(m0, dofs, sign) - translation).norm(), 1e-13 * translation.norm());
    const Eigen::Matrix4d r = rho * inertia / (30 * L) * rotary;
    EXPECT_LT((bending_block(m1 - m0, dofs, sign) - r).norm(), 1e-12 * r.norm());
  }
}

TEST(BeamElement, TimoshenkoMassMatchesPublishedCoefficients) {
  // Przemieniecki's consistent mass with shear deformation φ (Friedman & Kosmatka 1993, eq. 21),
  // x–y plane (I_z, A_y), for a stocky element where φ is large.
  const BeamSection section = stocky();
  const double L = 0.4, rho = test::kDensity;
  const BeamElement beam = inclined_beam(section, L);
  const double f = beam.shear_parameters()[0];
  ASSERT_GT(f, 0.1);
  Eigen::Matrix4d t, r;
  const double t11 = 13. / 35 + 7. / 10 * f + f * f / 3;
  const double t12 = (11. / 210 + 11. / 120 * f + f * f / 24) * L;
  const double t13 = 9. / 70 + 3. / 10 * f + f * f / 6;
  const double t14 = -(13. / 420 + 3. / 40 * f + f * f / 24) * L;
  const double t22 = (1. / 105 + f / 60 + f * f / 120) * L * L;
  const double t24 = -(1. / 140 + f / 60 + f * f / 120) * L * L;
  t << t11, t12, t13, t14, t12, t22, -t14, t24, t13, -t14, t11, -t12, t14, t24, -t12, t22;
  const double r12 = (1. / 10 - f / 2) * L, r22 = (2. / 15 + f / 6 + f * f / 3) * L * L;
  const double r24 = (-1. / 30 - f / 6 + f * f / 6) * L * L;
  r << 6. / 5, r12, -6. / 5, r12, r12, r22, -r12, r24, -6. / 5, -r12, 6. / 5, -r12, r12, r24, -r12,
      r22;
  const double c = 1 / ((1 + f) * (1 + f));
  const Eigen::Matrix4d expected = c * (rho * section.area * L * t + rho * section.iz / L * r);
  const int xy[4] = {1, 5, 7, 11};
  EXPECT_LT((bending_block(beam.local_mass(BeamMass::consistent), xy, 1) - expected).norm(),
            1e-12 * expected.norm());
}

TEST(BeamElement, ConsistentMassCarriesRigidBodyInertiaExactly) {
  const BeamSection section = stocky();
  const BeamElement beam = inclined_beam(section);
  const Matrix12 m = beam.mass(BeamMass::consistent);
  EXPECT_LT((m - m.transpose()).norm(), 1e-14 * m.norm());
  const double rho = test::kDensity, L = kLength, mass = rho * section.area * L;
  const Eigen::Matrix3d& r = beam.axes();
  const Eigen::Vector3d centre = inclined_start() + L / 2 * inclined_direction();
  const Vector12 translation =
      rigid_motion(beam, {0.3, -0.5, 0.8}, Eigen::Vector3d::Zero(), centre);
  EXPECT_NEAR(translation.dot(m * translation) / (0.98 * mass), 1, 1e-12);
  // Rotations about the local axes through the centre: ρ(Iy+Iz)L about x; ρAL³/12 + ρIL about
  // a transverse axis (the section's own rotary inertia included).
  const double expected[3] = {rho * (section.iy + section.iz) * L,
                              mass * L * L / 12 + rho * section.iy * L,
                              mass * L * L / 12 + rho * section.iz * L};
  for (int i = 0; i < 3; ++i) {
    const Vector12 u = rigid_motion(beam, Eigen::Vector3d::Zero(), r.row(i).transpose(), centre);
    EXPECT_NEAR(u.dot(m * u) / expected[i], 1, 1e-12) << "axis " << i;
  }
}

TEST(BeamElement, LumpedMassIsDiagonalAndKeepsTheMass) {
  const BeamSection section = stocky();
  const BeamElement beam = inclined_beam(section);
  const Matrix12 local = beam.local_mass(BeamMass::lumped);
  EXPECT_EQ((local - Matrix12(local.diagonal().asDiagonal())).norm(), 0);
  EXPECT_GT(local.diagonal().minCoeff(), 0);
  const double mass = test::kDensity * section.area * kLength;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR((local(c, c) + local(c + 6, c + 6)) / mass, 1, 1e-14) << c;
  EXPECT_NEAR(local(3, 3) / (test::kDensity * (section.iy + section.iz) * kLength / 2), 1, 1e-14);
  // In global axes the translations stay diagonal with m/2 each.
  const Matrix12 global = beam.mass(BeamMass::lumped);
  EXPECT_LT((global.topLeftCorner<3, 3>() - mass / 2 * Eigen::Matrix3d::Identity()).norm(),
            1e-12 * mass);
}

TEST(BeamElement, RefusesDegenerateInput) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0);
  const BeamSection section = stocky();
  EXPECT_THROW(BeamElement(a, a, {0, 1, 0}, steel(), section), std::invalid_argument);
  EXPECT_THROW(BeamElement(a, b, {2, 0, 0}, steel(), section), std::invalid_argument);
  EXPECT_THROW(BeamElement(a, b, {0, 0, 0}, steel(), section), std::invalid_argument);
  BeamSection no_torsion = section;
  no_torsion.torsion = 0;
  EXPECT_THROW(BeamElement(a, b, {0, 1, 0}, steel(), no_torsion), std::invalid_argument);
  BeamMaterial soft = steel();
  soft.shear_modulus = 0;
  EXPECT_THROW(BeamElement(a, b, {0, 1, 0}, soft, section), std::invalid_argument);
}

}  // namespace
}  // namespace railfe
