// Equivalent conicity by both routes against answers known in closed form: a pure cone (the
// cone's slope at every amplitude) and a rolling radius difference with a flange jump, whose
// harmonic regression is the describing function of a relay with dead zone.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/geometry/conicity.hpp"

namespace railfe {
namespace {

TEST(Conicity, BothRoutesGiveAConesSlopeAtEveryAmplitude) {
  const double gamma = 0.15, e = 0.75, r0 = 0.46;
  auto delta_r = [&](double y) { return 2 * gamma * y; };
  for (double amplitude : {0.001, 0.002, 0.004, 0.006}) {
    EXPECT_NEAR(regression_conicity(delta_r, amplitude), gamma, 1e-12 * gamma);
    const double lambda = kinematic_wavelength(delta_r, e, r0, amplitude);
    EXPECT_NEAR(lambda, klingel_wavelength(r0, e, gamma), 1e-6 * lambda);
    EXPECT_NEAR(equivalent_conicity(lambda, e, r0), gamma, 2e-6 * gamma);
  }
}

TEST(Conicity, RegressionAcrossAFlangeJumpIsTheDescribingFunction) {
  // dr = 2 gamma y plus a jump J at |y| = y_f. Over y = y_hat sin(phi) the least-squares slope
  // is 2 gamma + 4 J cos(asin(y_f / y_hat)) / (pi y_hat).
  const double gamma = 0.05, jump = 0.006, flange = 0.006;
  auto delta_r = [&](double y) {
    return 2 * gamma * y + (std::abs(y) > flange ? std::copysign(jump, y) : 0.0);
  };
  EXPECT_NEAR(regression_conicity(delta_r, 0.005), gamma, 1e-12);
  for (double amplitude : {0.007, 0.008, 0.010}) {
    const double expected =
        gamma + 2 * jump * std::cos(std::asin(flange / amplitude)) / (M_PI * amplitude);
    // 20000 phases resolve the jump's position to 1/20000 of a period.
    EXPECT_NEAR(regression_conicity(delta_r, amplitude, 20000), expected, 2e-3 * expected)
        << amplitude;
  }
}

}  // namespace
}  // namespace railfe
