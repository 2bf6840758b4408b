#include "contact/geometry/drawing_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

namespace drawing_math {
double dot(SectionPoint a, SectionPoint b) {
  return a[0] * b[0] + a[1] * b[1];
}
double cross(SectionPoint a, SectionPoint b) {
  return a[0] * b[1] - a[1] * b[0];
}
double norm(SectionPoint a) {
  return std::hypot(a[0], a[1]);
}
SectionPoint unit(SectionPoint a) {
  return (1 / norm(a)) * a;
}
SectionPoint left_of(SectionPoint d) {
  return {-d[1], d[0]};
}
}  // namespace drawing_math

using namespace drawing_math;

namespace {

using P = SectionPoint;

P tangent_of(const DrawingCurve& c, P at) {
  return c.is_arc ? static_cast<double>(c.turn) * left_of(unit(at - c.centre)) : c.direction;
}

// The point of \p c nearest to \p q (on the line, or on the circle towards q).
P project(const DrawingCurve& c, P q) {
  if (c.is_arc)
    return c.centre + c.radius * unit(q - c.centre);
  return c.point + dot(q - c.point, c.direction) * c.direction;
}

// Where two curves the drawing makes tangent touch.
P touching_point(const DrawingCurve& a, const DrawingCurve& b) {
  if (a.is_arc && b.is_arc) {
    const DrawingCurve& big = a.radius > b.radius ? a : b;
    const DrawingCurve& small = a.radius > b.radius ? b : a;
    if (std::abs(norm(small.centre - big.centre) - (big.radius - small.radius)) > 1e-9 * big.radius)
      throw std::logic_error("railfe: drawing: arcs meant to touch do not");
    return big.centre + big.radius * unit(small.centre - big.centre);
  }
  if (!a.is_arc && !b.is_arc)
    throw std::logic_error("railfe: drawing: two lines cannot touch; join them by a fillet");
  const DrawingCurve& circle = a.is_arc ? a : b;
  const DrawingCurve& straight = a.is_arc ? b : a;
  const P foot = project(straight, circle.centre);
  if (std::abs(norm(foot - circle.centre) - circle.radius) > 1e-9 * circle.radius)
    throw std::logic_error("railfe: drawing: a line and an arc meant to touch do not");
  return foot;
}

std::vector<P> intersections(const DrawingCurve& a, const DrawingCurve& b) {
  if (!a.is_arc && !b.is_arc) {
    const double det = cross(a.direction, b.direction);
    if (std::abs(det) < 1e-14)
      return {};
    const double t = cross(b.point - a.point, b.direction) / det;
    return {a.point + t * a.direction};
  }
  if (!a.is_arc || !b.is_arc) {
    const DrawingCurve& straight = a.is_arc ? b : a;
    const DrawingCurve& circle = a.is_arc ? a : b;
    const P w = straight.point - circle.centre;
    const double half_b = dot(straight.direction, w);
    const double disc = half_b * half_b - (dot(w, w) - circle.radius * circle.radius);
    if (disc < 0)
      return {};
    const double root = std::sqrt(disc);
    return {straight.point + (-half_b - root) * straight.direction,
            straight.point + (-half_b + root) * straight.direction};
  }
  const P d = b.centre - a.centre;
  const double distance = norm(d);
  const double along =
      (distance * distance + a.radius * a.radius - b.radius * b.radius) / (2 * distance);
  const double h2 = a.radius * a.radius - along * along;
  if (h2 < 0)
    return {};
  const P foot = a.centre + (along / distance) * d, across = std::sqrt(h2) * left_of(unit(d));
  return {foot + across, foot - across};
}

// How far along \p c one travels from \p from to \p to (for arcs, the angle times the radius
// turned in the arc's sense, in [0, 2π R)).
double travel(const DrawingCurve& c, P from, P to) {
  if (!c.is_arc)
    return dot(to - from, c.direction);
  double angle =
      std::atan2(cross(from - c.centre, to - c.centre), dot(from - c.centre, to - c.centre));
  angle *= c.turn;
  if (angle < 0)
    angle += 2 * M_PI;
  return angle * c.radius;
}

DrawingCurve offset(const DrawingCurve& c, double to_left) {
  DrawingCurve shifted = c;
  if (c.is_arc)
    shifted.radius = c.radius - c.turn * to_left;
  else
    shifted.point = c.point + to_left * left_of(c.direction);
  return shifted;
}

P nearest(const std::vector<P>& candidates, P to) {
  if (candidates.empty())
    throw std::logic_error("railfe: drawing: curves meant to meet do not");
  return *std::min_element(candidates.begin(), candidates.end(),
                           [&](P x, P y) { return norm(x - to) < norm(y - to); });
}

OutlineSegment piece(const DrawingCurve& c, P from, P to) {
  OutlineSegment s;
  s.start = from;
  s.end = to;
  s.is_arc = c.is_arc;
  s.centre = c.centre;
  s.radius = c.radius;
  s.turn = c.turn;
  return s;
}

// Points of one segment, start included and end excluded, no farther apart than spacing.
void sample_segment(const OutlineSegment& s, double spacing, std::vector<P>& points) {
  if (!s.is_arc) {
    const int n = std::max(1, static_cast<int>(std::ceil(norm(s.end - s.start) / spacing)));
    for (int k = 0; k < n; ++k)
      points.push_back(s.start + (static_cast<double>(k) / n) * (s.end - s.start));
    return;
  }
  const double sweep = arc_sweep(s);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) * s.radius / spacing)));
  const P a = s.start - s.centre;
  const double a0 = std::atan2(a[1], a[0]);
  for (int k = 0; k < n; ++k) {
    const double angle = a0 + sweep * k / n;
    points.push_back(s.centre + s.radius * P{std::cos(angle), std::sin(angle)});
  }
}

}  // namespace

DrawingCurve drawing_line(SectionPoint point, SectionPoint direction) {
  DrawingCurve c;
  c.point = point;
  c.direction = unit(direction);
  return c;
}

DrawingCurve drawing_circle(SectionPoint centre, double radius, int turn) {
  DrawingCurve c;
  c.is_arc = true;
  c.centre = centre;
  c.radius = radius;
  c.turn = turn;
  return c;
}

DrawingCurve drawing_circle_touching(const DrawingCurve& line, SectionPoint at, double radius,
                                     int turn) {
  return drawing_circle(project(line, at) + (turn * radius) * left_of(line.direction), radius,
                        turn);
}

std::vector<OutlineSegment> drawing_chain(const std::vector<DrawingCurve>& curves,
                                          const std::vector<DrawingJoin>& joins, SectionPoint start,
                                          SectionPoint end) {
  if (curves.empty() || joins.size() + 1 != curves.size())
    throw std::logic_error("railfe: drawing: a chain needs one join fewer than curves");
  std::vector<OutlineSegment> segments;
  P entry = start;
  for (std::size_t i = 0; i + 1 < curves.size(); ++i) {
    const DrawingCurve &a = curves[i], &b = curves[i + 1];
    if (joins[i].fillet <= 0) {
      const P meet = touching_point(a, b);
      segments.push_back(piece(a, entry, meet));
      entry = meet;
      continue;
    }
    // The sharp corner: the first meeting point ahead along a.
    std::vector<P> corners = intersections(a, b);
    if (corners.empty())
      throw std::logic_error("railfe: drawing: curves to be filleted do not meet");
    const P corner = *std::min_element(corners.begin(), corners.end(), [&](P x, P y) {
      const double tx = travel(a, entry, x), ty = travel(a, entry, y);
      return (tx > 0 ? tx : 1e300) < (ty > 0 ? ty : 1e300);
    });
    const int turn = cross(tangent_of(a, corner), tangent_of(b, corner)) > 0 ? 1 : -1;
    const double r = joins[i].fillet;
    const P centre = nearest(intersections(offset(a, turn * r), offset(b, turn * r)), corner);
    const P on_a = project(a, centre), on_b = project(b, centre);
    segments.push_back(piece(a, entry, on_a));
    segments.push_back(piece(drawing_circle(centre, r, turn), on_a, on_b));
    entry = on_b;
  }
  segments.push_back(piece(curves.back(), entry, end));
  return segments;
}

std::vector<SectionPoint> sample_segments(const std::vector<OutlineSegment>& segments,
                                          double spacing, bool with_end) {
  std::vector<P> points;
  for (const auto& s : segments)
    sample_segment(s, spacing, points);
  if (with_end && !segments.empty())
    points.push_back(segments.back().end);
  return points;
}

double arc_sweep(const OutlineSegment& s) {
  const P a = s.start - s.centre, b = s.end - s.centre;
  double sweep = std::atan2(cross(a, b), dot(a, b));
  if (sweep * s.turn < 0)
    sweep += s.turn * 2 * M_PI;
  return sweep;
}

double distance_to_segments(const std::vector<OutlineSegment>& segments, SectionPoint point) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments) {
    if (!s.is_arc) {
      const P e = s.end - s.start;
      const double t = std::clamp(dot(point - s.start, e) / dot(e, e), 0.0, 1.0);
      best = std::min(best, norm(s.start + t * e - point));
      continue;
    }
    // Within the arc's sweep the nearest point is along the radius; otherwise an end.
    const P a = s.start - s.centre, b = s.end - s.centre, q = point - s.centre;
    const double sweep = std::abs(std::atan2(cross(a, b), dot(a, b)));
    const double to_q = s.turn * std::atan2(cross(a, q), dot(a, q));
    if (to_q >= 0 && to_q <= sweep)
      best = std::min(best, std::abs(norm(q) - s.radius));
    best = std::min({best, norm(point - s.start), norm(point - s.end)});
  }
  return best;
}

SectionPoint segment_tangent(const OutlineSegment& s, bool at_end) {
  if (!s.is_arc)
    return unit(s.end - s.start);
  return static_cast<double>(s.turn) * left_of(unit((at_end ? s.end : s.start) - s.centre));
}

}  // namespace railfe
