#include "contact/geometry/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railfe {

namespace {

double dot(Vec2 a, Vec2 b) {
  return a.y * b.y + a.z * b.z;
}

/// The wheel point at one parameter, its foot on the rail, and the gap's derivatives along the
/// wheel: the search's merit function.
struct Evaluation {
  double s_wheel = 0, s_rail = 0;
  LocusPoint locus;
  CurveDerivatives rail;
  Vec2 normal;                  // unit outward rail normal at the foot
  double gap = 0;               // signed distance along the normal (negative: penetration)
  double slope = 0;             // d gap / d s_wheel: condition 2, the normal against the tangent
  double curvature = 0;         // d2 gap / d s_wheel2 (positive: the gap is locally convex)
  double relative_lateral = 0;  // rail + wheel profile curvature, convex positive
};

// Condition 1 alone: the foot of \p point on the rail (its tangent orthogonal to the distance),
// by Newton on the squared distance, which is convex near a rail that curves less than the
// distance to it.
double rail_foot(const ProfileCurve& rail, Vec2 point, double s, CurveDerivatives& foot) {
  const double lower = rail.begin(), upper = rail.end();
  for (int i = 0; i < 40; ++i) {
    foot = rail.at(s);
    const Vec2 d{point.y - foot.p.y, point.z - foot.p.z};
    const double f = dot(foot.d1, d);
    // The derivative of f, kept at least half the tangent's squared length so the step always
    // reduces the distance (a wheel point never lies near the rail's centres of curvature).
    const double df =
        std::min(dot(foot.d2, d) - dot(foot.d1, foot.d1), -0.5 * dot(foot.d1, foot.d1));
    const double next = std::clamp(s - f / df, lower, upper);
    if (std::abs(next - s) <= 1e-15 * (1 + std::abs(s)))
      return next;
    s = next;
  }
  foot = rail.at(s);
  return s;
}

Evaluation evaluate(const WheelRailGeometry& geometry, TrackSide side, const WheelsetPose& pose,
                    double s_wheel, double s_rail) {
  Evaluation e;
  e.s_wheel = s_wheel;
  e.locus = geometry.locus(side, s_wheel, pose);
  const Vec2 point{e.locus.y.v, e.locus.z.v};
  e.s_rail = rail_foot(geometry.rail(side), point, s_rail, e.rail);
  const CurveDerivatives& r = e.rail;
  const Vec2 d{point.y - r.p.y, point.z - r.p.z};
  const Vec2 tw{e.locus.y.d, e.locus.z.d}, ww{e.locus.y.dd, e.locus.z.dd};
  const double speed = std::hypot(r.d1.y, r.d1.z);
  e.normal = {r.d1.z / speed, -r.d1.y / speed};
  e.gap = dot(e.normal, d);
  e.slope = dot(e.normal, tw);
  // The foot moves with the wheel point as condition 1 demands: ds_rail/ds_wheel.
  const double foot_rate = -dot(r.d1, tw) / (dot(r.d2, d) - dot(r.d1, r.d1));
  const Vec2 raw_turn{r.d2.z / speed, -r.d2.y / speed};
  const double along = dot(raw_turn, e.normal);
  const Vec2 normal_turn{raw_turn.y - along * e.normal.y, raw_turn.z - along * e.normal.z};
  e.curvature = dot(e.normal, ww) + dot(normal_turn, tw) * foot_rate;
  // Rail: convex where the curve turns into the rail; wheel: convex where its locus turns away
  // from its outward normal (down), i.e. the opposite sign in the same plane.
  e.relative_lateral = signed_curvature(r.d1, r.d2) - signed_curvature(tw, ww);
  return e;
}

// The contact point of evaluation \p e (status left to the caller).
ContactPoint point_of(const WheelRailGeometry&, TrackSide side, bool flange, const Evaluation& e) {
  ContactPoint point;
  point.flange = flange;
  point.s_wheel = e.s_wheel;
  point.s_rail = e.s_rail;
  point.rail_point = e.rail.p;
  point.x = e.locus.x;
  point.gap = e.gap;
  point.normal = e.normal;
  const double towards_centre = side == TrackSide::right ? -1.0 : 1.0;
  point.contact_angle = std::atan2(towards_centre * e.normal.y, -e.normal.z);
  point.rolling_radius = e.locus.radius;
  point.wheel_rolling_curvature = e.locus.rolling_curvature;
  point.rail_lateral_curvature = signed_curvature(e.rail.d1, e.rail.d2);
  point.wheel_lateral_curvature = e.relative_lateral - point.rail_lateral_curvature;
  return point;
}

}  // namespace

ContactPoint contact_at(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                        const WheelsetPose& pose, double s_wheel, double s_rail) {
  ContactPoint point =
      point_of(geometry, side, flange, evaluate(geometry, side, pose, s_wheel, s_rail));
  point.status = SearchStatus::converged;
  return point;
}

std::string status_name(SearchStatus status) {
  switch (status) {
    case SearchStatus::converged:
      return "converged";
    case SearchStatus::part_boundary:
      return "part boundary";
    case SearchStatus::not_a_minimum:
      return "not a minimum";
    case SearchStatus::not_converged:
      return "not converged";
  }
  return "?";
}

std::array<double, 2> searched_range(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                                     const SearchSettings& settings) {
  const auto part = geometry.part_range(side, flange);
  const double first = std::max(part[0], settings.first), last = std::min(part[1], settings.last);
  return first < last ? std::array<double, 2>{first, last} : part;
}

ContactPoint search_contact(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                            const WheelsetPose& pose, double s_wheel, double s_rail,
                            const SearchSettings& settings) {
  const auto range = searched_range(geometry, side, flange, settings);
  Evaluation e = evaluate(geometry, side, pose, std::clamp(s_wheel, range[0], range[1]), s_rail);
  double radius = settings.trust_radius;
  bool converged = false, blocked = false;
  int iteration = 0;
  while (iteration < settings.max_iterations) {
    ++iteration;
    const double newton = -e.slope / e.curvature;
    const bool convex = e.curvature > 0;
    // Converged when the Newton correction of a convex gap is negligible, or the slope is zero
    // to round-off (a stationary point, perhaps not a minimum: reported as such below).
    if ((convex && std::abs(newton) <= settings.tolerance) ||
        std::abs(e.slope) <= 4 * std::numeric_limits<double>::epsilon()) {
      e = evaluate(geometry, side, pose,
                   std::clamp(e.s_wheel + (convex ? newton : 0.0), range[0], range[1]), e.s_rail);
      converged = true;
      break;
    }
    double step = newton;
    if (settings.use_trust_region) {
      // Where the gap is not convex the model has no minimum: go downhill to the radius.
      if (!convex)
        step = e.slope > 0 ? -radius : radius;
      step = std::clamp(step, -radius, radius);
    } else if (!std::isfinite(step)) {
      break;
    }
    const double trial_s = std::clamp(e.s_wheel + step, range[0], range[1]);
    const double taken = trial_s - e.s_wheel;
    if (taken == 0) {  // held at the part's end by a gap that falls outwards
      blocked = true;
      break;
    }
    const Evaluation trial = evaluate(geometry, side, pose, trial_s, e.s_rail);
    bool accept = true;
    if (settings.use_trust_region) {
      const double predicted = e.slope * taken + 0.5 * e.curvature * taken * taken;
      const double actual = trial.gap - e.gap;
      const double ratio = predicted < 0 ? actual / predicted : (actual < 0 ? 1.0 : -1.0);
      if (ratio < 0.25)
        radius = 0.25 * std::abs(taken);
      else if (ratio > 0.75 && std::abs(taken) >= 0.99 * radius)
        radius *= 2;
      // Close to a convex minimum the gap's change drowns in round-off; the slope still shows
      // the progress.
      accept = ratio > 1e-4 ||
               (convex && trial.curvature > 0 && std::abs(trial.slope) < 0.5 * std::abs(e.slope));
    }
    if (accept)
      e = trial;
    else if (radius <= settings.tolerance)
      break;
  }
  ContactPoint point = point_of(geometry, side, flange, e);
  point.iterations = iteration;
  const bool at_end = e.s_wheel <= range[0] || e.s_wheel >= range[1];
  if (blocked || (at_end && !converged))
    point.status = SearchStatus::part_boundary;
  else if (!converged)
    point.status = SearchStatus::not_converged;
  else if (e.curvature <= 0)
    point.status = SearchStatus::not_a_minimum;
  else
    point.status = SearchStatus::converged;
  return point;
}

GapSample least_gap_sample(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                           const WheelsetPose& pose, int samples, const SearchSettings& settings) {
  const auto range = searched_range(geometry, side, flange, settings);
  const ProfileCurve& rail = geometry.rail(side);
  // The first wheel point's foot starts from the nearest of a few rail points; each later one
  // from its neighbour's foot.
  const LocusPoint first = geometry.locus(side, range[0], pose);
  double s_rail = rail.begin(), nearest = 1e300;
  for (int k = 0; k <= 100; ++k) {
    const double s = rail.begin() + (rail.end() - rail.begin()) * k / 100;
    const Vec2 p = rail.at(s).p;
    const double distance = std::hypot(first.y.v - p.y, first.z.v - p.z);
    if (distance < nearest) {
      nearest = distance;
      s_rail = s;
    }
  }
  GapSample best{range[0], s_rail, 1e300};
  for (int i = 0; i <= samples; ++i) {
    const double s = range[0] + (range[1] - range[0]) * i / std::max(samples, 1);
    const Evaluation e = evaluate(geometry, side, pose, s, s_rail);
    s_rail = e.s_rail;
    if (e.gap < best.gap)
      best = {s, e.s_rail, e.gap};
  }
  return best;
}

}  // namespace railfe
