// FASTSIM: its small-creepage limit is Kalker's linear theory (which its flexibilities are
// built to reproduce), large creepages saturate at mu N, and refining the grid converges.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/laws/fastsim.hpp"
#include "contact/laws/hertz.hpp"

namespace railfe {
namespace {

constexpr double kG = 210e9 / (2 * 1.3);  // steel, nu 0.3
constexpr double kLoad = 1e5, kMu = 0.3;

// The Hertz case: 0.46 m wheel on a 0.30 m crown, 100 kN.
HertzContact patch() {
  return hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({210e9, 0.3}, {210e9, 0.3}),
                       kLoad);
}

TEST(Fastsim, SmallCreepagesGiveTheLinearTheory) {
  const HertzContact h = patch();
  const KalkerCoefficients c = KalkerTable::shipped().at(h.a, h.b, 0.3);
  FastsimSettings fine;
  fine.cells_x = fine.strips = 200;
  for (const Creepages creep : {Creepages{1e-6, 0, 0}, Creepages{0, 1e-6, 0}}) {
    const CreepForces linear = kalker_linear(c, kG, h.a, h.b, creep);
    const FastsimResult r = fastsim(c, kG, h.a, h.b, kLoad, kMu, creep, fine);
    EXPECT_NEAR(r.forces.Fx, linear.Fx, 0.005 * std::abs(linear.Fx) + 1e-9);
    EXPECT_NEAR(r.forces.Fy, linear.Fy, 0.005 * std::abs(linear.Fy) + 1e-9);
    EXPECT_DOUBLE_EQ(r.adhesion_fraction, 1.0);
  }
  // Spin: the lateral force of a small spin is the linear theory's -G c^3 C23 phi.
  const Creepages spin{0, 0, 1e-5};
  const CreepForces linear = kalker_linear(c, kG, h.a, h.b, spin);
  const FastsimResult r = fastsim(c, kG, h.a, h.b, kLoad, kMu, spin, fine);
  EXPECT_NEAR(r.forces.Fy, linear.Fy, 0.01 * std::abs(linear.Fy));
}

TEST(Fastsim, LargeCreepagesSaturateAtMuN) {
  const HertzContact h = patch();
  const KalkerCoefficients c = KalkerTable::shipped().at(h.a, h.b, 0.3);
  FastsimSettings fine;
  fine.cells_x = fine.strips = 200;
  for (TractionBound bound : {TractionBound::parabolic, TractionBound::elliptic}) {
    fine.bound = bound;
    const FastsimResult r = fastsim(c, kG, h.a, h.b, kLoad, kMu, {0.5, 0, 0}, fine);
    EXPECT_NEAR(-r.forces.Fx, kMu * kLoad, 2e-3 * kMu * kLoad);
    EXPECT_LT(r.adhesion_fraction, 0.01);
  }
}

TEST(Fastsim, GridConvergesAndTheAdhesionZoneLeads) {
  const HertzContact h = patch();
  const KalkerCoefficients c = KalkerTable::shipped().at(h.a, h.b, 0.3);
  const Creepages creep{1e-3, 0, 0};
  double previous_error = 1e300;
  FastsimSettings reference_grid;
  reference_grid.cells_x = reference_grid.strips = 640;
  const double reference = fastsim(c, kG, h.a, h.b, kLoad, kMu, creep, reference_grid).forces.Fx;
  for (int n : {10, 20, 40, 80}) {
    FastsimSettings grid;
    grid.cells_x = grid.strips = n;
    const FastsimResult r = fastsim(c, kG, h.a, h.b, kLoad, kMu, creep, grid);
    const double error = std::abs(r.forces.Fx - reference);
    EXPECT_LT(error, previous_error);
    previous_error = error;
    // Adhesion at the leading edge (+x), slip at the trailing edge, on the centre strip.
    const std::size_t centre = static_cast<std::size_t>(n / 2) * n;
    EXPECT_TRUE(r.adhesion[centre]);
    EXPECT_FALSE(r.adhesion[centre + n - 1]);
  }
  EXPECT_LT(previous_error, 0.01 * std::abs(reference));
}

TEST(Fastsim, ForcesAloneEqualTheFullSolution) {
  const HertzContact h = patch();
  const KalkerCoefficients c = KalkerTable::shipped().at(h.a, h.b, 0.3);
  FastsimSettings lean;
  lean.fields = false;
  const Creepages creep{1e-3, -5e-4, 0.3};
  const FastsimResult full = fastsim(c, kG, h.a, h.b, kLoad, kMu, creep);
  const FastsimResult forces = fastsim(c, kG, h.a, h.b, kLoad, kMu, creep, lean);
  EXPECT_EQ(forces.forces.Fx, full.forces.Fx);
  EXPECT_EQ(forces.forces.Fy, full.forces.Fy);
  EXPECT_EQ(forces.forces.Mz, full.forces.Mz);
  EXPECT_EQ(forces.adhesion_fraction, full.adhesion_fraction);
  EXPECT_TRUE(forces.px.empty());
}

}  // namespace
}  // namespace railfe
