// The inverse steady-rolling problem (forces prescribed, creepages found): a round trip through
// the forward solver, Kalker's linear theory at small forces, and the traction bound refused.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/laws/hertz.hpp"
#include "contact/laws/inverse_creepage.hpp"
#include "contact/laws/normal_problem.hpp"

namespace railfe {
namespace {

constexpr double kE = 210e9, kNu = 0.3, kG = kE / (2 * (1 + kNu)), kLoad = 1e5;

// The wheel-on-rail Hertz patch of the contact-mechanics issue (R 0.46 m and 0.30 m) at 30 x 30.
HertzPatch patch() {
  const HertzContact hertz =
      hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({kE, kNu}, {kE, kNu}), kLoad);
  return solve_hertz_patch(hertz, kG, kNu, 30);
}

TEST(InverseCreepage, RoundTripThroughTheForwardSolver) {
  const HertzPatch p = patch();
  FrictionLaw friction;
  friction.static_coefficient = friction.dynamic_coefficient = 0.3;
  // Partial slip in all three creepages: about 60 % of mu N.
  const Creepages creep{-8e-4, 5e-4, 0.3};
  const TangentialSolution forward =
      solve_tangential(*p.kernels, p.normal.pressure, creep, friction);
  ASSERT_TRUE(forward.converged);
  const double bound = 0.3 * kLoad;
  EXPECT_GT(std::hypot(forward.forces.Fx, forward.forces.Fy), 0.3 * bound);
  const InverseCreepageResult inverse =
      solve_for_creepages(*p.kernels, p.normal.pressure, forward.forces.Fx, forward.forces.Fy,
                          creep.spin, friction, 1e-8);
  ASSERT_TRUE(inverse.converged) << inverse.failure;
  EXPECT_NEAR(inverse.creepages.longitudinal, creep.longitudinal, 1e-4 * 8e-4);
  EXPECT_NEAR(inverse.creepages.lateral, creep.lateral, 1e-4 * 8e-4);
  EXPECT_NEAR(inverse.solution.forces.Fx, forward.forces.Fx, 1e-8 * bound);
  EXPECT_LT(inverse.iterations, 15);
}

TEST(InverseCreepage, SmallForcesGiveKalkersLinearCreepages) {
  // At 1e-4 of mu N the patch is all adhesion: the creepages are Kalker's linear theory
  // inverted, F = -G c^2 C11 xi, within the exact solver's 2 % of Kalker at this grid.
  const HertzPatch p = patch();
  const FrictionLaw friction;
  const HertzContact hertz =
      hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({kE, kNu}, {kE, kNu}), kLoad);
  const KalkerCoefficients c = KalkerTable::shipped().at(hertz.a, hertz.b, kNu);
  const CreepForces unit_xi = kalker_linear(c, kG, hertz.a, hertz.b, {1, 0, 0});
  const CreepForces unit_eta = kalker_linear(c, kG, hertz.a, hertz.b, {0, 1, 0});
  const double Fx = 3, Fy = -2;
  const InverseCreepageResult inverse =
      solve_for_creepages(*p.kernels, p.normal.pressure, Fx, Fy, 0, friction, 1e-9);
  ASSERT_TRUE(inverse.converged) << inverse.failure;
  EXPECT_NEAR(inverse.creepages.longitudinal / (Fx / unit_xi.Fx), 1, 0.02);
  EXPECT_NEAR(inverse.creepages.lateral / (Fy / unit_eta.Fy), 1, 0.02);
}

TEST(InverseCreepage, ForcesBeyondTheTractionBoundAreRefused) {
  const HertzPatch p = patch();
  const FrictionLaw friction;  // mu 0.3
  const InverseCreepageResult inverse =
      solve_for_creepages(*p.kernels, p.normal.pressure, 0.3 * kLoad, 1e3, 0, friction);
  EXPECT_FALSE(inverse.converged);
  EXPECT_NE(inverse.failure.find("traction bound"), std::string::npos) << inverse.failure;
}

}  // namespace
}  // namespace railfe
