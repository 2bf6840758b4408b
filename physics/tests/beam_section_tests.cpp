// Section properties against independent references: the rectangle's torsion constant against
// the exact Saint-Venant series (Timoshenko & Goodier, Theory of Elasticity, §109), tube and
// I-section inertias composed from solid shapes, and Cowper's shear coefficients in their limits
// (rectangle 5/6 at ν = 0, thin ring 2(1+ν)/(4+3ν), thick tube → solid circle, I without flanges
// → rectangle).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "physics/elements/beam_section.hpp"

namespace railfe {
namespace {

constexpr double kPi = 3.14159265358979323846;

// J of a rectangle with sides a ≥ b from the exact series.
double exact_rectangle_torsion(double a, double b) {
  double sum = 0;
  for (int n = 1; n < 400; n += 2)
    sum += std::tanh(n * kPi * a / (2 * b)) / std::pow(n, 5);
  return a * b * b * b * (1.0 / 3 - 64 / std::pow(kPi, 5) * b / a * sum);
}

TEST(BeamSection, RectangleMatchesExactTorsionAndInertias) {
  for (double ratio : {1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 50.0}) {
    const double b = 0.02, a = ratio * b;
    // Roark's formula is within 0.19 % of the series (the square is the worst case).
    EXPECT_NEAR(rectangle_torsion_constant(a, b) / exact_rectangle_torsion(a, b), 1, 2e-3) << ratio;
    EXPECT_EQ(rectangle_torsion_constant(a, b), rectangle_torsion_constant(b, a));
  }
  const BeamSection s = rectangle_section(0.1, 0.3, 0.0);
  EXPECT_DOUBLE_EQ(s.area, 0.03);
  EXPECT_DOUBLE_EQ(s.iy, 0.1 * 0.027 / 12);
  EXPECT_DOUBLE_EQ(s.iz, 0.3 * 0.001 / 12);
  EXPECT_DOUBLE_EQ(s.shear_area_y / s.area, 5.0 / 6);  // the classical 5/6 at ν = 0
  EXPECT_DOUBLE_EQ(s.shear_area_z, s.shear_area_y);
}

TEST(BeamSection, CircleAndTube) {
  const double d = 0.2, t = 0.015, nu = 0.3;
  const BeamSection c = circle_section(d, nu);
  EXPECT_DOUBLE_EQ(c.area, kPi * d * d / 4);
  EXPECT_DOUBLE_EQ(c.torsion, kPi * std::pow(d, 4) / 32);
  EXPECT_DOUBLE_EQ(c.shear_area_y / c.area, 6 * 1.3 / 8.8);
  // A tube is the outer circle less the inner one.
  const BeamSection tube = tube_section(d, t, nu);
  const BeamSection inner = circle_section(d - 2 * t, nu);
  EXPECT_NEAR(tube.area / (c.area - inner.area), 1, 1e-14);
  EXPECT_NEAR(tube.iy / (c.iy - inner.iy), 1, 1e-13);
  EXPECT_NEAR(tube.torsion / (c.torsion - inner.torsion), 1, 1e-13);
  // Cowper's hollow circle: a pin hole gives the solid circle, a thin wall the thin ring.
  const BeamSection almost_solid = tube_section(d, d / 2 * (1 - 1e-6), nu);
  EXPECT_NEAR(almost_solid.shear_area_y / almost_solid.area, 6 * 1.3 / 8.8, 1e-9);
  const BeamSection thin = tube_section(d, d * 1e-6, nu);
  EXPECT_NEAR(thin.shear_area_z / thin.area, 2 * 1.3 / (4 + 3 * nu), 1e-5);
}

TEST(BeamSection, ISectionFromItsRectangles) {
  const double d = 0.3, b = 0.3, tf = 0.019, tw = 0.011, nu = 0.3;  // an HEB 300 without fillets
  const BeamSection s = i_section(d, b, tf, tw, nu);
  const double web = d - 2 * tf, arm = (d - tf) / 2;
  EXPECT_NEAR(s.area / (2 * b * tf + web * tw), 1, 1e-14);
  EXPECT_NEAR(s.iy / (2 * (b * tf * tf * tf / 12 + b * tf * arm * arm) + tw * web * web * web / 12),
              1, 1e-13);
  EXPECT_NEAR(s.iz / (2 * tf * b * b * b / 12 + web * tw * tw * tw / 12), 1, 1e-13);
  // Shear along the web is carried by the web: κ A within 15 % of the web's area h t_w.
  EXPECT_NEAR(s.shear_area_z / ((d - tf) * tw), 1, 0.15);
  // Vanishing flanges leave Cowper's rectangle.
  const BeamSection bare = i_section(d, tw, 1e-9, tw, nu);
  EXPECT_NEAR(bare.shear_area_z / bare.area, 10 * 1.3 / (12 + 11 * nu), 1e-6);
}

TEST(BeamSection, EulerBernoulliLimitAndChecks) {
  const BeamSection s = euler_bernoulli(rectangle_section(0.1, 0.2, 0.3));
  EXPECT_TRUE(std::isinf(s.shear_area_y) && std::isinf(s.shear_area_z));
  EXPECT_NO_THROW(check_section(s));
  BeamSection bad = s;
  bad.iy = 0;
  EXPECT_THROW(check_section(bad), std::invalid_argument);
  EXPECT_THROW(rectangle_section(-0.1, 0.2, 0.3), std::invalid_argument);
  EXPECT_THROW(tube_section(0.1, 0.06, 0.3), std::invalid_argument);
  EXPECT_THROW(i_section(0.1, 0.1, 0.06, 0.01, 0.3), std::invalid_argument);
  EXPECT_THROW(circle_section(0.1, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace railfe
