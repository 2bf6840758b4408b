// The direct method's moving constraints: the beam interpolation they use, a moving force
// carried through the constraint machinery against the plain moving load, block against
// monolithic saddle-point solves, separation over a bump and a path that ends.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "framework/base/error.hpp"
#include "physics/elements/beam_interpolation.hpp"
#include "physics/implicit/moving_crossing.hpp"

namespace railfe {
namespace {

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

double peak(const std::vector<double>& a) {
  double p = 0;
  for (double x : a)
    p = std::max(p, std::abs(x));
  return p;
}

// A rigid-body motion (translation t, small rotation θ) is interpolated exactly inside a skewed
// shear-deformable beam, and the nodal translations at the ends.
TEST(BeamInterpolation, ReproducesRigidMotionAndNodes) {
  const Eigen::Vector3d a(0.3, -0.2, 0.1), b(2.1, 0.9, -0.7);
  BeamSection section{0.02, 3e-5, 5e-5, 4e-5, 0.015, 0.012};
  const BeamElement beam(a, b, Eigen::Vector3d(0, 0, 1), isotropic_beam_material(2e11, 0.3, 7850),
                         section);
  ASSERT_GT(beam.shear_parameters()[0], 1e-3);
  const Eigen::Vector3d t(0.01, -0.02, 0.03), theta(0.002, -0.003, 0.001);
  Vector12 u;
  u << t + theta.cross(a - a), theta, t + theta.cross(b - a), theta;
  for (double xi : {0.0, 0.17, 0.5, 0.83, 1.0}) {
    const Eigen::Vector3d x = a + xi * (b - a);
    const Eigen::Vector3d expected = t + theta.cross(x - a);
    EXPECT_LT((beam_translation_interpolation(beam, xi) * u - expected).norm(), 1e-14) << xi;
  }
  Vector12 nodal = Vector12::Random();
  EXPECT_LT((beam_translation_interpolation(beam, 0.0) * nodal - nodal.head<3>()).norm(), 1e-14);
  EXPECT_LT((beam_translation_interpolation(beam, 1.0) * nodal - nodal.segment<3>(6)).norm(),
            1e-14);
}

// A massless vehicle point carrying its weight through the constraint gives the moving-force
// response exactly (the α-weighted multiplier term equals the α-weighted external load), with
// both saddle-point solvers.
TEST(MovingContacts, ConstrainedWeightEqualsMovingForce) {
  CrossingSettings s;
  s.vehicle_dofs = 1;  // the wheel alone, carrying vehicle_mass · g
  s.alpha = -0.1;
  s.dt = 2e-3;
  CrossingSettings force = s;
  force.moving_force = true;
  const CrossingResult reference = run_crossing(force);
  for (const char* solver : {"block", "monolithic"}) {
    s.solver = solver;
    const CrossingResult r = run_crossing(s);
    ASSERT_EQ(r.time.size(), reference.time.size());
    const double scale = peak(reference.midspan_deflection);
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(max_difference(r.midspan_deflection, reference.midspan_deflection), 1e-10 * scale)
        << solver;
    EXPECT_LT(max_difference(r.contact_force, reference.contact_force), 1e-8 * 5750 * 9.81)
        << solver;
  }
}

// The sprung mass on a grillage: factor-once block solves and monolithic UMFPACK solves agree to
// round-off; the block solver factors the structure twice (M for a_0, then A).
TEST(MovingContacts, BlockAndMonolithicAgreeOnSprungMass) {
  CrossingSettings s;
  s.lines = 2;
  s.wheels = 2;
  s.vehicle_dofs = 6;
  s.wheel_mass = 300;
  s.alpha = -0.05;
  s.dt = 2e-3;
  s.bump_height = 0.002;
  s.steps = 400;  // whole steps only: one Δt, so A_s is factored once after M
  const CrossingResult block = run_crossing(s);
  s.solver = "monolithic";
  const CrossingResult monolithic = run_crossing(s);
  EXPECT_EQ(block.structure_factorizations, 2u);
  for (auto member : {&CrossingResult::midspan_deflection, &CrossingResult::vehicle_acceleration,
                      &CrossingResult::contact_force}) {
    const double scale = peak(monolithic.*member);
    EXPECT_GT(scale, 0);
    EXPECT_LT(max_difference(block.*member, monolithic.*member), 1e-9 * scale);
  }
}

// A 500 kg wheel over a 10 mm, 1 m bump at 100 km/h (Δt = 0.5 ms, HHT \p alpha): one release,
// then one landing with its consistent restart; the contact force never pulls.
CrossingResult expect_one_landing(double alpha, CrossingSettings& s) {
  s.wheel_mass = 500;
  s.vehicle_dofs = 2;
  s.bump_height = 0.01;
  s.bump_length = 1.0;
  s.bump_start = 12;
  s.dt = 5e-4;
  s.alpha = alpha;
  const CrossingResult r = run_crossing(s);
  EXPECT_EQ(r.events.size(), 2u) << "alpha " << alpha;
  if (r.events.size() == 2) {
    EXPECT_TRUE(r.events[0].separation);
    EXPECT_FALSE(r.events[1].separation);
    EXPECT_GT(r.events[1].time, r.events[0].time);
  }
  EXPECT_EQ(r.restarts, 1u) << "alpha " << alpha;
  for (double f : r.contact_force)
    EXPECT_GE(f, 0.0);
  return r;
}

// The wheel leaves the surface near the crest, where the surface's downward acceleration
// h/2 (2π/l)² v² = 152 m/s² exceeds what gravity and the suspension give the wheel, and lands
// once, 0.06 m further. Without the bump it stays in contact.
TEST(MovingContacts, SeparationOverABumpIsReported) {
  CrossingSettings s;
  const CrossingResult r = expect_one_landing(-0.3, s);
  ASSERT_FALSE(r.events.empty());
  EXPECT_GT(r.events[0].position, s.bump_start + 0.25 * s.bump_length);  // curvature < 0
  EXPECT_LT(r.events[0].position, s.bump_start + 0.75 * s.bump_length);
  s.bump_height = 0;
  EXPECT_TRUE(run_crossing(s).events.empty());
}

// The same landing at α = −0.05, where the displacement rows alone reflect the landing
// velocity into a step-to-step mode that decays by at most ρ∞ = 0.905 a step (45–91 releases and
// engagements before the plastic-impact restart).
TEST(MovingContacts, LandingAtSmallAlphaDoesNotChatter) {
  CrossingSettings s;
  expect_one_landing(-0.05, s);
}

// A 500 kg wheel under 5750 kg on a smooth beam at α = 0 (no numerical damping): the moving
// rows drive the multipliers' step-to-step mode, which grows without bound (before the restarts
// it separated falsely after 0.44 s, with forces up to 12 MN); restarted whenever it grows, the
// contact force stays within 3 % of the weight (6250 kg × 9.81 m/s² = 61,312.5 N) the whole
// crossing, as it does at α = −0.05 (within 1.5 %).
TEST(MovingContacts, WheelWithMassStaysInContactAtAlphaZero) {
  CrossingSettings s;
  s.wheel_mass = 500;
  s.vehicle_dofs = 2;
  s.alpha = 0;
  const CrossingResult r = run_crossing(s);
  EXPECT_TRUE(r.events.empty());
  EXPECT_GT(r.restarts, 0u);
  const double weight = (s.vehicle_mass + s.wheel_mass) * 9.81;
  for (double f : r.contact_force)
    EXPECT_NEAR(f, weight, 0.03 * weight);
}

// Irregularities from a CSV file (linear between rows) on the right-hand side of a vertical and
// a lateral row, both released together; a file that does not cover s, or a bad file, is named.
TEST(MovingContacts, IrregularityFromCsvFeedsVerticalAndLateralRows) {
  const std::string path = testing::TempDir() + "railfe_irregularity.csv";
  {
    std::ofstream file(path);
    file << "s,vertical,lateral\n0,0,0\n2,0.004,-0.002\n4,0,0\n";
  }
  const Irregularity surface = Irregularity::from_csv(path);
  EXPECT_DOUBLE_EQ(surface.vertical(1.0), 0.002);
  EXPECT_DOUBLE_EQ(surface.lateral(3.0), -0.001);
  EXPECT_THROW(surface.vertical(4.5), RunError);
  BeamSection section{1.0, 1.0, 1.0, 2.0, INFINITY, INFINITY};
  const BeamElement beam(Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 0, 0),
                         Eigen::Vector3d(0, 0, 1), isotropic_beam_material(2e11, 0.3, 7850),
                         section);
  std::array<long, 12> unknowns;
  for (int k = 0; k < 12; ++k)
    unknowns[k] = k;
  MovingContacts contacts(BeamPath({{beam, unknowns}}),
                          {{"wheel", 13, 12, 0.5, 1.0, surface, true}});
  ConstraintRows rows;
  contacts.rows_at(0.5, rows);  // s = 1 m
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows.rhs[0], 0.002);   // vertical
  EXPECT_DOUBLE_EQ(rows.rhs[1], -0.001);  // lateral
  // Row 0: u_13 − N_z u_e; the vertical beam DOFs at s = 1 m (ξ = 1/4): u_z,a weight 27/32.
  EXPECT_EQ(rows.columns[rows.offsets[0]], 13u);
  double weight = 0;
  for (std::size_t k = rows.offsets[0]; k < rows.offsets[1]; ++k)
    if (rows.columns[k] == 2)
      weight = -rows.values[k];
  EXPECT_NEAR(weight, 27.0 / 32.0, 1e-14);  // Hermite 1 − 3ξ² + 2ξ³
  const double pulling[2] = {1.0, 0.0};
  std::vector<double> u(14, 0.0);
  EXPECT_TRUE(contacts.accept(0.5, u.data(), pulling));
  rows.clear();
  contacts.rows_at(0.6, rows);
  EXPECT_EQ(rows.size(), 0u);  // both rows released
  std::remove(path.c_str());
  try {
    Irregularity::from_csv(path);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
}

// A vehicle that runs past the end of the bridge is refused with the time and the place.
TEST(MovingContacts, PathThatLeavesTheStructureIsRefused) {
  CrossingSettings s;
  s.dt = 0.01;
  s.steps = 200;  // 2 s at 27.8 m/s: beyond the 25 m span
  try {
    run_crossing(s);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("moving contact 'wheel 1' leaves the structure"), std::string::npos)
        << message;
    EXPECT_NE(message.find("outside its path [0, 25] m"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace railfe
