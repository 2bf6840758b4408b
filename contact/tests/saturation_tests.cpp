// Shen-Hedrick-Elkins: the linear theory for small creepages, mu N from beta = 3 on, smooth
// (value and slope) where the two meet, and the direction of the linear force kept.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/laws/saturation.hpp"

namespace railfe {
namespace {

TEST(ShenHedrickElkins, LinearForSmallCreepagesAndMuNBeyondThree) {
  const double N = 1e5, mu = 0.3, limit = mu * N;
  const CreepForces small = shen_hedrick_elkins({-3, 4, 0.2}, N, mu);
  EXPECT_NEAR(small.Fx, -3, 3 * 5 / limit);  // relative change beta / 3
  EXPECT_NEAR(small.Fy, 4, 4 * 5 / limit);
  for (double beta : {3.0, 10.0, 1e6}) {
    const CreepForces f = shen_hedrick_elkins({-0.6 * beta * limit, 0.8 * beta * limit, 0}, N, mu);
    EXPECT_NEAR(std::hypot(f.Fx, f.Fy), limit, 1e-9 * limit);
    EXPECT_NEAR(f.Fy / f.Fx, -0.8 / 0.6, 1e-12);
  }
  // Continuous with a zero slope at beta = 3 (the cubic's maximum).
  const auto resultant = [&](double beta) {
    const CreepForces f = shen_hedrick_elkins({beta * limit, 0, 0}, N, mu);
    return f.Fx / limit;
  };
  EXPECT_NEAR(resultant(3 - 1e-6), 1, 1e-11);
  EXPECT_NEAR((resultant(3) - resultant(3 - 1e-4)) / 1e-4, 0, 1e-4);
}

}  // namespace
}  // namespace railfe
