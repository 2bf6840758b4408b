#pragma once
/// \file
/// Shapes drawn as standards draw them: a chain of straight lines and circular arcs, each
/// joined to the next where the drawing makes them touch (tangent) or by a fillet of a given
/// radius. The drawing gives each curve whole (a line through a point with a direction, a
/// circle with its centre and radius); the chain works out where each piece starts and ends, so
/// a generated shape has the drawing's exact radii rather than a digitized approximation. Rail
/// sections (rail_drawing.hpp) and wheel profiles (wheel_drawing.hpp) are built this way.

#include <array>
#include <vector>

namespace railfe {

/// A point or vector of the drawing's plane, metres (or the drawing's unit while it is built).
using SectionPoint = std::array<double, 2>;

/// Vector arithmetic on drawing points, for the files that write drawings.
namespace drawing_math {
/// Sum.
inline SectionPoint operator+(SectionPoint a, SectionPoint b) {
  return {a[0] + b[0], a[1] + b[1]};
}
/// Difference.
inline SectionPoint operator-(SectionPoint a, SectionPoint b) {
  return {a[0] - b[0], a[1] - b[1]};
}
/// Scaling.
inline SectionPoint operator*(double s, SectionPoint a) {
  return {s * a[0], s * a[1]};
}
/// Scalar product.
double dot(SectionPoint a, SectionPoint b);
/// z component of the cross product (positive when b lies counter-clockwise of a).
double cross(SectionPoint a, SectionPoint b);
/// Length.
double norm(SectionPoint a);
/// \p a scaled to unit length.
SectionPoint unit(SectionPoint a);
/// \p d turned a quarter counter-clockwise.
SectionPoint left_of(SectionPoint d);
}  // namespace drawing_math

/// One piece of a chain: a straight segment or a circular arc, traversed from start to end.
struct OutlineSegment {
  SectionPoint start;   ///< where the piece begins
  SectionPoint end;     ///< where it ends
  bool is_arc = false;  ///< false: the straight segment start-end
  SectionPoint centre;  ///< centre of the arc (arcs only)
  double radius = 0;    ///< radius of the arc (arcs only)
  /// +1 when the arc turns left (counter-clockwise), -1 when it turns right (arcs only).
  int turn = 0;
};

/// A curve as a drawing gives it, with the sense the chain travels it in.
struct DrawingCurve {
  bool is_arc = false;           ///< false: a straight line
  SectionPoint point{0, 0};      ///< a point of the line (lines only)
  SectionPoint direction{0, 0};  ///< unit direction of travel (lines only)
  SectionPoint centre{0, 0};     ///< centre of the circle (arcs only)
  double radius = 0;             ///< radius of the circle (arcs only)
  int turn = 0;                  ///< +1 travelled counter-clockwise, -1 clockwise (arcs only)
};

/// The line through \p point travelled along \p direction (any length).
DrawingCurve drawing_line(SectionPoint point, SectionPoint direction);
/// The circle of \p radius about \p centre, travelled counter-clockwise (\p turn = +1) or
/// clockwise (-1).
DrawingCurve drawing_circle(SectionPoint centre, double radius, int turn);
/// The circle of \p radius that touches \p line at \p at, on the line's left (\p turn = +1,
/// the chain turning counter-clockwise after the line) or right (-1): how drawings give an arc
/// "tangent to the line at this point".
DrawingCurve drawing_circle_touching(const DrawingCurve& line, SectionPoint at, double radius,
                                     int turn);

/// How a curve meets the next one in a chain.
struct DrawingJoin {
  /// 0: where the drawing makes the two curves touch; > 0: a fillet arc of this radius at the
  /// first corner ahead where they cross.
  double fillet = 0;
};
/// The join of two curves that the drawing makes tangent.
constexpr DrawingJoin kTangentJoin{0};

/// The pieces of the chain \p curves from \p start (on the first curve) to \p end (on the
/// last): curve i runs from where it meets curve i - 1 to where it meets curve i + 1 as
/// \p joins[i] says; fillets become arcs of their own. Throws std::logic_error when curves meant
/// to touch or cross do not (a drawing written wrong).
std::vector<OutlineSegment> drawing_chain(const std::vector<DrawingCurve>& curves,
                                          const std::vector<DrawingJoin>& joins, SectionPoint start,
                                          SectionPoint end);

/// Points along \p segments no farther apart than \p spacing (every segment's ends included,
/// arcs subdivided evenly), in order; the last segment's end is added when \p with_end.
std::vector<SectionPoint> sample_segments(const std::vector<OutlineSegment>& segments,
                                          double spacing, bool with_end);

/// The angle the arc \p s sweeps from start to end, radians, signed by its turn.
double arc_sweep(const OutlineSegment& s);

/// Shortest distance from \p point to \p segments (to their exact lines and arcs).
double distance_to_segments(const std::vector<OutlineSegment>& segments, SectionPoint point);

/// The unit tangent (direction of travel) of \p s at its start (\p at_end false) or end.
SectionPoint segment_tangent(const OutlineSegment& s, bool at_end);

}  // namespace railfe
