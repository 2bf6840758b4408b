#include "contact/geometry/rail_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

using namespace drawing_math;

namespace {

using P = SectionPoint;
using Curve = DrawingCurve;

// The head's top, the parts every drawing here shares (millimetres, left half): the crown of
// radius \p crown about the axis, to half-width \p w1, and the 80 mm shoulder touching it there.
std::vector<Curve> crown_and_shoulder(double crown, double w1) {
  const Curve top = drawing_circle({0, -crown}, crown, 1);
  const P t1{-w1, -crown + std::sqrt(crown * crown - w1 * w1)};
  return {top, drawing_circle(t1 + 80 * unit(top.centre - t1), 80, 1)};
}

// The 13 mm gauge corner touching the shoulder at half-width \p w2 (the EN drawings give w2).
Curve corner_from_shoulder_end(const Curve& shoulder, double w2) {
  const double du = -w2 - shoulder.centre[0];
  const P t2{-w2, shoulder.centre[1] + std::sqrt(80 * 80 - du * du)};
  return drawing_circle(t2 + 13 * unit(shoulder.centre - t2), 13, 1);
}

// The 13 mm gauge corner touching the shoulder and ending on a side sloping 1:\p side_slope
// at half-width \p half_head (a drawing that gives the head's width instead of w2).
Curve corner_from_head_width(const Curve& shoulder, double half_head, double side_slope) {
  const P outward = unit(P{-side_slope, 1});  // the side's normal, away from the rail
  const double u = -half_head - 13 * outward[0], du = u - shoulder.centre[0];
  return drawing_circle({u, shoulder.centre[1] + std::sqrt(67 * 67 - du * du)}, 13, 1);
}

// The head's side sloping 1:\p side_slope down from the corner, then the underside sloping
// 1:\p underside_slope towards the point (0, -underside) on the axis.
void add_side_and_underside(std::vector<Curve>& curves, double side_slope, double underside,
                            double underside_slope) {
  const Curve& corner = curves.back();
  const P direction = unit(P{-1, -side_slope});
  curves.push_back(drawing_line(corner.centre + 13 * P{direction[1], -direction[0]}, direction));
  curves.push_back(drawing_line({0, -underside}, {underside_slope, -1}));
}

// The head common to the EN 13674 drawings: the crown R300 to half-width w1, R80 to half-width
// w2, the corner R13 down to a side sloping 1:20, a 3 mm fillet, and the underside sloping
// 1:2.75 towards the point (0, -underside) on the axis (millimetres).
std::vector<Curve> en_head(double w1, double w2, double underside) {
  std::vector<Curve> curves = crown_and_shoulder(300, w1);
  curves.push_back(corner_from_shoulder_end(curves[1], w2));
  add_side_and_underside(curves, 20, underside, 2.75);
  return curves;
}

// Centre of a right-turning circle of radius r at height v that touches the right-turning
// circle (centre, big) from inside.
P inner_centre(P centre, double big, double r, double v) {
  const double dv = v - centre[1];
  return {centre[0] + std::sqrt((big - r) * (big - r) - dv * dv), v};
}

// The foot: its top sloping 1:top_slope from the axis at height -foot_top, then (slope > 0)
// 1:slope to the edge, with the fillet r_top between the slopes; the edge (half-width
// half_width, thickness edge) with fillets r_edge and 2 mm at the bottom corner; height h.
void add_foot(std::vector<Curve>& curves, std::vector<DrawingJoin>& joins, double foot_top,
              double top_slope, double r_top, double slope, double half_width, double edge,
              double r_edge, double h) {
  curves.push_back(drawing_line({0, -foot_top}, {-top_slope, -1}));
  if (slope > 0) {
    joins.push_back({r_top});
    curves.push_back(drawing_line({-half_width, -h + edge}, {-slope, -1}));
  }
  joins.push_back({r_edge});
  curves.push_back(drawing_line({-half_width, -h + edge}, {0, -1}));
  joins.push_back({2});
  curves.push_back(drawing_line({-half_width, -h}, {1, 0}));
}

OutlineSegment mirrored(const OutlineSegment& s) {
  OutlineSegment m = s;
  m.start = {-s.end[0], s.end[1]};
  m.end = {-s.start[0], s.start[1]};
  m.centre = {-s.centre[0], s.centre[1]};
  return m;  // mirroring reverses the sense of travel twice over: the turn is kept
}

RailOutline assemble(const std::string& name, const std::vector<Curve>& curves,
                     const std::vector<DrawingJoin>& joins, double height_mm) {
  std::vector<OutlineSegment> half = drawing_chain(curves, joins, {0, 0}, {0, -height_mm});
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
  std::vector<Curve> curves = en_head(20.024 / 2, 49.727 / 2, 49.4);
  std::vector<DrawingJoin> joins = {kTangentJoin, kTangentJoin, kTangentJoin, {3}, {8}};
  const P web_centre{-516, -159 + 76.2};
  curves.push_back(drawing_circle(inner_centre(web_centre, 508, 22, -159 + 76.2 + 25.4), 22, -1));
  joins.push_back(kTangentJoin);
  curves.push_back(drawing_circle(web_centre, 508, -1));
  joins.push_back({16});
  add_foot(curves, joins, 159 - 30.2, 2.75, 20, 10, 70, 11, 3, 159);
  return assemble("54E1", curves, joins, 159);
}

RailOutline drawing_60e1() {
  // EN 13674-1, 60E1 (UIC 60): height 172, head 72, foot 150, web 16.5 (millimetres).
  std::vector<Curve> curves = en_head(20.456 / 2, 52.053 / 2, 51);
  std::vector<DrawingJoin> joins = {kTangentJoin, kTangentJoin, kTangentJoin, {3}, {7}};
  const double web_top = -172 + 31.5 + 28.75 + 32, web_bottom = -172 + 31.5 + 28.75;
  const P upper{-8.25 - 120, web_top}, lower{-8.25 - 120, web_bottom};
  curves.push_back(drawing_circle(inner_centre(upper, 120, 35, web_top + 19.5), 35, -1));
  curves.push_back(drawing_circle(upper, 120, -1));
  curves.push_back(drawing_line({-8.25, web_top}, {0, -1}));
  curves.push_back(drawing_circle(lower, 120, -1));
  curves.push_back(drawing_circle(inner_centre(lower, 120, 35, web_bottom - 19.5), 35, -1));
  joins.insert(joins.end(), {kTangentJoin, kTangentJoin, kTangentJoin, kTangentJoin, {7}});
  add_foot(curves, joins, 172 - 31.5, 2.75, 40, 14, 75, 11.5, 4, 172);
  return assemble("60E1", curves, joins, 172);
}

RailOutline drawing_jis60() {
  // JIS E 1101, 60 kg rail (Shinkansen and main lines in Japan), millimetres. From the JIS
  // dimension table (as JFE and Nippon Steel list it): height 174, foot 145, head 65, web 16.5,
  // head depth 49.0, foot depth 30.1 (each extended flank meets the axis there). Hosen wiki
  // ("60kgレール"): upper and lower neck radii 19, the foot's top one slope of 1:4. The crown R600
  // (issue 19: "crown radius 600 mm at the centre"). Not found in any public source, and chosen
  // here: the R80 shoulder and R13 gauge corner of the UIC heads this rail descends from, the
  // crown R600 to half-width 10 (as wide as 60E1's R300), the head width taken where the corner
  // meets a 1:20 side (as EN 13674-1 takes it), the head's underside at 1:4 like the foot's top,
  // a straight web, and EN 60E1's small radii: 3 (side to underside), 4 (foot top to edge) and
  // 2 (foot's bottom corners).
  std::vector<Curve> curves = crown_and_shoulder(600, 10);
  curves.push_back(corner_from_head_width(curves[1], 65.0 / 2, 20));
  add_side_and_underside(curves, 20, 49, 4);
  std::vector<DrawingJoin> joins = {kTangentJoin, kTangentJoin, kTangentJoin, {3}, {19}};
  curves.push_back(drawing_line({-16.5 / 2, 0}, {0, -1}));
  joins.push_back({19});
  add_foot(curves, joins, 174 - 30.1, 4, 0, 0, 145.0 / 2, 30.1 - 145.0 / 2 / 4, 4, 174);
  return assemble("JIS60", curves, joins, 174);
}

}  // namespace

std::vector<std::string> rail_drawing_names() {
  return {"54E1", "60E1", "JIS60"};
}

RailOutline rail_outline(const std::string& name) {
  if (name == "54E1")
    return drawing_54e1();
  if (name == "60E1")
    return drawing_60e1();
  if (name == "JIS60")
    return drawing_jis60();
  throw std::invalid_argument("railfe: unknown rail drawing '" + name + "'");
}

std::vector<OutlineSegment> rail_head(const RailOutline& outline) {
  // The running surface is contiguous in the counter-clockwise outline; one segment more on
  // each side is the head's side, down to where the underside begins.
  const auto [first, last] =
      std::minmax_element(outline.running_surface.begin(), outline.running_surface.end());
  return {outline.segments.begin() + static_cast<std::ptrdiff_t>(*first - 1),
          outline.segments.begin() + static_cast<std::ptrdiff_t>(*last + 2)};
}

std::vector<SectionPoint> sample_outline(const RailOutline& outline, double spacing) {
  return sample_segments(outline.segments, spacing, false);
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
      a0 = std::atan2(s.start[1] - s.centre[1], s.start[0] - s.centre[0]);
      sweep = arc_sweep(s);
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
  return distance_to_segments(outline.segments, point);
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
