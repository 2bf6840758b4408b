#pragma once
/// \file
/// Online contact-point search between a wheel and a rail in the track's cross-section, on the
/// wheel's contact locus so that yaw is taken into account. The two contact conditions are
/// solved nested: for a wheel parameter, Newton finds its foot on the rail (the rail tangent
/// orthogonal to the distance); a trust-region Newton iteration on the wheel parameter then
/// minimises the signed gap, whose slope is the second condition (the rail normal orthogonal to
/// the wheel tangent). Minimising the gap, not the conditions' residual, keeps near-conformal
/// contact well posed (docs/theory.md). Tread and flange are searched separately, so a wheel can
/// touch at two points.

#include <array>
#include <string>

#include "contact/geometry/wheel_rail_geometry.hpp"

namespace railfe {

/// Why a search ended.
enum class SearchStatus {
  converged,      ///< a minimum of the gap inside the part
  part_boundary,  ///< the gap is least at the end of the part: the other part's contact
  not_a_minimum,  ///< the contact conditions hold at a maximum or saddle of the gap
  not_converged   ///< no convergence within the iteration limit
};

/// Text for \p status ("converged", "part boundary", ...).
std::string status_name(SearchStatus status);

/// Settings of the Newton iterations.
struct SearchSettings {
  int max_iterations = 50;       ///< Newton iterations on the wheel parameter before giving up
  double tolerance = 1e-12;      ///< converged when the Newton correction is below this (m)
  double trust_radius = 2e-3;    ///< initial trust-region radius in the wheel parameter (m)
  bool use_trust_region = true;  ///< false: plain Newton (clipped to the part)
  /// The stretch of the part searched, in wheel parameter (default: the whole part). A
  /// contact element narrows it to where the rigid contact table found contacts, so that the
  /// conformal flange root a new profile never touches rigidly is not searched.
  double first = -1e300;
  double last = 1e300;  ///< end of the stretch searched
};

/// The wheel parameter range of \p side's tread or (\p flange) flange part, narrowed to
/// [settings.first, settings.last] (the part itself where they do not overlap it).
std::array<double, 2> searched_range(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                                     const SearchSettings& settings);

/// A wheel-rail contact point.
struct ContactPoint {
  SearchStatus status = SearchStatus::not_converged;  ///< how the search ended
  int iterations = 0;                                 ///< Newton iterations taken
  bool flange = false;        ///< searched on the flange part (else the tread)
  double s_wheel = 0;         ///< wheel profile parameter
  double s_rail = 0;          ///< rail profile parameter
  Vec2 rail_point;            ///< contact point on the rail, track coordinates (m)
  Vec2 normal;                ///< unit rail normal, out of the rail (track coordinates)
  double x = 0;               ///< longitudinal position of the wheel point (m; nonzero under yaw)
  double gap = 0;             ///< normal distance, negative when penetrating (m)
  double contact_angle = 0;   ///< rail normal from vertical, positive towards the flange (rad)
  double rolling_radius = 0;  ///< wheel radius at the point (m)
  double wheel_lateral_curvature = 0;  ///< wheel profile curvature, convex positive (1/m)
  double wheel_rolling_curvature = 0;  ///< wheel curvature along the rolling direction (1/m)
  double rail_lateral_curvature = 0;   ///< rail profile curvature, convex positive (1/m)
  /// Hertz's A: half the sum of the curvatures along the rolling direction (1/m).
  double relative_curvature_rolling() const { return 0.5 * wheel_rolling_curvature; }
  /// Hertz's B: half the sum of the lateral curvatures (1/m).
  double relative_curvature_lateral() const {
    return 0.5 * (wheel_lateral_curvature + rail_lateral_curvature);
  }
  /// Penetration (m, zero when apart).
  double penetration() const { return gap < 0 ? -gap : 0.0; }
  /// Whether a contact point was found (a gap minimum inside the part).
  bool valid() const { return status == SearchStatus::converged; }
};

/// Solves the contact conditions for the tread (\p flange false) or flange of the wheel of
/// \p side in \p pose, from the start (\p s_wheel, \p s_rail).
ContactPoint search_contact(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                            const WheelsetPose& pose, double s_wheel, double s_rail,
                            const SearchSettings& settings = {});

/// The contact point at the wheel parameter \p s_wheel held fixed (its foot on the rail found
/// from \p s_rail, the gap, normal and curvatures there), status converged: the point an
/// offline contact table prescribes, with no search along the wheel.
ContactPoint contact_at(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                        const WheelsetPose& pose, double s_wheel, double s_rail);

/// A sampled point of a wheel part and its gap.
struct GapSample {
  double s_wheel = 0;  ///< wheel profile parameter
  double s_rail = 0;   ///< parameter of its foot on the rail
  double gap = 0;      ///< signed distance to the rail (m)
};

/// The least gap over \p samples + 1 evenly spaced points of the tread or (\p flange) the
/// flange of \p side in \p pose: a start for \p search_contact found without a table, and the
/// check that a converged search found the part's lowest minimum.
GapSample least_gap_sample(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                           const WheelsetPose& pose, int samples = 200,
                           const SearchSettings& settings = {});

}  // namespace railfe
