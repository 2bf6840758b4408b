#include "contact/geometry/rail_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

namespace {

using P = SectionPoint;

P operator+(P a, P b) {
  return {a[0] + b[0], a[1] + b[1]};
}
P operator-(P a, P b) {
  return {a[0] - b[0], a[1] - b[1]};
}
P operator*(double s, P a) {
  return {s * a[0], s * a[1]};
}
double dot(P a, P b) {
  return a[0] * b[0] + a[1] * b[1];
}
double cross(P a, P b) {
  return a[0] * b[1] - a[1] * b[0];
}
double norm(P a) {
  return std::hypot(a[0], a[1]);
}
P unit(P a) {
  return (1 / norm(a)) * a;
}
P left_of(P d) {
  return {-d[1], d[0]};
}

// A drawing's curve: a line (point, direction of travel) or a circle (centre, radius, turn).
struct Curve {
  bool is_arc = false;
  P point{0, 0}, direction{0, 0};
  P centre{0, 0};
  double radius = 0;
  int turn = 0;
};

Curve line(P point, P direction) {
  return {false, point, unit(direction), {0, 0}, 0, 0};
}
Curve arc(P centre, double radius, int turn) {
  return {true, {0, 0}, {0, 0}, centre, radius, turn};
}

// How a curve meets the next: where the drawing makes them touch, or a fillet (radius > 0).
struct Join {
  double fillet = 0;
};
constexpr Join kTangent{0};

P tangent_of(const Curve& c, P at) {
  return c.is_arc ? static_cast<double>(c.turn) * left_of(unit(at - c.centre)) : c.direction;
}

// The point of \p c nearest to \p q (on the line, or on the circle towards q).
P project(const Curve& c, P q) {
  if (c.is_arc)
    return c.centre + c.radius * unit(q - c.centre);
  return c.point + dot(q - c.point, c.direction) * c.direction;
}

// Where two curves the drawing makes tangent touch.
P touching_point(const Curve& a, const Curve& b) {
  if (a.is_arc && b.is_arc) {
    const Curve& big = a.radius > b.radius ? a : b;
    const Curve& small = a.radius > b.radius ? b : a;
    if (std::abs(norm(small.centre - big.centre) - (big.radius - small.radius)) > 1e-9 * big.radius)
      throw std::logic_error("railfe: rail drawing: arcs meant to touch do not");
    return big.centre + big.radius * unit(small.centre - big.centre);
  }
  const Curve& circle = a.is_arc ? a : b;
  const Curve& straight = a.is_arc ? b : a;
  return project(straight, circle.centre);
}

std::vector<P> intersections(const Curve& a, const Curve& b) {
  if (!a.is_arc && !b.is_arc) {
    const double det = cross(a.direction, b.direction);
    if (std::abs(det) < 1e-14)
      return {};
    const double t = cross(b.point - a.point, b.direction) / det;
    return {a.point + t * a.direction};
  }
  if (!a.is_arc || !b.is_arc) {
    const Curve& straight = a.is_arc ? b : a;
    const Curve& circle = a.is_arc ? a : b;
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
double travel(const Curve& c, P from, P to) {
  if (!c.is_arc)
    return dot(to - from, c.direction);
  double angle =
      std::atan2(cross(from - c.centre, to - c.centre), dot(from - c.centre, to - c.centre));
  angle *= c.turn;
  if (angle < 0)
    angle += 2 * M_PI;
  return angle * c.radius;
}

Curve offset(const Curve& c, double to_left) {
  Curve shifted = c;
  if (c.is_arc)
    shifted.radius = c.radius - c.turn * to_left;
  else
    shifted.point = c.point + to_left * left_of(c.direction);
  return shifted;
}

P nearest(const std::vector<P>& candidates, P to) {
  if (candidates.empty())
    throw std::logic_error("railfe: rail drawing: curves meant to meet do not");
  return *std::min_element(candidates.begin(), candidates.end(),
                           [&](P x, P y) { return norm(x - to) < norm(y - to); });
}

OutlineSegment piece(const Curve& c, P from, P to) {
  OutlineSegment s;
  s.start = from;
  s.end = to;
  s.is_arc = c.is_arc;
  s.centre = c.centre;
  s.radius = c.radius;
  s.turn = c.turn;
  return s;
}

// The left half from \p start to \p end: curve i runs from where it meets curve i - 1 to where
// it meets curve i + 1; fillets become arcs of their own.
std::vector<OutlineSegment> half_outline(const std::vector<Curve>& curves,
                                         const std::vector<Join>& joins, P start, P end) {
  std::vector<OutlineSegment> segments;
  P entry = start;
  for (std::size_t i = 0; i + 1 < curves.size(); ++i) {
    const Curve &a = curves[i], &b = curves[i + 1];
    if (joins[i].fillet <= 0) {
      const P meet = touching_point(a, b);
      segments.push_back(piece(a, entry, meet));
      entry = meet;
      continue;
    }
    // The sharp corner: the first meeting point ahead along a.
    std::vector<P> corners = intersections(a, b);
    if (corners.empty())
      throw std::logic_error("railfe: rail drawing: curves to be filleted do not meet");
    const P corner = *std::min_element(corners.begin(), corners.end(), [&](P x, P y) {
      const double tx = travel(a, entry, x), ty = travel(a, entry, y);
      return (tx > 0 ? tx : 1e300) < (ty > 0 ? ty : 1e300);
    });
    const int turn = cross(tangent_of(a, corner), tangent_of(b, corner)) > 0 ? 1 : -1;
    const double r = joins[i].fillet;
    const P centre = nearest(intersections(offset(a, turn * r), offset(b, turn * r)), corner);
    const P on_a = project(a, centre), on_b = project(b, centre);
    segments.push_back(piece(a, entry, on_a));
    segments.push_back(piece(arc(centre, r, turn), on_a, on_b));
    entry = on_b;
  }
  segments.push_back(piece(curves.back(), entry, end));
  return segments;
}

OutlineSegment mirrored(const OutlineSegment& s) {
  OutlineSegment m = s;
  m.start = {-s.end[0], s.end[1]};
  m.end = {-s.start[0], s.start[1]};
  m.centre = {-s.centre[0], s.centre[1]};
  return m;  // mirroring reverses the sense of travel twice over: the turn is kept
}

// The head common to the EN 13674 drawings: the crown R300 to half-width w1, R80 to half-width
// w2, the corner R13 down to a side sloping 1:20, a 3 mm fillet, and the underside sloping
// 1:2.75 towards the point (0, -underside) on the axis (millimetres).
std::vector<Curve> head_curves(double w1, double w2, double underside) {
  const Curve crown = arc({0, -300}, 300, 1);
  const P t1{-w1, -300 + std::sqrt(300 * 300 - w1 * w1)};
  const Curve shoulder = arc(t1 + 80 * unit(crown.centre - t1), 80, 1);
  const double du = -w2 - shoulder.centre[0];
  const P t2{-w2, shoulder.centre[1] + std::sqrt(80 * 80 - du * du)};
  const Curve corner = arc(t2 + 13 * unit(shoulder.centre - t2), 13, 1);
  const P side_direction = unit(P{-1, -20});
  const P side_point = corner.centre + 13 * P{side_direction[1], -side_direction[0]};
  return {crown, shoulder, corner, line(side_point, side_direction),
          line({0, -underside}, {2.75, -1})};
}

// Centre of a right-turning circle of radius r at height v that touches the right-turning
// circle (centre, big) from inside.
P inner_centre(P centre, double big, double r, double v) {
  const double dv = v - centre[1];
  return {centre[0] + std::sqrt((big - r) * (big - r) - dv * dv), v};
}

// The foot: its top sloping 1:2.75 from the axis at height -foot_top, then 1:slope to the edge
// (half-width half_width, edge thickness edge), fillets r_top (between the slopes), r_edge and
// 2 mm at the bottom corner; height h.
void add_foot(std::vector<Curve>& curves, std::vector<Join>& joins, double foot_top, double r_top,
              double slope, double half_width, double edge, double r_edge, double h) {
  curves.push_back(line({0, -foot_top}, {-2.75, -1}));
  joins.push_back({r_top});
  curves.push_back(line({-half_width, -h + edge}, {-slope, -1}));
  joins.push_back({r_edge});
  curves.push_back(line({-half_width, -h + edge}, {0, -1}));
  joins.push_back({2});
  curves.push_back(line({-half_width, -h}, {1, 0}));
}

RailOutline assemble(const std::string& name, const std::vector<Curve>& curves,
                     const std::vector<Join>& joins, double height_mm) {
  std::vector<OutlineSegment> half = half_outline(curves, joins, {0, 0}, {0, -height_mm});
  for (auto& s : half) {
    s.start = 1e-3 * s.start;
    s.end = 1e-3 * s.end;
    s.centre = 1e-3 * s.centre;
    s.radius *= 1e-3;
  }
  RailOutline outline;
  outline.name = name;
  // Counter-clockwise: the right half from the foot's middle up to the crown top, then the left.
  for (auto it = half.rbegin(); it != half.rend(); ++it)
    outline.segments.push_back(mirrored(*it));
  const std::size_t n = half.size();
  outline.segments.insert(outline.segments.end(), half.begin(), half.end());
  // Crown, shoulder and corner arcs: the first three of the left half and their mirrors.
  for (std::size_t k = 0; k < 3; ++k) {
    outline.running_surface.push_back(n + k);
    outline.running_surface.push_back(n - 1 - k);
  }
  std::sort(outline.running_surface.begin(), outline.running_surface.end());
  return outline;
}

RailOutline drawing_54e1() {
  // EN 13674-1, 54E1 (UIC 54): height 159, head 70, foot 140, web 16 (millimetres).
  std::vector<Curve> curves = head_curves(20.024 / 2, 49.727 / 2, 49.4);
  std::vector<Join> joins = {kTangent, kTangent, kTangent, {3}, {8}};
  const P web_centre{-516, -159 + 76.2};
  curves.push_back(arc(inner_centre(web_centre, 508, 22, -159 + 76.2 + 25.4), 22, -1));
  joins.push_back(kTangent);
  curves.push_back(arc(web_centre, 508, -1));
  joins.push_back({16});
  add_foot(curves, joins, 159 - 30.2, 20, 10, 70, 11, 3, 159);
  return assemble("54E1", curves, joins, 159);
}

RailOutline drawing_60e1() {
  // EN 13674-1, 60E1 (UIC 60): height 172, head 72, foot 150, web 16.5 (millimetres).
  std::vector<Curve> curves = head_curves(20.456 / 2, 52.053 / 2, 51);
  std::vector<Join> joins = {kTangent, kTangent, kTangent, {3}, {7}};
  const double web_top = -172 + 31.5 + 28.75 + 32, web_bottom = -172 + 31.5 + 28.75;
  const P upper{-8.25 - 120, web_top}, lower{-8.25 - 120, web_bottom};
  curves.push_back(arc(inner_centre(upper, 120, 35, web_top + 19.5), 35, -1));
  curves.push_back(arc(upper, 120, -1));
  curves.push_back(line({-8.25, web_top}, {0, -1}));
  curves.push_back(arc(lower, 120, -1));
  curves.push_back(arc(inner_centre(lower, 120, 35, web_bottom - 19.5), 35, -1));
  joins.insert(joins.end(), {kTangent, kTangent, kTangent, kTangent, {7}});
  add_foot(curves, joins, 172 - 31.5, 40, 14, 75, 11.5, 4, 172);
  return assemble("60E1", curves, joins, 172);
}

// Points of one segment, start included and end excluded, no farther apart than spacing.
void sample_segment(const OutlineSegment& s, double spacing, std::vector<P>& points) {
  if (!s.is_arc) {
    const int n = std::max(1, static_cast<int>(std::ceil(norm(s.end - s.start) / spacing)));
    for (int k = 0; k < n; ++k)
      points.push_back(s.start + (static_cast<double>(k) / n) * (s.end - s.start));
    return;
  }
  const P a = s.start - s.centre, b = s.end - s.centre;
  double sweep = std::atan2(cross(a, b), dot(a, b));
  if (sweep * s.turn < 0)
    sweep += s.turn * 2 * M_PI;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) * s.radius / spacing)));
  const double a0 = std::atan2(a[1], a[0]);
  for (int k = 0; k < n; ++k) {
    const double angle = a0 + sweep * k / n;
    points.push_back(s.centre + s.radius * P{std::cos(angle), std::sin(angle)});
  }
}

}  // namespace

std::vector<std::string> rail_drawing_names() {
  return {"54E1", "60E1"};
}

RailOutline rail_outline(const std::string& name) {
  if (name == "54E1")
    return drawing_54e1();
  if (name == "60E1")
    return drawing_60e1();
  throw std::invalid_argument("railfe: unknown rail drawing '" + name + "'");
}

std::vector<SectionPoint> sample_outline(const RailOutline& outline, double spacing) {
  std::vector<P> points;
  for (const auto& s : outline.segments)
    sample_segment(s, spacing, points);
  return points;
}

SectionProperties section_properties(const RailOutline& outline) {
  // Green's theorem on the closed counter-clockwise outline: A = ∮u dv, ∫u dA = ∮u²/2 dv,
  // ∫v dA = -∮v²/2 du, ∫u² dA = ∮u³/3 dv, ∫v² dA = -∮v³/3 du; each piece integrated by
  // five-point Gauss–Legendre on 64 sub-pieces (arcs: polynomials in cos and sin of the angle).
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  double sums[5] = {0, 0, 0, 0, 0};
  for (const auto& s : outline.segments) {
    double a0 = 0, sweep = 0;
    if (s.is_arc) {
      const P a = s.start - s.centre, b = s.end - s.centre;
      a0 = std::atan2(a[1], a[0]);
      sweep = std::atan2(cross(a, b), dot(a, b));
      if (sweep * s.turn < 0)
        sweep += s.turn * 2 * M_PI;
    }
    const int pieces = 64;
    for (int k = 0; k < pieces; ++k) {
      for (int g = 0; g < 5; ++g) {
        const double t = (k + 0.5 * (1 + x[g])) / pieces, weight = w[g] * 0.5 / pieces;
        P at, d;
        if (s.is_arc) {
          const double angle = a0 + sweep * t;
          at = s.centre + s.radius * P{std::cos(angle), std::sin(angle)};
          d = sweep * s.radius * P{-std::sin(angle), std::cos(angle)};
        } else {
          at = s.start + t * (s.end - s.start);
          d = s.end - s.start;
        }
        const double u = at[0], v = at[1];
        sums[0] += weight * u * d[1];
        sums[1] += weight * u * u / 2 * d[1];
        sums[2] -= weight * v * v / 2 * d[0];
        sums[3] += weight * u * u * u / 3 * d[1];
        sums[4] -= weight * v * v * v / 3 * d[0];
      }
    }
  }
  SectionProperties p;
  p.area = sums[0];
  p.centroid = {sums[1] / p.area, sums[2] / p.area};
  p.inertia_vertical = sums[3] - p.area * p.centroid[0] * p.centroid[0];
  p.inertia_horizontal = sums[4] - p.area * p.centroid[1] * p.centroid[1];
  return p;
}

double distance_to_outline(const RailOutline& outline, const SectionPoint& point) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : outline.segments) {
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

double outline_width_at(const RailOutline& outline, double v) {
  const std::vector<P> points = sample_outline(outline, 1e-5);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const P a = points[i], b = points[(i + 1) % points.size()];
    if ((a[1] - v) * (b[1] - v) > 0 || a[1] == b[1])
      continue;
    const double u = a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
    low = std::min(low, u);
    high = std::max(high, u);
  }
  return high > low ? high - low : 0;
}

}  // namespace railfe
