#pragma once
/// \file
/// A wheelset on a straight track, in track coordinates: x along the track, y lateral (to the
/// right), z down, origin at the track centre line on the top of the rails. Rail profiles are
/// given for the right rail (y towards the field side, z down); wheel profiles as the S1002 file
/// lists them (y from the running point towards the flange, z radially outwards). The left side
/// is the mirror image.

#include <array>
#include <memory>

#include "contact/geometry/jet.hpp"
#include "contact/geometry/profile_curve.hpp"

namespace railfe {

/// Track dimensions.
struct TrackLayout {
  double gauge = 1.435;           ///< between the rails' gauge points (m)
  double gauge_depth = 0.014;     ///< depth of the gauge point below the top of rail (m)
  double inclination = 1.0 / 40;  ///< rail cant, tan of the angle towards the track centre
  bool profile_inclined = false;  ///< the rail profile is already canted: do not rotate it
};

/// Wheelset dimensions.
struct WheelsetLayout {
  double back_to_back = 1.360;   ///< between the flange back faces (m)
  double flange_back = 0.070;    ///< the profile's y of the flange back face (m)
  double nominal_radius = 0.46;  ///< rolling radius at the profile's y = 0 (m)
};

/// Rigid-body position of the wheelset relative to its centred nominal position.
struct WheelsetPose {
  double lateral = 0;   ///< y shift of the wheelset centre (m, to the right)
  double vertical = 0;  ///< z shift of the wheelset centre (m, down)
  double roll = 0;      ///< rotation about x (rad; positive lowers the right wheel)
  double yaw = 0;       ///< rotation about z, down (rad; positive turns the axle's right end back)
};

/// Side of the track.
enum class TrackSide { left = 0, right = 1 };

/// One point of a wheel's contact locus: where on the wheel (profile parameter s) its surface
/// normal lies in the track's cross-section, so it can meet a straight rail's normal there.
struct LocusPoint {
  Jet y, z;           ///< position in the cross-section, with derivatives in s
  double x = 0;       ///< longitudinal position (nonzero under yaw)
  double radius = 0;  ///< distance to the axle: the rolling radius (m)
  /// Curvature of the wheel in the rolling direction (normal section), convex positive (1/m).
  double rolling_curvature = 0;
};

/// Profiles placed on a track and a wheelset; the geometry both contact searches work on.
class WheelRailGeometry {
 public:
  /// \p rail: the right rail's profile (y to the field side, z down); \p wheel: the right
  /// wheel's profile (y to the flange, z radially out). Both sides use the mirrored profiles.
  WheelRailGeometry(std::shared_ptr<const ProfileCurve> rail,
                    std::shared_ptr<const ProfileCurve> wheel, const TrackLayout& track,
                    const WheelsetLayout& wheelset);

  /// The rail of \p side in track coordinates, y increasing along s (outward normal upwards).
  const ProfileCurve& rail(TrackSide side) const { return *rails_[static_cast<int>(side)]; }
  /// The wheel profile of \p side in wheelset coordinates (eta along the axle to the right,
  /// rho = radius), eta increasing along s.
  const ProfileCurve& wheel(TrackSide side) const { return *wheels_[static_cast<int>(side)]; }
  /// The wheel parameter that separates tread (field side) from flange: the most concave point
  /// of the flange root.
  double flange_split(TrackSide side) const { return split_[static_cast<int>(side)]; }
  /// The wheel parameter range {first, last} of the tread or (\p flange) the flange of \p side.
  std::array<double, 2> part_range(TrackSide side, bool flange) const;
  /// The wheel parameter of the running circle (the profile's y = 0).
  double running_point(TrackSide side) const { return running_[static_cast<int>(side)]; }
  /// The contact locus of the wheel of \p side at parameter \p s for \p pose.
  LocusPoint locus(TrackSide side, double s, const WheelsetPose& pose) const;
  /// Track dimensions.
  const TrackLayout& track() const { return track_; }
  /// Wheelset dimensions.
  const WheelsetLayout& wheelset() const { return wheelset_; }

 private:
  TrackLayout track_;
  WheelsetLayout wheelset_;
  std::array<std::shared_ptr<const ProfileCurve>, 2> rails_, wheels_;
  std::array<double, 2> split_{}, running_{};
};

/// The parameter in [\p from, \p to] where \p curve's coordinate (0 = y, 1 = z) equals
/// \p value, by sampling then bisection; NaN when it is not crossed.
double parameter_where(const ProfileCurve& curve, int coordinate, double value, double from,
                       double to);

}  // namespace railfe
