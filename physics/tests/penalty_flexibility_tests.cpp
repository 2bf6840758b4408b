// The penalty layer's tangential flexibility against the patch's own: on a Hertz pressure
// sampled over a flat master grid, the pressure-weighted second moments give the ellipse's
// semi-axes, the penalty flexibility is the nodes' A/k, and the patch's is Kalker's
// 8a / (3 C11 G) with C11 = 4.12 for a circle at ν = 0.25 (Kalker 1990, Table E.3).

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "contact/enforcement/penalty_contact_pair.hpp"
#include "physics/common/penalty_flexibility.hpp"

namespace railfe {
namespace {

constexpr double kFace = 1e-3;      // master face size (m)
constexpr int kFaces = 40;          // per side, centred on the origin
constexpr double kPitch = 0.25e-3;  // slave spacing (m)
constexpr double kStiffness = 4e8;  // N/m per face
constexpr double kPeak = 1e9;       // Pa

struct Patch {
  std::vector<double> x;
  PenaltyContactPair pair;
};

// A slave grid pressed into the master with the Hertz pressure of an a x b ellipse (x rolling).
Patch hertz_patch(double a, double b, FrictionLaw friction, bool uniform = false) {
  PenaltyPairGeometry geometry;
  std::vector<double> x;
  const int n = kFaces + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      x.insert(x.end(), {(i - kFaces / 2) * kFace, (j - kFaces / 2) * kFace, 0.0});
  for (int j = 0; j < kFaces; ++j)
    for (int i = 0; i < kFaces; ++i)
      geometry.master_faces.push_back(
          {j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
  geometry.face_stiffness.assign(geometry.master_faces.size(), kStiffness);
  const double area = kPitch * kPitch;
  for (double sy = -b + 0.5 * kPitch; sy < b; sy += kPitch)
    for (double sx = -a + 0.5 * kPitch; sx < a; sx += kPitch) {
      const double r2 = (sx / a) * (sx / a) + (sy / b) * (sy / b);
      if (r2 >= 1)
        continue;
      const double force = kPeak * (uniform ? 1.0 : std::sqrt(1 - r2)) * area;
      geometry.slave_nodes.push_back(static_cast<int>(x.size() / 3));
      geometry.slave_area.push_back(area);
      x.insert(x.end(), {sx, sy, -force / kStiffness});
    }
  geometry.n_surface_nodes = static_cast<int>(x.size() / 3);
  geometry.mass.assign(geometry.n_surface_nodes, 1e-3);
  PenaltyPairSettings settings;
  settings.name = "hertz";
  settings.friction = friction;
  settings.search_margin = 2e-3;
  PenaltyContactPair pair(geometry, settings);
  std::vector<double> du(x.size(), 0.0), force(x.size(), 0.0);
  pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
  return {x, std::move(pair)};
}

TEST(PenaltyFlexibility, HertzPatchGivesItsSemiAxesAndKalkersFlexibility) {
  const double a = 6e-3, b = 9e-3, G = 80e9, nu = 0.25;
  const Patch patch = hertz_patch(a, b, {FrictionLaw::Kind::coulomb, 0.3, 0, 0});
  const PenaltyFlexibility result = penalty_flexibility(patch.pair, G, nu);
  EXPECT_NEAR(result.rolling_semi_axis, a, 0.01 * a);
  EXPECT_NEAR(result.lateral_semi_axis, b, 0.01 * b);
  EXPECT_NEAR(result.penalty, kPitch * kPitch / kStiffness, 1e-12 * kPitch * kPitch / kStiffness);
  // Kalker's Table E.3 at a/b = 2/3, ν = 0.25 lies between 3.72 (0.6) and 3.81 (0.7).
  const double c11 = 8 * result.rolling_semi_axis / (3 * G * result.patch);
  EXPECT_GT(c11, 3.72);
  EXPECT_LT(c11, 3.81);
}

TEST(PenaltyFlexibility, CircleMatchesKalkersC11) {
  const double a = 5e-3, G = 80e9, nu = 0.25;
  const Patch patch = hertz_patch(a, a, {FrictionLaw::Kind::coulomb, 0.3, 0, 0});
  const PenaltyFlexibility result = penalty_flexibility(patch.pair, G, nu);
  const double expected = 8 * a / (3 * 4.12 * G);  // Kalker: C11 = 4.12 at a = b, ν = 0.25
  EXPECT_NEAR(result.patch, expected, 0.01 * expected);
  EXPECT_NEAR(result.ratio(), (kPitch * kPitch / kStiffness) / expected, 0.01 * result.ratio());
}

TEST(PenaltyFlexibility, NoRatioWithoutAPatchThatSticks) {
  // Too few nodes: a patch smaller than the slave pitch twice over.
  const Patch tiny =
      hertz_patch(0.6 * kPitch, 0.6 * kPitch, {FrictionLaw::Kind::coulomb, 0.3, 0, 0});
  EXPECT_LT(tiny.pair.totals().active, 4);
  EXPECT_EQ(penalty_flexibility(tiny.pair, 80e9, 0.25).ratio(), 0.0);
  // A line contact (a/b beyond Kalker's table) has no ellipse to compare with.
  const Patch line = hertz_patch(0.4e-3, 9e-3, {FrictionLaw::Kind::coulomb, 0.3, 0, 0});
  EXPECT_GE(line.pair.totals().active, 4);
  EXPECT_EQ(penalty_flexibility(line.pair, 80e9, 0.25).ratio(), 0.0);
}

TEST(PenaltyFlexibility, NoRatioForAFlatBlock) {
  // A uniform pressure (a block on a plane): not a rolling patch, whatever its size.
  Patch patch = hertz_patch(6e-3, 9e-3, {FrictionLaw::Kind::coulomb, 0.3, 0, 0}, true);
  EXPECT_GE(patch.pair.totals().active, 100);
  EXPECT_EQ(penalty_flexibility(patch.pair, 80e9, 0.25).ratio(), 0.0);
}

}  // namespace
}  // namespace railfe
