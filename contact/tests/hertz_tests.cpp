// Hertz against the exact solution of the wheel-on-crown case and the sphere on a flat
// in closed form; the inverse problems return the forward one.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "contact/laws/hertz.hpp"

namespace railfe {
namespace {

const double kSteel = contact_modulus({210e9, 0.3}, {210e9, 0.3});

TEST(Hertz, WheelOnRailCrownMatchesTheExactSolution) {
  // Wheel radius 0.46 m rolling (x), rail crown 0.30 m lateral (y), 100 kN, steel E 210 GPa,
  // nu 0.3: a = 7.162 mm, b = 5.387 mm, p0 = 1237.6 MPa, approach 104.1 um (issue 6), within
  // 0.1 %.
  const HertzContact c = hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), kSteel, 1e5);
  EXPECT_NEAR(c.a, 7.162e-3, 7.162e-6);
  EXPECT_NEAR(c.b, 5.387e-3, 5.387e-6);
  EXPECT_NEAR(c.pressure, 1237.6e6, 1237.6e3);
  EXPECT_NEAR(c.approach, 104.1e-6, 104.1e-9);
  EXPECT_NEAR(c.stiffness, c.load / std::pow(c.approach, 1.5), 1e-9 * c.stiffness);
  // The same bodies turned by 90 degrees: the ellipse turns with them.
  const HertzContact turned = hertz_contact(1 / (2 * 0.30), 1 / (2 * 0.46), kSteel, 1e5);
  EXPECT_NEAR(turned.a, c.b, 1e-12);
  EXPECT_NEAR(turned.b, c.a, 1e-12);
}

TEST(Hertz, SphereOnFlatInClosedForm) {
  // A sphere of radius R on a flat: A = B = 1 / (2R); a = (3 N R / 4 E*)^(1/3),
  // delta = a^2 / R, p0 = 3 N / (2 pi a^2).
  for (double R : {0.01, 0.46}) {
    for (double N : {1.0, 1e5}) {
      const HertzContact c = hertz_contact(1 / (2 * R), 1 / (2 * R), kSteel, N);
      const double a = std::cbrt(3 * N * R / (4 * kSteel));
      EXPECT_NEAR(c.a, a, 1e-12 * a);
      EXPECT_NEAR(c.b, a, 1e-12 * a);
      EXPECT_NEAR(c.approach, a * a / R, 1e-12 * a * a / R);
      EXPECT_NEAR(c.pressure, 3 * N / (2 * M_PI * a * a), 1e-12 * c.pressure);
    }
  }
  // Nearly circular: no loss of digits as the ellipse approaches the circle.
  const HertzContact near = hertz_contact(1.0, 1.0 + 1e-9, kSteel, 1e4);
  const HertzContact exact = hertz_contact(1.0, 1.0, kSteel, 1e4);
  EXPECT_NEAR(near.approach, exact.approach, 1e-8 * exact.approach);
}

TEST(Hertz, InverseProblemsReturnTheForwardOne) {
  const HertzContact c = hertz_contact(1.087, 6.3, kSteel, 8e4);
  const HertzContact from_approach = hertz_from_approach(c.A, c.B, kSteel, c.approach);
  EXPECT_NEAR(from_approach.load, c.load, 1e-9 * c.load);
  EXPECT_NEAR(from_approach.a, c.a, 1e-9 * c.a);
  const HertzContact from_axes = hertz_from_semi_axes(c.a, c.b, kSteel, c.load);
  EXPECT_NEAR(from_axes.A, c.A, 1e-9 * c.A);
  EXPECT_NEAR(from_axes.B, c.B, 1e-9 * c.B);
  EXPECT_NEAR(from_axes.pressure, c.pressure, 1e-9 * c.pressure);
  EXPECT_NEAR(from_axes.approach, c.approach, 1e-9 * c.approach);
  // Conformal or separating geometry has no Hertzian contact.
  EXPECT_THROW(hertz_contact(1.0, -0.1, kSteel, 1e4), std::invalid_argument);
  EXPECT_THROW(hertz_contact(1.0, 1.0, kSteel, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace railfe

namespace railfe {
namespace {

TEST(Hertz, ArithmeticGeometricMeanGivesTheCompleteEllipticIntegrals) {
  // K(m) and E(m), m = 1 − g², from mpmath's ellipk and ellipe at 30 digits (m formed exactly
  // there): std::comp_ellint_1/2 take e = √(1 − g²), which loses g's digits as g falls, and
  // comp_ellint_2 is 1.5e-13 off at g = 0.2.
  struct Reference {
    double g, K, E;
  };
  const Reference references[] = {{0.999, 1.5715822161760173374, 1.5700110268553830724},
                                  {0.9, 1.6546166675225269145, 1.4932901081312072032},
                                  {0.5, 2.1565156474996432354, 1.2110560275684595248},
                                  {0.2, 3.0161124924776474373, 1.0505022269844500518},
                                  {0.05, 4.3841432321341594754, 1.0048564047864903648},
                                  {0.01, 5.9915893405069963815, 1.0002745824306629652},
                                  {1e-4, 10.596634757087660272, 1.0000000504831738439},
                                  {1e-8, 19.806975105072256325, 1.0000000000000009653},
                                  {1.0, M_PI / 2, M_PI / 2}};
  for (const Reference& r : references) {
    const CompleteEllipticIntegrals f = complete_elliptic_integrals(r.g);
    EXPECT_NEAR(f.K, r.K, 4e-15 * r.K) << "g = " << r.g;
    EXPECT_NEAR(f.E, r.E, 4e-15 * r.E) << "g = " << r.g;
  }
}

}  // namespace
}  // namespace railfe
