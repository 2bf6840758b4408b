#pragma once
/// \file
/// Profile curves in a plane: a C2 cubic spline through measured points, or an exact circular
/// arc or straight line for verification. A curve is a map from a parameter s (metres along the
/// curve: chord length for splines, arc length for exact shapes) to a point (y, z), with the
/// derivatives the contact equations and curvatures need.

#include <array>
#include <memory>
#include <vector>

#include "contact/geometry/jet.hpp"

namespace railfe {

/// A point or vector in a profile's plane: y lateral, z vertical (down for rails and wheels in
/// track coordinates).
struct Vec2 {
  double y = 0;  ///< lateral component
  double z = 0;  ///< vertical component
};

/// A curve's position and its first three derivatives with respect to s.
struct CurveDerivatives {
  Vec2 p;   ///< position
  Vec2 d1;  ///< dp/ds
  Vec2 d2;  ///< d²p/ds²
  Vec2 d3;  ///< d³p/ds³
};

/// A parametric plane curve on [begin(), end()].
class ProfileCurve {
 public:
  virtual ~ProfileCurve() = default;
  /// Position and derivatives at \p s (extrapolated beyond the ends along the end tangents).
  virtual CurveDerivatives at(double s) const = 0;
  /// First parameter value.
  virtual double begin() const = 0;
  /// Last parameter value.
  virtual double end() const = 0;
};

/// Signed curvature at \p s: positive where the curve turns to the left of its direction
/// (counter-clockwise in the (y, z) plane), 1/m.
double signed_curvature(const ProfileCurve& curve, double s);
/// Signed curvature of a curve with first derivative \p d1 and second derivative \p d2 (1/m).
double signed_curvature(Vec2 d1, Vec2 d2);

/// Natural C2 cubic spline through \p points (at least 3, consecutive points distinct),
/// parameterized by cumulative chord length.
std::unique_ptr<ProfileCurve> spline_curve(const std::vector<Vec2>& points);
/// The same through (y, z) pairs, as profile files and drawings list them.
std::unique_ptr<ProfileCurve> spline_curve(const std::vector<std::array<double, 2>>& points);

/// Circular arc of \p radius about \p centre from polar angle \p angle_begin to \p angle_end
/// (radians, measured from +y towards +z); parameter = arc length from the first end.
std::unique_ptr<ProfileCurve> arc_curve(Vec2 centre, double radius, double angle_begin,
                                        double angle_end);

/// Straight segment from \p from to \p to; parameter = distance from \p from.
std::unique_ptr<ProfileCurve> line_curve(Vec2 from, Vec2 to);

/// A rigid placement of a curve: p -> R p + offset with R a rotation by \p angle (radians, from
/// +y towards +z), optionally preceded by mirroring y (y -> -y), and optionally reversed in
/// direction. Reversal keeps the parameter range and runs it backwards.
struct Placement {
  bool mirror_y = false;  ///< y -> -y before rotating
  double angle = 0;       ///< rotation, radians
  Vec2 offset;            ///< translation after rotating
  bool reverse = false;   ///< run the parameter backwards
};

/// \p curve seen through \p placement (shares the curve).
std::unique_ptr<ProfileCurve> placed_curve(std::shared_ptr<const ProfileCurve> curve,
                                           const Placement& placement);

/// The curve's position as jets in s (value, first and second derivative) and the jets of its
/// first derivative; what the contact locus is built from.
struct CurveJets {
  Jet y, z;    ///< position
  Jet dy, dz;  ///< first derivative
};
/// Jets of \p curve at \p s.
CurveJets curve_jets(const ProfileCurve& curve, double s);

}  // namespace railfe
