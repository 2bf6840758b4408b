#include "contact/geometry/contact_search.hpp"

#include <algorithm>
#include <cmath>

namespace railfe {

namespace {

struct Conditions {
  double f[2];              // the two contact conditions
  double J[2][2];           // their derivatives in (s_wheel, s_rail)
  double gap;               // normal distance along the unit rail normal
  Vec2 normal;              // unit outward rail normal
  double rail_lateral;      // rail profile curvature, convex positive
  double relative_lateral;  // wheel + rail lateral curvature (positive: the gap is a minimum)
};

Conditions evaluate(const WheelRailGeometry& geometry, Side side, const WheelsetPose& pose,
                    double s_wheel, double s_rail, LocusPoint& locus, CurveDerivatives& rail) {
  locus = geometry.locus(side, s_wheel, pose);
  rail = geometry.rail(side).at(s_rail);
  const Vec2 d{locus.y.v - rail.p.y, locus.z.v - rail.p.z};
  const Vec2 tw{locus.y.d, locus.z.d}, ww{locus.y.dd, locus.z.dd};
  const Vec2 nr{rail.d1.z, -rail.d1.y}, dnr{rail.d2.z, -rail.d2.y};
  auto dot = [](Vec2 a, Vec2 b) { return a.y * b.y + a.z * b.z; };
  Conditions c;
  c.f[0] = dot(rail.d1, d);
  c.f[1] = dot(nr, tw);
  c.J[0][0] = dot(rail.d1, tw);
  c.J[0][1] = dot(rail.d2, d) - dot(rail.d1, rail.d1);
  c.J[1][0] = dot(nr, ww);
  c.J[1][1] = dot(dnr, tw);
  const double rail_speed = std::hypot(rail.d1.y, rail.d1.z);
  c.normal = {nr.y / rail_speed, nr.z / rail_speed};
  c.gap = dot(c.normal, d);
  // Rail: convex where the curve turns into the rail; wheel: convex where its locus turns away
  // from its outward normal (down), i.e. the opposite sign in the same plane.
  c.rail_lateral = signed_curvature(rail.d1, rail.d2);
  c.relative_lateral = c.rail_lateral - signed_curvature(tw, ww);
  return c;
}

double norm(const double v[2]) {
  return std::hypot(v[0], v[1]);
}

// Step minimising |f + J step| within radius (Levenberg-Marquardt form of the trust region);
// \p step enters holding the Newton step, kept when it is finite and inside the radius.
void trust_region_step(const Conditions& c, double radius, bool newton_finite, double step[2]) {
  if (newton_finite && norm(step) <= radius)
    return;
  // (J^T J + mu I) step = -J^T f, mu found by bisection in log space so |step| = radius.
  const double g[2] = {c.J[0][0] * c.f[0] + c.J[1][0] * c.f[1],
                       c.J[0][1] * c.f[0] + c.J[1][1] * c.f[1]};
  const double a = c.J[0][0] * c.J[0][0] + c.J[1][0] * c.J[1][0];
  const double b = c.J[0][0] * c.J[0][1] + c.J[1][0] * c.J[1][1];
  const double d = c.J[0][1] * c.J[0][1] + c.J[1][1] * c.J[1][1];
  auto solve = [&](double mu, double out[2]) {
    const double m = (a + mu) * (d + mu) - b * b;
    out[0] = -((d + mu) * g[0] - b * g[1]) / m;
    out[1] = -(-b * g[0] + (a + mu) * g[1]) / m;
  };
  double lo = 1e-30 * (a + d) + 1e-300, hi = 1e30 * (a + d) + 1e-300;
  for (int i = 0; i < 100 && hi / lo > 1.0001; ++i) {
    const double mu = std::sqrt(lo * hi);
    solve(mu, step);
    (norm(step) > radius ? lo : hi) = mu;
  }
  solve(hi, step);
}

}  // namespace

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

ContactPoint search_contact(const WheelRailGeometry& geometry, Side side, bool flange,
                            const WheelsetPose& pose, double s_wheel, double s_rail,
                            const SearchSettings& settings) {
  const auto wheel_range = geometry.part_range(side, flange);
  const ProfileCurve& rail_curve = geometry.rail(side);
  const double lower[2] = {wheel_range[0], rail_curve.begin()};
  const double upper[2] = {wheel_range[1], rail_curve.end()};
  double s[2] = {std::clamp(s_wheel, lower[0], upper[0]), std::clamp(s_rail, lower[1], upper[1])};
  LocusPoint locus;
  CurveDerivatives rail;
  Conditions c = evaluate(geometry, side, pose, s[0], s[1], locus, rail);
  double radius = settings.trust_radius;
  ContactPoint point;
  point.flange = flange;
  bool converged = false;
  int iteration = 0;
  while (iteration < settings.max_iterations) {
    ++iteration;
    const double det = c.J[0][0] * c.J[1][1] - c.J[0][1] * c.J[1][0];
    double newton[2] = {-(c.J[1][1] * c.f[0] - c.J[0][1] * c.f[1]) / det,
                        -(-c.J[1][0] * c.f[0] + c.J[0][0] * c.f[1]) / det};
    const bool newton_finite = std::isfinite(newton[0]) && std::isfinite(newton[1]);
    // Converged when the full Newton correction is negligible, or the conditions hold to
    // round-off (near-conformal contact makes J nearly singular and magnifies that round-off
    // in the correction): take it and stop.
    const bool residual_small = std::abs(c.f[0]) <= 0.1 * settings.tolerance &&
                                std::abs(c.f[1]) <= settings.tolerance / 0.01;
    if (newton_finite && (norm(newton) <= settings.tolerance || residual_small)) {
      s[0] = std::clamp(s[0] + newton[0], lower[0], upper[0]);
      s[1] = std::clamp(s[1] + newton[1], lower[1], upper[1]);
      c = evaluate(geometry, side, pose, s[0], s[1], locus, rail);
      converged = true;
      break;
    }
    double step[2] = {newton[0], newton[1]};
    if (settings.use_trust_region)
      trust_region_step(c, radius, newton_finite, step);
    else if (!newton_finite)
      break;
    double trial[2];
    for (int k = 0; k < 2; ++k)
      trial[k] = std::clamp(s[k] + step[k], lower[k], upper[k]);
    const double taken[2] = {trial[0] - s[0], trial[1] - s[1]};
    LocusPoint trial_locus;
    CurveDerivatives trial_rail;
    const Conditions t =
        evaluate(geometry, side, pose, trial[0], trial[1], trial_locus, trial_rail);
    const double merit = norm(c.f), trial_merit = norm(t.f);
    const double model[2] = {c.f[0] + c.J[0][0] * taken[0] + c.J[0][1] * taken[1],
                             c.f[1] + c.J[1][0] * taken[0] + c.J[1][1] * taken[1]};
    const double predicted = merit * merit - norm(model) * norm(model);
    const double ratio = predicted > 0 ? (merit * merit - trial_merit * trial_merit) / predicted
                                       : (trial_merit < merit ? 1.0 : -1.0);
    if (settings.use_trust_region) {
      if (ratio < 0.25)
        radius = std::max(0.25 * norm(taken), 1e-15);
      else if (ratio > 0.75)
        radius = std::max(radius, 2 * norm(taken));
    }
    if (!settings.use_trust_region || ratio > 1e-4) {
      s[0] = trial[0];
      s[1] = trial[1];
      c = t;
      locus = trial_locus;
      rail = trial_rail;
      // Stopped by the part's end and unable to move: the least gap lies there.
      if (norm(taken) == 0)
        break;
    } else if (radius <= settings.tolerance) {
      break;
    }
  }
  point.iterations = iteration;
  point.s_wheel = s[0];
  point.s_rail = s[1];
  point.rail_point = rail.p;
  point.x = locus.x;
  point.gap = c.gap;
  point.normal = c.normal;
  const double towards_centre = side == Side::right ? -1.0 : 1.0;
  point.contact_angle = std::atan2(towards_centre * c.normal.y, -c.normal.z);
  point.rolling_radius = locus.radius;
  point.wheel_rolling_curvature = locus.rolling_curvature;
  point.rail_lateral_curvature = c.rail_lateral;
  point.wheel_lateral_curvature = c.relative_lateral - point.rail_lateral_curvature;
  const bool at_bound = s[0] <= lower[0] || s[0] >= upper[0];
  const bool satisfied = converged;
  if (at_bound && !satisfied)
    point.status = SearchStatus::part_boundary;
  else if (!satisfied)
    point.status = SearchStatus::not_converged;
  else if (c.relative_lateral <= 0)
    point.status = SearchStatus::not_a_minimum;
  else
    point.status = SearchStatus::converged;
  return point;
}

std::array<double, 2> sampled_start(const WheelRailGeometry& geometry, Side side, bool flange,
                                    const WheelsetPose& pose, int samples) {
  const auto range = geometry.part_range(side, flange);
  const ProfileCurve& rail = geometry.rail(side);
  // Rail sampled once: its points in y order are what the vertical clearance is measured to.
  const int rail_samples = 4 * samples;
  std::vector<Vec2> rail_points(static_cast<std::size_t>(rail_samples) + 1);
  for (int i = 0; i <= rail_samples; ++i)
    rail_points[i] = rail.at(rail.begin() + (rail.end() - rail.begin()) * i / rail_samples).p;
  double best[2] = {range[0], rail.begin()};
  double best_clearance = 1e300;
  for (int i = 0; i <= samples; ++i) {
    const double s = range[0] + (range[1] - range[0]) * i / samples;
    const LocusPoint p = geometry.locus(side, s, pose);
    // The rail's uppermost surface at the wheel point's y: the clearance is measured to it.
    // Where no rail lies below (a flange beside the gauge face), the distance to the nearest
    // rail point stands in for it.
    double nearest = 1e300;
    std::size_t nearest_k = 0;
    for (std::size_t k = 0; k < rail_points.size(); ++k) {
      const double distance = std::hypot(p.y.v - rail_points[k].y, p.z.v - rail_points[k].z);
      if (distance < nearest) {
        nearest = distance;
        nearest_k = k;
      }
    }
    if (nearest < best_clearance) {
      best_clearance = nearest;
      best[0] = s;
      best[1] = rail.begin() +
                (rail.end() - rail.begin()) * static_cast<double>(nearest_k) / rail_samples;
    }
    for (int k = 0; k < rail_samples; ++k) {
      const Vec2 a = rail_points[k], b = rail_points[k + 1];
      if ((p.y.v - a.y) * (p.y.v - b.y) > 0 || a.y == b.y)
        continue;
      const double w = (p.y.v - a.y) / (b.y - a.y);
      const double clearance = a.z + w * (b.z - a.z) - p.z.v;
      if (clearance < best_clearance) {
        best_clearance = clearance;
        best[0] = s;
        best[1] = rail.begin() + (rail.end() - rail.begin()) * (k + w) / rail_samples;
      }
    }
  }
  return {best[0], best[1]};
}

}  // namespace railfe
