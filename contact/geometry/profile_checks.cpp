#include "contact/geometry/profile_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

using Point = std::array<double, 2>;

double cross(Point o, Point a, Point b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Whether segments ab and cd share a point (collinear ones when their extents overlap). Cross
// products within round-off of zero count as zero, so straight runs of points are collinear:
// the round-off grows with the distance between the segments, not with their lengths, so it is
// measured against the square of the four points' extent.
bool segments_cross(Point a, Point b, Point c, Point d) {
  double extent = 0;
  for (const Point& p : {b, c, d})
    extent = std::max(extent, std::hypot(p[0] - a[0], p[1] - a[1]));
  const double scale = extent * extent;
  auto sign = [&](double v) { return v > 1e-12 * scale ? 1 : (v < -1e-12 * scale ? -1 : 0); };
  const int s1 = sign(cross(c, d, a)), s2 = sign(cross(c, d, b));
  const int s3 = sign(cross(a, b, c)), s4 = sign(cross(a, b, d));
  if (s1 == 0 && s2 == 0) {
    for (int k = 0; k < 2; ++k)
      if (std::max(std::min(a[k], b[k]), std::min(c[k], d[k])) >
          std::min(std::max(a[k], b[k]), std::max(c[k], d[k])))
        return false;
    return true;
  }
  return s1 * s2 <= 0 && s3 * s4 <= 0;
}

// Signed turn (degrees) from segment i-1..i to segment i..i+1.
double turn_degrees(const std::vector<Point>& p, std::size_t i) {
  const double a = std::atan2(p[i][1] - p[i - 1][1], p[i][0] - p[i - 1][0]);
  const double b = std::atan2(p[i + 1][1] - p[i][1], p[i + 1][0] - p[i][0]);
  return std::remainder(b - a, 2 * M_PI) * 180 / M_PI;
}

std::string where(const std::vector<Point>& p, const std::vector<int>& lines, std::size_t i) {
  std::ostringstream text;
  text.precision(6);
  if (i < lines.size() && lines[i] > 0)
    text << "line " << lines[i] << ", ";
  text << "point " << i + 1 << " (y = " << p[i][0] * 1e3 << " mm, z = " << p[i][1] * 1e3 << " mm)";
  return text.str();
}

}  // namespace

void check_profile(std::vector<Point>& points, const std::vector<int>& lines,
                   const std::string& source, const ProfileReadSettings& settings) {
  auto fail = [&](std::size_t i, const std::string& problem, const std::string& allowed) {
    throw_input_error(source, where(points, lines, i), problem, allowed);
  };
  if (points.size() < 3)
    throw_input_error(source, "", std::to_string(points.size()) + " profile points", "at least 3");
  for (std::size_t i = 1; i < points.size(); ++i)
    if (std::hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]) < 1e-9)
      fail(i, "repeats the point before it", "distinct points (remove the duplicate)");
  // A loop is a crossing of two segments that are not neighbours; O(n^2) is fine for the few
  // thousand points of a measured profile.
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    for (std::size_t j = i + 2; j + 1 < points.size(); ++j)
      if (segments_cross(points[i], points[i + 1], points[j], points[j + 1]))
        fail(j, "the profile crosses itself (a loop) here and at " + where(points, lines, i),
             "a profile that does not cross itself");
  // A measured rail head may overhang (y turns back along its gauge face), so y need not be
  // monotonic; but a list that reverses its direction of travel between two segments has
  // points out of order.
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const double turn = turn_degrees(points, i);
    if (std::abs(turn) > 90) {
      std::ostringstream problem;
      problem.precision(3);
      problem << "the list turns back by " << std::abs(turn) << " degrees: points out of order";
      fail(i + 1, problem.str(), "points listed in order along the profile");
    }
  }
  for (int pass = 0; pass < settings.smoothing_passes; ++pass) {
    std::vector<Point> smoothed = points;
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
      smoothed[i][1] = 0.25 * points[i - 1][1] + 0.5 * points[i][1] + 0.25 * points[i + 1][1];
    points = std::move(smoothed);
  }
  const std::string hint = "or set the profile's smoothing passes to filter it";
  for (std::size_t i = 1; i + 2 < points.size(); ++i) {
    const double a = turn_degrees(points, i), b = turn_degrees(points, i + 1);
    if (a * b < 0 && std::abs(a) > settings.zigzag_angle_degrees &&
        std::abs(b) > settings.zigzag_angle_degrees) {
      std::ostringstream problem;
      problem.precision(3);
      problem << "zig-zag: the profile turns " << a << " then " << b << " degrees";
      fail(i, problem.str(),
           "turns below " + std::to_string(static_cast<int>(settings.zigzag_angle_degrees)) +
               " degrees (remove the outlier " + hint + ")");
    }
  }
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const double a = turn_degrees(points, i);
    if (std::abs(a) > settings.kink_angle_degrees) {
      std::ostringstream problem;
      problem.precision(3);
      problem << "kink: the profile turns " << a << " degrees at one point";
      fail(i, problem.str(),
           "turns below " + std::to_string(static_cast<int>(settings.kink_angle_degrees)) +
               " degrees (add points along the corner " + hint + ")");
    }
  }
}

}  // namespace railfe
