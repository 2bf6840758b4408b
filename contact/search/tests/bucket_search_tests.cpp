// The bucket search and the choice of a slave node's master face, on a wheel-tread-like surface
// (a patch of a surface of revolution, 40 x 40 quadrilaterals, nodes jittered so that faces are
// warped): candidates against a loop over every face's box, the chosen face against a loop over
// every face's projection, and the gap along paths across shared edges and corners against the
// Lipschitz bound of a signed distance (|Δgap| <= |Δx|), which any jump would break.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "contact/search/bucket_search.hpp"
#include "framework/base/error.hpp"

namespace railfe {
namespace {

constexpr int kCells = 40;              // faces per direction
constexpr double kWheelRadius = 0.46;   // m
constexpr double kProfileRadius = 0.3;  // m, the tread's lateral curvature
constexpr double kArc = 0.2;            // rad of the wheel
constexpr double kWidth = 0.08;         // m

struct Surface {
  std::vector<double> positions;  // x, y, z per node
  std::vector<std::array<int, 4>> faces;
  double face_size = 0;  // m, about
};

int node_index(int i, int j) {
  return i * (kCells + 1) + j;
}

// Nodes on the tread (outward normal with the natural order) moved along the radius by up to
// \p jitter of a face; \p inward reverses every face's node order, so that from the front the
// edges are concave.
Surface tread(double jitter, bool inward) {
  Surface s;
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> bump(-jitter, jitter);
  s.face_size = kWheelRadius * kArc / kCells;
  for (int i = 0; i <= kCells; ++i)
    for (int j = 0; j <= kCells; ++j) {
      const double angle = -kArc / 2 + kArc * i / kCells;
      const double y = -kWidth / 2 + kWidth * j / kCells;
      const double radius = kWheelRadius - kProfileRadius +
                            std::sqrt(kProfileRadius * kProfileRadius - y * y) +
                            bump(random) * s.face_size;
      s.positions.insert(s.positions.end(),
                         {radius * std::sin(angle), y, radius * std::cos(angle)});
    }
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      std::array<int, 4> f = {node_index(i, j), node_index(i + 1, j), node_index(i + 1, j + 1),
                              node_index(i, j + 1)};
      if (inward)
        std::swap(f[1], f[3]);
      s.faces.push_back(f);
    }
  return s;
}

const double* node(const Surface& s, int i, int j) {
  return &s.positions[3 * node_index(i, j)];
}

// The outward unit radial direction at a point (the tread's normal, near enough for offsets).
std::array<double, 3> radial(const double* p) {
  const double r = std::hypot(p[0], p[2]);
  return {p[0] / r, 0, p[2] / r};
}

ContactPoint brute_force(const Surface& s, const double* x) {
  ContactPoint best;
  for (int f = 0; f < static_cast<int>(s.faces.size()); ++f) {
    const auto& n = s.faces[f];
    const auto p = project_onto_quad({&s.positions[3 * n[0]], &s.positions[3 * n[1]],
                                      &s.positions[3 * n[2]], &s.positions[3 * n[3]]},
                                     x);
    if (best.face < 0 || p.distance < best.projection.distance)
      best = {f, p, false};
  }
  return best;
}

TEST(BucketSearch, CandidatesAreExactlyTheGrownBoxesHoldingThePoint) {
  const Surface s = tread(0.1, false);
  BucketSearch search(s.faces);
  const double capture = 0.3 * s.face_size;
  search.rebuild(s.positions.data(), capture);
  EXPECT_EQ(search.capture_distance(), capture);
  EXPECT_LE(search.entries(), 8 * s.faces.size()) << "a grown box spans about 2 cells a direction";
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<int> found;
  for (int n = 0; n < 2000; ++n) {
    const double x[3] = {(u(random) - 0.5) * 0.25, (u(random) - 0.5) * 0.1,
                         kWheelRadius - 0.01 + 0.02 * u(random)};
    search.candidates(x, found);
    std::vector<int> expected;
    for (int f = 0; f < static_cast<int>(s.faces.size()); ++f) {
      bool inside = true;
      for (int d = 0; d < 3; ++d) {
        double lo = 1e300, hi = -1e300;
        for (int k : s.faces[f]) {
          lo = std::min(lo, s.positions[3 * k + d]);
          hi = std::max(hi, s.positions[3 * k + d]);
        }
        inside = inside && x[d] >= lo - capture && x[d] <= hi + capture;
      }
      if (inside)
        expected.push_back(f);
    }
    EXPECT_EQ(found, expected);
  }
}

TEST(BucketSearch, ContactPointIsTheNearestOfAllFaces) {
  for (bool inward : {false, true}) {
    const Surface s = tread(0.1, inward);
    BucketSearch search(s.faces);
    const double capture = 0.5 * s.face_size;
    search.rebuild(s.positions.data(), capture);
    std::mt19937 random(11);
    std::uniform_int_distribution<int> index(1, kCells - 1);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<int> scratch;
    for (int n = 0; n < 3000; ++n) {
      // Near a node, off the surface by up to the capture distance, either side.
      const double* base = node(s, index(random), index(random));
      const auto out = radial(base);
      const double offset = 0.95 * capture * u(random);
      const double x[3] = {base[0] + 0.5 * s.face_size * u(random) + offset * out[0],
                           base[1] + 0.5 * s.face_size * u(random), base[2] + offset * out[2]};
      const ContactPoint found = find_contact_point(search, s.positions.data(), x, scratch);
      const ContactPoint expected = brute_force(s, x);
      ASSERT_GE(found.face, 0) << "a point within the capture distance has a face";
      EXPECT_EQ(found.face, expected.face);
      EXPECT_EQ(found.projection.distance, expected.projection.distance);
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(found.projection.point[d], expected.projection.point[d]);
      EXPECT_NEAR(std::abs(found.projection.gap), found.projection.distance, 1e-12 * s.face_size)
          << "inside the patch the gap is the signed distance";
      EXPECT_FALSE(found.beyond_free_edge);
    }
  }
}

// Slides a point from the centre of face (i, j) to the centre of face (i + di, j + dj), at a
// height h along the radius, in many steps; the gap of a signed distance moves no more than the
// point does, and its sign is the side. Returns how many steps had their nearest point on an
// edge or corner.
int expect_continuous_gap(const Surface& s, const BucketSearch& search, int i, int j, int di,
                          int dj, double height, bool inward) {
  auto centre = [&](int a, int b) {
    std::array<double, 3> c{};
    for (const auto* p :
         {node(s, a, b), node(s, a + 1, b), node(s, a + 1, b + 1), node(s, a, b + 1)})
      for (int d = 0; d < 3; ++d)
        c[d] += p[d] / 4;
    return c;
  };
  const auto from = centre(i, j), to = centre(i + di, j + dj);
  std::vector<int> scratch;
  constexpr int kSteps = 20000;
  double previous_gap = 0;
  std::array<double, 3> previous{};
  int boundary_points = 0;
  for (int k = 0; k <= kSteps; ++k) {
    const double t = double(k) / kSteps;
    std::array<double, 3> x;
    for (int d = 0; d < 3; ++d)
      x[d] = from[d] + t * (to[d] - from[d]);
    const auto out = radial(x.data());
    for (int d = 0; d < 3; ++d)
      x[d] += height * out[d];
    const ContactPoint c = find_contact_point(search, s.positions.data(), x.data(), scratch);
    if (c.face < 0) {
      ADD_FAILURE() << "lost between faces at step " << k;
      return boundary_points;
    }
    const double side = inward ? -height : height;
    // The nodes stray from the straight path by up to 0.1 of a face (jitter): only higher paths
    // have a known side.
    if (std::abs(height) > 0.2 * s.face_size) {
      EXPECT_GT(c.projection.gap * side, 0) << "step " << k;
    }
    boundary_points += c.projection.on_boundary;
    if (k > 0) {
      const double moved = std::hypot(x[0] - previous[0], x[1] - previous[1], x[2] - previous[2]);
      EXPECT_LE(std::abs(c.projection.gap - previous_gap), moved * (1 + 1e-9) + 1e-12 * s.face_size)
          << "gap jumps at step " << k << " (height " << height << ", inward " << inward << ")";
    }
    previous_gap = c.projection.gap;
    previous = x;
  }
  return boundary_points;
}

TEST(BucketSearch, GapIsContinuousAcrossSharedEdgesAndCorners) {
  for (bool inward : {false, true}) {
    const Surface s = tread(0.1, inward);
    BucketSearch search(s.faces);
    search.rebuild(s.positions.data(), 0.5 * s.face_size);
    for (double height : {0.3, 0.05, 0.001, -0.001, -0.05, -0.3}) {
      const double h = height * s.face_size;
      const int on_edges = expect_continuous_gap(s, search, 10, 20, 1, 0, h, inward) +  // edge
                           expect_continuous_gap(s, search, 10, 20, 0, 1, h, inward) +  // edge
                           expect_continuous_gap(s, search, 10, 20, 1, 1, h, inward) +  // corner
                           expect_continuous_gap(s, search, 25, 7, 1, -1, h, inward);   // corner
      // Radially outside, the tread is convex: the paths cross the edges' own regions, so the
      // rule for edges (outside with the outward faces, penetrated with the inward ones) was
      // exercised.
      if (height >= 0.3) {
        EXPECT_GT(on_edges, 1000) << "inward " << inward;
      }
    }
  }
}

TEST(BucketSearch, PointOnASharedEdgeGetsOneFaceOnly) {
  const Surface s = tread(0.1, false);
  BucketSearch search(s.faces);
  search.rebuild(s.positions.data(), 0.5 * s.face_size);
  std::vector<int> scratch;
  // Midpoints of the edge between faces (10, 20) and (11, 20), and of the corner node (12, 5),
  // lifted along the radius.
  const double* a = node(s, 11, 20);
  const double* b = node(s, 11, 21);
  for (double height : {0.0, 0.2 * s.face_size, -0.2 * s.face_size}) {
    for (const std::array<double, 3>& base :
         {std::array<double, 3>{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2},
          std::array<double, 3>{node(s, 12, 5)[0], node(s, 12, 5)[1], node(s, 12, 5)[2]}}) {
      const auto out = radial(base.data());
      const double x[3] = {base[0] + height * out[0], base[1], base[2] + height * out[2]};
      const ContactPoint first = find_contact_point(search, s.positions.data(), x, scratch);
      const ContactPoint again = find_contact_point(search, s.positions.data(), x, scratch);
      ASSERT_GE(first.face, 0);
      EXPECT_EQ(first.face, again.face) << "deterministic";
      EXPECT_EQ(first.projection.gap, again.projection.gap);
      // Every face sharing the point is a candidate, but one is chosen: the nearest (ties
      // to the smallest index), and the gap agrees with the signed distance.
      EXPECT_EQ(first.face, brute_force(s, x).face);
      EXPECT_NEAR(std::abs(first.projection.gap), first.projection.distance, 1e-15);
      if (height == 0) {
        EXPECT_NEAR(first.projection.gap, 0, 1e-15);
      }
    }
  }
}

TEST(BucketSearch, BeyondTheSurfacesEdgeTheGapFollowsTheFaceNormal) {
  // A point behind the last face sliding off the patch: the gap stays continuous (measured
  // along the face normal), and the flag tells the caller.
  const Surface s = tread(0.0, false);
  BucketSearch search(s.faces);
  search.rebuild(s.positions.data(), 0.5 * s.face_size);
  std::vector<int> scratch;
  const double* edge = node(s, 20, kCells);
  double previous = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double beyond = (k / 1000.0 - 0.5) * 0.4 * s.face_size;
    const double x[3] = {edge[0] * (1 - 0.001), edge[1] + beyond, edge[2] * (1 - 0.001)};
    const ContactPoint c = find_contact_point(search, s.positions.data(), x, scratch);
    ASSERT_GE(c.face, 0);
    // The tread's lateral slope tilts the normal by 0.13 there, which moves the boundary of the
    // edge's region by 0.13 × 0.46 mm: the flag is only sure a little away from it.
    if (std::abs(beyond) > 0.05 * s.face_size) {
      EXPECT_EQ(c.beyond_free_edge, beyond > 0) << "beyond " << beyond;
    }
    if (k > 0) {
      EXPECT_LE(std::abs(c.projection.gap - previous), 0.4 * s.face_size / 1000 * (1 + 1e-9));
    }
    previous = c.projection.gap;
  }
}

TEST(BucketSearch, FarPointsHaveNoFace) {
  const Surface s = tread(0.1, false);
  BucketSearch search(s.faces);
  search.rebuild(s.positions.data(), 0.5 * s.face_size);
  std::vector<int> scratch;
  const double x[3] = {0, 0, 2 * kWheelRadius};
  EXPECT_EQ(find_contact_point(search, s.positions.data(), x, scratch).face, -1);
  const double nan[3] = {std::nan(""), 0, kWheelRadius};
  EXPECT_EQ(find_contact_point(search, s.positions.data(), nan, scratch).face, -1);
}

TEST(BucketSearch, RefusesBadFacesAndBadPositions) {
  try {
    BucketSearch({{0, 1, 2, 3}, {4, 5, 5, 6}});
    FAIL() << "a face repeating a node must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("master face 1 (nodes 4, 5, 5, 6) repeats node 5"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(BucketSearch({{0, -1, 2, 3}}), InputError);
  Surface s = tread(0.1, false);
  BucketSearch search(s.faces);
  EXPECT_THROW(search.rebuild(s.positions.data(), -1e-3), std::invalid_argument);
  s.positions[3 * 17 + 1] = std::nan("");
  EXPECT_THROW(search.rebuild(s.positions.data(), 1e-3), RunError);
}

}  // namespace
}  // namespace railfe
