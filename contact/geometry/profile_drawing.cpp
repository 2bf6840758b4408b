#include "contact/geometry/profile_drawing.hpp"

#include <stdexcept>

#include "contact/geometry/rail_drawing.hpp"
#include "contact/geometry/wheel_drawing.hpp"

namespace railfe {

namespace {

// Dense enough that the spline through the points follows a 13 mm gauge corner to well under a
// micrometre, and the drawing's joins (where the curvature jumps) ring over a few tenths of a
// millimetre only.
constexpr double kSpacing = 2e-4;

}  // namespace

std::vector<std::string> profile_drawing_names(ProfileType role) {
  return role == ProfileType::wheel ? wheel_drawing_names() : rail_drawing_names();
}

std::vector<std::array<double, 2>> profile_drawing_points(const std::string& name,
                                                          ProfileType role) {
  std::vector<std::array<double, 2>> points;
  if (role == ProfileType::wheel) {
    for (const SectionPoint& p : sample_segments(wheel_outline(name).segments, kSpacing, true))
      points.push_back({p[0], p[1]});
    return points;
  }
  // The head runs from u > 0 to u < 0: y = -u lists it from the gauge side of a right rail
  // (the section is symmetric), and z = -v puts its top at z = 0, downwards positive.
  for (const SectionPoint& p : sample_segments(rail_head(rail_outline(name)), kSpacing, true))
    points.push_back({-p[0], -p[1]});
  return points;
}

std::shared_ptr<const ProfileCurve> drawing_curve(const std::string& name, ProfileType role) {
  return spline_curve(profile_drawing_points(name, role));
}

}  // namespace railfe
