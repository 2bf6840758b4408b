// The rail's lateral deviation over a displaced structure: the closed forms against a numerical
// convolution of the structure's shape with the Green's function of a beam on an elastic
// foundation, and against the beam equation itself.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/common/structure_deviation.hpp"

namespace railfe {
namespace {

StructureDeviationSettings settings(DeviationShape shape) {
  StructureDeviationSettings s;
  s.shape = shape;
  s.start = 50;
  s.span = 20;
  s.amplitude = 0.008;
  return s;
}

// ∫ G(x) w_s(s − x) dx by the midpoint rule on cells of 0.2 mm over ±8 m (G below 1e-6
// beyond), the cells' edges on the structure's kinks and offset for the s tested.
double convolved(const StructureDeviation& deviation, double s) {
  const double beta = deviation.beta(), h = 2e-4;
  const int n = 40000;
  double sum = 0;
  for (int k = -n; k < n; ++k) {
    const double x = (k + 0.5) * h, bx = beta * std::abs(x);
    const double g = 0.5 * beta * std::exp(-bx) * (std::cos(bx) + std::sin(bx));
    sum += g * deviation.structure(s - x);
  }
  return sum * h;
}

TEST(StructureDeviation, RailIsTheStructureConvolvedWithTheFoundationsGreensFunction) {
  for (DeviationShape shape : {DeviationShape::bending, DeviationShape::translation}) {
    const StructureDeviation deviation(settings(shape));
    // β of the published rail and pads: (4.6e7 / (4 · 2.1e11 · 509e-8))^(1/4).
    EXPECT_NEAR(deviation.beta(), std::pow(4.6e7 / (4 * 2.1e11 * 509e-8), 0.25), 1e-12);
    for (double s : {45.0, 49.5, 50.0, 50.7, 55.0, 69.0, 70.0, 71.2, 89.9, 90.0, 90.4, 95.0})
      EXPECT_NEAR(deviation.rail(s), convolved(deviation, s), 2e-9) << "s = " << s;
  }
}

TEST(StructureDeviation, FarFromTheSpanEndsTheRailFollowsTheStructure) {
  const StructureDeviation bent(settings(DeviationShape::bending));
  EXPECT_NEAR(bent.structure(70), 0.008, 1e-15);
  EXPECT_NEAR(bent.rail(60), bent.structure(60), 1e-9);
  EXPECT_NEAR(bent.rail(200), 0, 1e-15);
  // At a pier the rail stays Δs / (4β) inside the structure's corner.
  EXPECT_NEAR(bent.rail(70) - 0.008, -2 * 0.008 / 20 / (4 * bent.beta()), 1e-15);
  const StructureDeviation moved(settings(DeviationShape::translation));
  EXPECT_NEAR(moved.structure(80), 0.008, 1e-15);
  EXPECT_NEAR(moved.structure(91), 0, 1e-15);
  EXPECT_NEAR(moved.rail(90), 0.004, 1e-15);  // half-way down the smoothed offset
}

TEST(StructureDeviation, RailSatisfiesTheBeamOnElasticFoundation) {
  // EI w'''' + k (w − w_s) = 0 away from the kinks, by central differences of the fourth order.
  const StructureDeviationSettings s = settings(DeviationShape::translation);
  const StructureDeviation deviation(s);
  const double h = 0.02;
  for (double x : {48.0, 51.0, 69.0, 71.5, 88.8, 91.3}) {
    const double d4 =
        (deviation.rail(x + 2 * h) - 4 * deviation.rail(x + h) + 6 * deviation.rail(x) -
         4 * deviation.rail(x - h) + deviation.rail(x - 2 * h)) /
        std::pow(h, 4);
    const double residual = s.rail_modulus * s.rail_inertia * d4 +
                            s.pad_stiffness * (deviation.rail(x) - deviation.structure(x));
    EXPECT_NEAR(residual, 0, 1e-4 * s.pad_stiffness * 0.008) << "s = " << x;
  }
}

}  // namespace
}  // namespace railfe
