// Closest-point projection on bilinear faces against exact answers (a flat square, where the
// nearest point is the clamped coordinates) and against a brute-force search in long double: a
// dense grid of the natural coordinates, zoomed in around its best sample until the spacing is
// below 1e-13 (no derivatives, no Newton, so nothing shared with the method under test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "contact/search/quad_projection.hpp"
#include "framework/base/error.hpp"

namespace railfe {
namespace {

using Corners = std::array<std::array<double, 3>, 4>;

std::array<const double*, 4> pointers(const Corners& c) {
  return {c[0].data(), c[1].data(), c[2].data(), c[3].data()};
}

struct Reference {
  double xi, eta, distance;
  std::array<double, 3> point;
};

// The bilinear map in long double, from corner 0: the distance's minimum is flat (quadratic), so
// locating it to 1e-9 by comparing values needs more than double's 16 digits.
std::array<long double, 3> surface(const Corners& c, long double xi, long double eta) {
  const long double n[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4,
                            (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
  std::array<long double, 3> s{};
  for (int a = 1; a < 4; ++a)
    for (int d = 0; d < 3; ++d)
      s[d] += n[a] * (static_cast<long double>(c[a][d]) - c[0][d]);
  return s;
}

long double squared_distance(const Corners& c, long double xi, long double eta, const double* x) {
  const auto s = surface(c, xi, eta);
  long double sum = 0;
  for (int d = 0; d < 3; ++d) {
    const long double r = s[d] - (static_cast<long double>(x[d]) - c[0][d]);
    sum += r * r;
  }
  return sum;
}

Reference brute_force(const Corners& c, const double* x) {
  long double best_xi = 0, best_eta = 0, best = squared_distance(c, 0, 0, x);
  long double centre_xi = 0, centre_eta = 0, half_width = 1;
  int intervals = 200;
  while (half_width > 1e-14L) {
    const long double lo_xi = std::max(-1.0L, centre_xi - half_width);
    const long double hi_xi = std::min(1.0L, centre_xi + half_width);
    const long double lo_eta = std::max(-1.0L, centre_eta - half_width);
    const long double hi_eta = std::min(1.0L, centre_eta + half_width);
    for (int i = 0; i <= intervals; ++i)
      for (int j = 0; j <= intervals; ++j) {
        const long double xi = lo_xi + (hi_xi - lo_xi) * i / intervals;
        const long double eta = lo_eta + (hi_eta - lo_eta) * j / intervals;
        const long double value = squared_distance(c, xi, eta, x);
        if (value < best) {
          best = value;
          best_xi = xi;
          best_eta = eta;
        }
      }
    centre_xi = best_xi;
    centre_eta = best_eta;
    half_width = 2 * half_width * 2 / intervals;  // two spacings either side of the best
    intervals = 16;
  }
  const auto s = surface(c, best_xi, best_eta);
  return {double(best_xi),
          double(best_eta),
          double(std::sqrt(best)),
          {double(s[0] + c[0][0]), double(s[1] + c[0][1]), double(s[2] + c[0][2])}};
}

double diagonal(const Corners& c) {
  return std::hypot(c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]);
}

// The projection's nearest point is the brute force's within 1e-9 of the face size, its
// distance is never longer, and for an interior point the normal is along x − point.
void expect_matches_brute_force(const Corners& c, const double* x) {
  const QuadProjection p = project_onto_quad(pointers(c), x);
  const Reference r = brute_force(c, x);
  const double size = diagonal(c);
  // Round-off of coordinates far from the origin, against a face of millimetres.
  const double roundoff = 1e-15 * (std::hypot(x[0], x[1], x[2]) + size);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(p.point[d], r.point[d], 1e-9 * size)
        << "x = (" << x[0] << ", " << x[1] << ", " << x[2] << "), xi " << p.xi << " vs " << r.xi
        << ", eta " << p.eta << " vs " << r.eta << ", on_boundary " << p.on_boundary;
  EXPECT_LE(p.distance, r.distance * (1 + 1e-12) + roundoff);
  EXPECT_NEAR(p.distance, r.distance, 1e-12 * size);
  EXPECT_LE(std::abs(p.xi), 1.0);
  EXPECT_LE(std::abs(p.eta), 1.0);
  EXPECT_NEAR(std::hypot(p.normal[0], p.normal[1], p.normal[2]), 1, 1e-14);
  if (!p.on_boundary) {
    EXPECT_NEAR(std::abs(p.gap), p.distance, 1e-10 * size);
  }
  EXPECT_LE(std::abs(p.gap), p.distance * (1 + 1e-14) + roundoff);
}

const Corners kUnitSquare = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
// A hyperbolic paraboloid: opposite corners lifted by 0.3 (warp angle about 17 degrees).
const Corners kWarped = {{{0, 0, 0}, {1, 0, 0.3}, {1, 1, 0}, {0, 1, 0.3}}};

TEST(QuadProjection, FlatSquareInteriorIsExact) {
  const double x[3] = {0.3, 0.6, 0.25};
  const QuadProjection p = project_onto_quad(pointers(kUnitSquare), x);
  EXPECT_NEAR(p.xi, -0.4, 1e-15);
  EXPECT_NEAR(p.eta, 0.2, 1e-15);
  EXPECT_NEAR(p.point[0], 0.3, 1e-15);
  EXPECT_NEAR(p.point[1], 0.6, 1e-15);
  EXPECT_NEAR(p.point[2], 0.0, 1e-15);
  EXPECT_NEAR(p.normal[2], 1.0, 1e-15);
  EXPECT_NEAR(p.gap, 0.25, 1e-15);
  EXPECT_NEAR(p.distance, 0.25, 1e-15);
  EXPECT_FALSE(p.on_boundary);
  EXPECT_LE(p.iterations, 3);
}

TEST(QuadProjection, FlatSquareBeyondEachEdgeAndCornerAndBehind) {
  // On a flat square the nearest point is the clamped in-plane coordinates; gap = z.
  for (double x0 : {-0.7, 0.4, 1.3})
    for (double y0 : {-0.2, 0.55, 1.9})
      for (double z0 : {0.35, -0.15}) {
        const double x[3] = {x0, y0, z0};
        const QuadProjection p = project_onto_quad(pointers(kUnitSquare), x);
        const double px = std::clamp(x0, 0.0, 1.0), py = std::clamp(y0, 0.0, 1.0);
        EXPECT_NEAR(p.point[0], px, 1e-15);
        EXPECT_NEAR(p.point[1], py, 1e-15);
        EXPECT_NEAR(p.point[2], 0.0, 1e-15);
        EXPECT_NEAR(p.xi, 2 * px - 1, 1e-15);
        EXPECT_NEAR(p.eta, 2 * py - 1, 1e-15);
        EXPECT_NEAR(p.gap, z0, 1e-15) << "gap is along the face normal";
        EXPECT_NEAR(p.distance, std::hypot(x0 - px, y0 - py, z0), 1e-15);
        EXPECT_EQ(p.on_boundary, px != x0 || py != y0);
      }
}

TEST(QuadProjection, NormalFollowsTheNodeOrder) {
  const Corners reversed = {kUnitSquare[0], kUnitSquare[3], kUnitSquare[2], kUnitSquare[1]};
  const double x[3] = {0.5, 0.5, 0.1};
  const QuadProjection p = project_onto_quad(pointers(reversed), x);
  EXPECT_NEAR(p.normal[2], -1.0, 1e-15);
  EXPECT_NEAR(p.gap, -0.1, 1e-15) << "a point in front of the other side is behind this face";
}

TEST(QuadProjection, WarpedFaceMatchesBruteForceOnAGrid) {
  // Points on both sides, inside and beyond every edge and corner.
  for (double x0 = -0.4; x0 <= 1.41; x0 += 0.2)
    for (double y0 = -0.4; y0 <= 1.41; y0 += 0.2)
      for (double z0 : {-0.3, -0.05, 0.0, 0.15, 0.5}) {
        const double x[3] = {x0, y0, z0};
        expect_matches_brute_force(kWarped, x);
      }
}

TEST(QuadProjection, WarpedFaceCentreHasTheExactNormal) {
  // z = 0.3 (x + y − 2xy) through the four corners: at (0.5, 0.5) the gradient is zero, so the
  // normal is (0, 0, 1), and x − point along it.
  const double x[3] = {0.5, 0.5, 0.4};
  const QuadProjection p = project_onto_quad(pointers(kWarped), x);
  EXPECT_NEAR(p.point[2], 0.15, 1e-15);
  EXPECT_NEAR(p.normal[2], 1.0, 1e-15);
  EXPECT_NEAR(p.gap, 0.25, 1e-15);
}

TEST(QuadProjection, SkinnyFaceMatchesBruteForce) {
  // 1 m by 1 mm, slightly warped: aspect ratio 1000.
  const Corners skinny = {{{0, 0, 0}, {1, 0, 1e-4}, {1, 1e-3, 0}, {0, 1e-3, 1e-4}}};
  std::mt19937 random(15);
  std::uniform_real_distribution<double> along(-0.2, 1.2), across(-2e-3, 3e-3), height(-2e-3, 2e-3);
  for (int n = 0; n < 200; ++n) {
    const double x[3] = {along(random), across(random), height(random)};
    expect_matches_brute_force(skinny, x);
  }
}

TEST(QuadProjection, RandomFacesAndPointsMatchBruteForce) {
  std::mt19937 random(1501);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25), warp(-0.3, 0.3), around(-0.6, 1.6),
      height(-0.6, 0.6);
  for (int face = 0; face < 40; ++face) {
    Corners c = kUnitSquare;
    for (auto& corner : c) {
      corner[0] += jitter(random);
      corner[1] += jitter(random);
      corner[2] += warp(random);
    }
    for (int n = 0; n < 25; ++n) {
      const double x[3] = {around(random), around(random), height(random)};
      expect_matches_brute_force(c, x);
    }
  }
}

TEST(QuadProjection, SmallFaceFarFromTheOriginMatchesBruteForce) {
  // A 2 mm face warped by 0.04 mm at 0.5 m from the origin (a wheel tread's element): Newton
  // must converge quadratically although each coordinate carries 1e-16 m of round-off.
  Corners c = kWarped;
  c[1][2] = c[3][2] = 0.02;
  for (auto& corner : c)
    for (int d = 0; d < 3; ++d)
      corner[d] = corner[d] * 2e-3 + (d == 2 ? 0.46 : 0.13);
  std::mt19937 random(46);
  std::uniform_real_distribution<double> around(-1e-3, 3e-3), height(-1e-3, 1e-3);
  for (int n = 0; n < 200; ++n) {
    const double x[3] = {0.13 + around(random), 0.13 + around(random), 0.46 + height(random)};
    expect_matches_brute_force(c, x);
    const QuadProjection p = project_onto_quad(pointers(c), x);
    EXPECT_LE(p.iterations, 6);
  }
}

TEST(QuadProjection, ShapeFunctionsInterpolateTheFace) {
  const double x[3] = {0.2, 0.7, -0.3};
  const QuadProjection p = project_onto_quad(pointers(kWarped), x);
  const auto n = quad_shape_functions(p.xi, p.eta);
  EXPECT_NEAR(n[0] + n[1] + n[2] + n[3], 1.0, 1e-15);
  for (int d = 0; d < 3; ++d) {
    double interpolated = 0;
    for (int a = 0; a < 4; ++a)
      interpolated += n[a] * kWarped[a][d];
    EXPECT_NEAR(interpolated, p.point[d], 1e-15);
  }
  const double corner_xi[4] = {-1, 1, 1, -1}, corner_eta[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      EXPECT_EQ(quad_shape_functions(corner_xi[a], corner_eta[a])[b], a == b ? 1.0 : 0.0);
}

TEST(QuadProjection, CollapsedCornerUsesTheCentreNormal) {
  // Corners 2 and 3 at one point (a hex8 collapsed to a wedge): the normal at that corner is
  // undefined; the centre's is used.
  const Corners wedge = {{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 1, 0}}};
  const double x[3] = {0.5, 1.4, -0.2};
  const QuadProjection p = project_onto_quad(pointers(wedge), x);
  EXPECT_NEAR(p.normal[2], 1.0, 1e-15);
  EXPECT_NEAR(p.gap, -0.2, 1e-15);
  EXPECT_TRUE(p.on_boundary);
}

TEST(QuadProjection, FaceCollapsedToALineIsARunError) {
  const Corners line = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}};
  const double x[3] = {0.5, 0.5, 0.5};
  EXPECT_THROW(project_onto_quad(pointers(line), x), RunError);
}

}  // namespace
}  // namespace railfe
