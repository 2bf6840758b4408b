// The modal eigensolver's size rules (krylov_plan.hpp): no Krylov space may exceed the free DOFs
// less the modes already found, the parameter at fault is named, and the batch estimate of a
// frequency band recovers the mode count of spectra whose counting function is known in closed
// form (a clamped-free bar's axial modes, N ∝ f; Weyl's law for a 3-D body, N ∝ f³).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/modal/krylov_plan.hpp"

namespace railfe {
namespace {

TEST(KrylovPlan, AutomaticSpaceNeverExceedsTheFreeDofs) {
  for (long long free_dofs : {12LL, 120LL, 121LL, 1000LL}) {
    for (long long deflated : {0LL, 5LL}) {
      for (int modes = 1; modes < free_dofs - deflated; ++modes) {
        const KrylovPlan plan = plan_krylov_space(modes, 0, 0, free_dofs, deflated);
        if (!plan.problem.empty()) {
          EXPECT_EQ(plan.parameter, "Modes");
          continue;
        }
        EXPECT_LT(plan.dimension(), free_dofs - deflated) << modes << " of " << free_dofs;
        EXPECT_GT(plan.dimension(), modes) << "no block left to extend the space";
      }
    }
  }
}

TEST(KrylovPlan, TooManyModesNameModesAndTheFreeDofs) {
  // The case: a small bar (120 free DOFs of 132) asked for more modes than it has.
  const KrylovPlan plan = plan_krylov_space(200, 2, 0, 120);
  EXPECT_EQ(plan.parameter, "Modes");
  EXPECT_NE(plan.problem.find("120 free DOFs"), std::string::npos) << plan.problem;
  // The largest batch the message allows must itself be accepted.
  const int largest = largest_batch(2, 120);
  EXPECT_TRUE(plan_krylov_space(largest, 2, 0, 120).problem.empty());
  EXPECT_FALSE(plan_krylov_space(largest + 1, 2, 0, 120).problem.empty());
  const int automatic_largest = largest_batch(0, 120);
  EXPECT_TRUE(plan_krylov_space(automatic_largest, 0, 0, 120).problem.empty());
  EXPECT_FALSE(plan_krylov_space(automatic_largest + 1, 0, 0, 120).problem.empty());
}

TEST(KrylovPlan, ExplicitBlocksAreCheckedBothWays) {
  EXPECT_EQ(plan_krylov_space(10, 2, 5, 1000).parameter, "Krylov blocks");   // too few
  EXPECT_EQ(plan_krylov_space(10, 2, 100, 120).parameter, "Krylov blocks");  // too many
  // A space of all 120 free DOFs hangs Krylov-Schur; 118 (59 blocks of 2) is the largest.
  EXPECT_EQ(plan_krylov_space(10, 2, 60, 120).parameter, "Krylov blocks");
  EXPECT_TRUE(plan_krylov_space(10, 2, 59, 120).problem.empty());
}

TEST(KrylovPlan, BandBatchesGetFortyEightVectorsToSpare) {
  // The wheel's first band batch: 16 modes restarted in 48 vectors (82 operator applications)
  // and converged in one filling of 56 or 64 (58, 66).
  EXPECT_GE(plan_krylov_space(16, 0, 0, 100000, 0, band_space(16)).dimension(), 16 + 48);
  // Without a band the rule stays three times the modes (10 modes: 52 applications in 30
  // vectors, 60 in 58), and from 24 modes on the two agree.
  EXPECT_EQ(plan_krylov_space(10, 2, 0, 100000).dimension(), 30);
  EXPECT_EQ(plan_krylov_space(140, 8, 0, 100000, 0, band_space(140)).dimension(), 424);
  EXPECT_EQ(plan_krylov_space(140, 8, 0, 100000).dimension(), 424);
}

TEST(KrylovPlan, ContinuationSpaceIsSizedForTheWholeBand) {
  // The wheel's second batch: 118 modes beyond 16 found, 134 in the band as estimated. A space
  // for the 118 alone (3 x 118) restarts; one for all 134 converges in one filling.
  const KrylovPlan plan = plan_krylov_space(118, 0, 0, 102120, 16, band_space(134));
  EXPECT_EQ(plan.block_size, 8);
  EXPECT_GE(plan.dimension(), 3 * 134);
  EXPECT_LT(plan.dimension(), 3 * 134 + 8);
  // Never past the free DOFs less the modes found, however large the band.
  const KrylovPlan bounded = plan_krylov_space(30, 0, 0, 200, 50, band_space(400));
  EXPECT_TRUE(bounded.problem.empty()) << bounded.problem;
  EXPECT_LT(bounded.dimension(), 200 - 50);
  // A deck's Krylov blocks win over the band's size.
  EXPECT_EQ(plan_krylov_space(118, 8, 20, 102120, 16, band_space(134)).dimension(), 160);
}

TEST(KrylovPlan, BlockSizeGrowsWithTheBatch) {
  EXPECT_EQ(plan_krylov_space(10, 0, 0, 100000).block_size, 2);
  EXPECT_EQ(plan_krylov_space(40, 0, 0, 100000).block_size, 4);
  EXPECT_EQ(plan_krylov_space(140, 0, 0, 100000).block_size, 8);
  EXPECT_EQ(plan_krylov_space(140, 3, 0, 100000).block_size, 3);  // the deck's choice wins
}

// Counts of a spectrum f_k (k = 1, 2, ...) up to f.
int count_below(const std::vector<double>& spectrum, double f) {
  int n = 0;
  for (double value : spectrum)
    n += value <= f ? 1 : 0;
  return n;
}

// The estimate covers the band (no third batch) without computing more than ~40 % extra.
void expect_band_estimate(const std::vector<double>& spectrum, int first_batch, double band_high) {
  const std::vector<double> found(spectrum.begin(), spectrum.begin() + first_batch);
  const int in_band = count_below(spectrum, band_high);
  const int total = first_batch + next_band_batch(found, band_high, 8);
  EXPECT_GE(total, in_band);
  EXPECT_LE(total, 1.4 * in_band + 8);
}

TEST(KrylovPlan, BandEstimateOfABarFollowsNProportionalToF) {
  // Axial modes of a clamped-free bar: f_k = (2k - 1) c / 4L, c / 4L = 1293 Hz (steel, 1 m).
  std::vector<double> spectrum;
  for (int k = 1; k <= 400; ++k)
    spectrum.push_back((2 * k - 1) * 1293.0);
  expect_band_estimate(spectrum, automatic_first_batch(100000), 200e3);
  expect_band_estimate(spectrum, 32, 200e3);
}

TEST(KrylovPlan, BandEstimateOfASolidFollowsWeylsLaw) {
  // Weyl: N(f) = C f³, so f_k = (k / C)^(1/3); C from a 0.05 m³ steel body (c_L 5900, c_T 3200).
  const double pi = 3.141592653589793;
  const double C = 4.0 * pi / 3.0 * 0.05 * (1 / std::pow(5900.0, 3) + 2 / std::pow(3200.0, 3));
  std::vector<double> spectrum;
  for (int k = 1; k <= 2000; ++k)
    spectrum.push_back(std::cbrt(k / C));
  expect_band_estimate(spectrum, automatic_first_batch(100000), spectrum[299]);
  expect_band_estimate(spectrum, 32, spectrum[299]);
}

}  // namespace
}  // namespace railfe
