#include "contact/geometry/wheel_rail_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

namespace {

constexpr int kSamples = 4000;

// The parameter of the extreme (smallest when smallest is set, else largest) value of coordinate
// \p coordinate, to a sampling step refined by bisection on the derivative.
double extreme_parameter(const ProfileCurve& curve, int coordinate, bool smallest) {
  const double a = curve.begin(), b = curve.end();
  auto value = [&](double s) {
    const Vec2 p = curve.at(s).p;
    const double v = coordinate == 0 ? p.y : p.z;
    return smallest ? v : -v;
  };
  double best = a, best_value = value(a);
  for (int i = 1; i <= kSamples; ++i) {
    const double s = a + (b - a) * i / kSamples;
    if (value(s) < best_value) {
      best = s;
      best_value = value(s);
    }
  }
  // Golden-section refinement within one sample either side.
  const double h = (b - a) / kSamples;
  double lo = std::max(a, best - h), hi = std::min(b, best + h);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 60; ++i) {
    const double s1 = hi - g * (hi - lo), s2 = lo + g * (hi - lo);
    if (value(s1) < value(s2))
      hi = s2;
    else
      lo = s1;
  }
  return (lo + hi) / 2;
}

// The sample to split a wheel at, given the curvatures \p k and the most concave sample \p peak:
// the peak, unless the root there is a circular arc (a drawn profile's), concave alike all along,
// whose middle is taken instead: its ends, where the spline through its points rings, would put
// most of the root in one part.
std::size_t root_middle(const std::array<double, 401>& k, std::size_t peak) {
  std::size_t first = peak, last = peak;
  while (first > 0 && k[first - 1] >= 0.8 * k[peak])
    --first;
  while (last + 1 < k.size() && k[last + 1] >= 0.8 * k[peak])
    ++last;
  const std::size_t middle = (first + last) / 2;
  const auto alike = std::count_if(k.begin() + first, k.begin() + last + 1, [&](double value) {
    return std::abs(value - k[middle]) <= 0.02 * k[middle];
  });
  const bool arc = last - first >= 4 && alike >= 0.8 * (last - first + 1);
  return arc ? middle : peak;
}

}  // namespace

double parameter_where(const ProfileCurve& curve, int coordinate, double value, double from,
                       double to) {
  auto f = [&](double s) {
    const Vec2 p = curve.at(s).p;
    return (coordinate == 0 ? p.y : p.z) - value;
  };
  const int n = 2000;
  double s0 = from, f0 = f(from);
  for (int i = 1; i <= n; ++i) {
    const double s1 = from + (to - from) * i / n, f1 = f(s1);
    if ((f0 <= 0) != (f1 <= 0)) {
      double lo = s0, hi = s1, flo = f0;
      for (int k = 0; k < 80; ++k) {
        const double mid = (lo + hi) / 2, fm = f(mid);
        if ((fm <= 0) == (flo <= 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      return (lo + hi) / 2;
    }
    s0 = s1;
    f0 = f1;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

WheelRailGeometry::WheelRailGeometry(std::shared_ptr<const ProfileCurve> rail,
                                     std::shared_ptr<const ProfileCurve> wheel,
                                     const TrackLayout& track, const WheelsetLayout& wheelset)
    : track_(track), wheelset_(wheelset) {
  // Right rail: cant the top towards the track centre (-y), then put its gauge point at
  // y = gauge / 2 and its top at z = 0.
  Placement cant;
  cant.angle = track.profile_inclined ? 0.0 : -std::atan(track.inclination);
  std::shared_ptr<const ProfileCurve> canted = placed_curve(rail, cant);
  const double s_top = extreme_parameter(*canted, 1, true);
  const double z_top = canted->at(s_top).p.z;
  const double s_gauge =
      parameter_where(*canted, 1, z_top + track.gauge_depth, s_top, canted->begin());
  if (std::isnan(s_gauge))
    throw std::invalid_argument(
        "the rail profile does not reach the gauge depth on its gauge side");
  Placement right_rail = cant;
  right_rail.offset = {track.gauge / 2 - canted->at(s_gauge).p.y, -z_top};
  rails_[1] = placed_curve(rail, right_rail);
  rails_[0] = placed_curve(rails_[1], {true, 0, {0, 0}, true});

  // Right wheel: eta = B/2 + (y_back - y), rho = r0 + z; listed in increasing eta.
  Placement right_wheel;
  right_wheel.mirror_y = true;
  right_wheel.offset = {wheelset.back_to_back / 2 + wheelset.flange_back, wheelset.nominal_radius};
  right_wheel.reverse = true;
  wheels_[1] = placed_curve(wheel, right_wheel);
  wheels_[0] = placed_curve(wheels_[1], {true, 0, {0, 0}, true});

  for (int side = 0; side < 2; ++side) {
    const ProfileCurve& w = *wheels_[side];
    const double eta_running =
        (side == 1 ? 1 : -1) * (wheelset.back_to_back / 2 + wheelset.flange_back);
    running_[side] = parameter_where(w, 0, eta_running, w.begin(), w.end());
    if (std::isnan(running_[side]))
      throw std::invalid_argument("the wheel profile does not reach its running point (y = 0)");
    // The flange tip is the largest radius; the split is the most concave point between it and
    // the running point (concave: the profile turns towards its outward normal).
    const double s_tip = extreme_parameter(w, 1, false);
    const double lo = std::min(s_tip, running_[side]), hi = std::max(s_tip, running_[side]);
    std::array<double, 401> k;
    for (std::size_t i = 0; i < k.size(); ++i)
      k[i] = signed_curvature(w, lo + (hi - lo) * i / 400);
    const std::size_t peak = std::max_element(k.begin(), k.end()) - k.begin();
    const double best_curvature = k[peak];
    const double best = lo + (hi - lo) * root_middle(k, peak) / 400;
    // A profile without a concave flange root (a cone, a cylinder) is all tread.
    const bool flange_first = side == 1;
    split_[side] = best_curvature > 1e-9 ? best : (flange_first ? w.begin() : w.end());
  }
}

std::array<double, 2> WheelRailGeometry::part_range(TrackSide side, bool flange) const {
  const ProfileCurve& w = wheel(side);
  const double split = flange_split(side);
  // The right wheel's flange lies towards the track centre (small eta, the start of s).
  const bool flange_first = side == TrackSide::right;
  if (flange == flange_first)
    return {w.begin(), split};
  return {split, w.end()};
}

LocusPoint WheelRailGeometry::locus(TrackSide side, double s, const WheelsetPose& pose) const {
  // The axle after roll about x, then yaw about z.
  const double cos_roll = std::cos(pose.roll);
  const double a[3] = {-std::sin(pose.yaw) * cos_roll, std::cos(pose.yaw) * cos_roll,
                       std::sin(pose.roll)};
  // e1: the axle-normal direction closest to straight down; e2 = a x e1.
  double e1[3] = {-a[2] * a[0], -a[2] * a[1], 1 - a[2] * a[2]};
  const double n1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (double& v : e1)
    v /= n1;
  const double e2[3] = {a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2],
                        a[0] * e1[1] - a[1] * e1[0]};
  const CurveJets j = curve_jets(wheel(side), s);
  // The point of the circle at eta(s) whose surface normal has no x component:
  // cos(theta) e1x + sin(theta) e2x = a_x rho' / eta'.
  const Jet u = (a[0] * j.dz) / (std::hypot(e1[0], e2[0]) * j.dy);
  const double theta0 = std::atan2(e2[0], e1[0]);
  auto wrapped = [](double t) { return std::remainder(t, 2 * M_PI); };
  const double plus = theta0 + (M_PI / 2 - std::asin(u.v)),
               minus = theta0 - (M_PI / 2 - std::asin(u.v));
  const double sign = std::abs(wrapped(plus)) <= std::abs(wrapped(minus)) ? 1.0 : -1.0;
  const Jet theta = Jet::constant(theta0 + sign * M_PI / 2) - sign * asin(u);
  const Jet c = cos(theta), sn = sin(theta);
  const double centre[3] = {0, pose.lateral, pose.vertical - wheelset_.nominal_radius};
  LocusPoint point;
  const Jet ry = c * Jet::constant(e1[1]) + sn * Jet::constant(e2[1]);
  const Jet rz = c * Jet::constant(e1[2]) + sn * Jet::constant(e2[2]);
  point.y = Jet::constant(centre[1]) + a[1] * j.y + j.z * ry;
  point.z = Jet::constant(centre[2]) + a[2] * j.y + j.z * rz;
  point.x = a[0] * j.y.v + j.z.v * (c.v * e1[0] + sn.v * e2[0]);
  point.radius = j.z.v;
  point.rolling_curvature = j.dy.v / (std::hypot(j.dy.v, j.dz.v) * j.z.v);
  return point;
}

}  // namespace railfe
