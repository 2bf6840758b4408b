// Shen-Hedrick-Elkins: the linear theory for small creepages, mu N from beta = 3 on, smooth
// (value and slope) where the two meet, and the direction of the linear force kept.
// Polach: Kalker's linear theory for small creepages (pure longitudinal, lateral and spin, and
// combined creepage), mu Q at large creepage, the falling friction law where the patch slides,
// the reduction factors' slope, and the spin force's rise and fall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/laws/hertz.hpp"
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

// The issue's patch: 0.46 m wheel on a 0.30 m crown, 100 kN, steel.
struct IssuePatch {
  double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu)), load = 1e5;
  HertzContact h =
      hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({E, nu}, {E, nu}), load);
  KalkerCoefficients c = KalkerTable(RAILFE_KALKER_TABLE).at(h.a, h.b, nu);
};

TEST(Polach, KalkersLinearTheoryForSmallCreepages) {
  const IssuePatch p;
  for (const Creepages& s :
       {Creepages{1e-8, 0, 0}, Creepages{0, -1e-8, 0}, Creepages{0, 0, 1e-6}}) {
    const CreepForces linear = kalker_linear(p.c, p.G, p.h.a, p.h.b, s);
    const CreepForces f = polach(p.c, p.G, p.h.a, p.h.b, p.load, s);
    const double size = std::hypot(linear.Fx, linear.Fy);
    EXPECT_NEAR(f.Fx, linear.Fx, 1e-5 * size);
    EXPECT_NEAR(f.Fy, linear.Fy, 1e-5 * size);
    EXPECT_TRUE(std::isnan(f.Mz));
  }
  // Combined creepage: the linear resultant's size, along the creepage (Polach's c_jj).
  const Creepages combined{3e-8, 4e-8, 0};
  const CreepForces linear = kalker_linear(p.c, p.G, p.h.a, p.h.b, combined);
  const CreepForces f = polach(p.c, p.G, p.h.a, p.h.b, p.load, combined);
  EXPECT_NEAR(std::hypot(f.Fx, f.Fy), std::hypot(linear.Fx, linear.Fy),
              1e-5 * std::hypot(linear.Fx, linear.Fy));
  EXPECT_NEAR(f.Fy / f.Fx, 4.0 / 3, 1e-12);
}

TEST(Polach, SaturatesAtTheFrictionOfTheSlipVelocity) {
  const IssuePatch p;
  PolachParameters coulomb;
  coulomb.friction = 0.3;
  const CreepForces full = polach(p.c, p.G, p.h.a, p.h.b, p.load, {0.3, 0.4, 0}, coulomb);
  EXPECT_NEAR(std::hypot(full.Fx, full.Fy), 0.3 * p.load, 1e-6 * p.load);
  EXPECT_NEAR(full.Fy / full.Fx, 0.4 / 0.3, 1e-12);
  // Friction falling from 0.3 to 0.12 with slip velocity: where the patch slides (epsilon above
  // 1e3, so (2/pi)(eps/(1+eps^2) + atan eps) is 1 within 1e-8) the force follows mu(w) itself.
  PolachParameters falling = coulomb;
  falling.friction_ratio = 0.4;
  falling.friction_decay = 0.6;
  falling.rolling_speed = 3;
  for (double xi : {0.2, 0.5, 1.0}) {
    const double mu = 0.3 * (0.6 * std::exp(-0.6 * 3 * xi) + 0.4);
    const CreepForces f = polach(p.c, p.G, p.h.a, p.h.b, p.load, {xi, 0, 0}, falling);
    EXPECT_NEAR(-f.Fx, mu * p.load, 1e-6 * p.load) << xi;
  }
}

TEST(Polach, ReductionFactorsScaleTheInitialSlope) {
  const IssuePatch p;
  PolachParameters reduced;
  reduced.adhesion_reduction = 0.8;
  reduced.slip_reduction = 0.4;
  const Creepages small{1e-8, 0, 0};
  const double slope = polach(p.c, p.G, p.h.a, p.h.b, p.load, small, reduced).Fx;
  EXPECT_NEAR(slope / kalker_linear(p.c, p.G, p.h.a, p.h.b, small).Fx, (0.8 + 0.4) / 2, 1e-6);
  reduced.slip_reduction = 0.9;  // k_S > k_A
  EXPECT_THROW(polach(p.c, p.G, p.h.a, p.h.b, p.load, small, reduced), std::invalid_argument);
}

TEST(Polach, SpinForceRisesThenFallsToZero) {
  const IssuePatch p;
  std::vector<double> force;
  for (double phi = 0.25; phi < 1e4; phi *= 2)
    force.push_back(-polach(p.c, p.G, p.h.a, p.h.b, p.load, {0, 0, phi}).Fy);
  const auto peak = std::max_element(force.begin(), force.end());
  EXPECT_GT(peak - force.begin(), 0);
  EXPECT_LT(peak - force.begin(), static_cast<long>(force.size()) - 1);
  EXPECT_LT(*peak, 0.3 * p.load);
  EXPECT_LT(force.back(), 1e-2 * *peak);
}

}  // namespace
}  // namespace railfe
