#pragma once
/// \file
/// The offline contact table: a rigid wheelset on a rigid track over a range of lateral shifts,
/// with the vertical position and roll that keep both wheels touching. It gives the standard
/// geometry outputs (rolling radii, their difference, contact angles, where contact jumps to the
/// flange) and the start points of the online search.

#include <array>
#include <utility>
#include <vector>

#include "contact/geometry/contact_search.hpp"

namespace railfe {

/// The rigid contact state of one lateral shift.
struct RigidContact {
  double lateral = 0;      ///< wheelset lateral shift (m)
  double vertical = 0;     ///< wheelset centre's z shift that closes both gaps (m)
  double roll = 0;         ///< roll angle that closes both gaps (rad)
  bool converged = false;  ///< both gaps closed to the tolerance
  int iterations = 0;      ///< outer Newton iterations on (vertical, roll)
  /// The tread [side][0] and flange [side][1] contact searches at the final position.
  std::array<std::array<ContactPoint, 2>, 2> parts;
  /// The touching part of \p side: the valid part with the smaller gap.
  const ContactPoint& active(TrackSide side) const;
};

/// Solves for the vertical position and roll that close both wheels' gaps at \p lateral and
/// \p yaw, starting from \p start (or from a sampled start when null). Once closed, each part
/// is sampled at \p check_samples + 1 points (none when 0); where one lies lower than the
/// contact found, the contact has jumped there and the solve goes on from it.
RigidContact solve_rigid_contact(const WheelRailGeometry& geometry, double lateral, double yaw,
                                 const RigidContact* start, int check_samples = 100);

/// Rigid contact over a uniform range of lateral shifts.
class ContactTable {
 public:
  /// Builds \p count rows for shifts from -\p max_shift to +\p max_shift (continuation from
  /// the centre outwards; \p check_samples as in solve_rigid_contact).
  ContactTable(const WheelRailGeometry& geometry, double max_shift, int count,
               int check_samples = 100);
  /// The rows in increasing shift.
  const std::vector<RigidContact>& rows() const { return rows_; }
  /// Start point (s_wheel, s_rail) for the online search of \p side's tread or flange at
  /// \p lateral (linear interpolation, clamped to the table's range).
  std::array<double, 2> start(TrackSide side, bool flange, double lateral) const;
  /// The gap of \p side's tread or flange part at the rigid contact of \p lateral (m, linear
  /// interpolation, clamped to the table's range): how far that part is from touching.
  double part_gap(TrackSide side, bool flange, double lateral) const;
  /// The searched point of \p side's tread or flange part in the row nearest \p lateral.
  const ContactPoint& part_point(TrackSide side, bool flange, double lateral) const;
  /// Rolling radius difference right minus left of row \p i (m).
  double rolling_radius_difference(std::size_t i) const;
  /// The first shift towards \p side at which that wheel's flange part carries the contact;
  /// NaN when it never does within the table.
  double flange_contact_shift(TrackSide side) const;
  /// Half the lateral distance between the two contact points of the centred wheelset (m).
  double half_contact_distance() const;
  /// Rolling radius of the centred wheelset, mean of both wheels (m).
  double centred_rolling_radius() const;

 private:
  // The row below \p lateral and the fraction of the way to the next (clamped to the table).
  std::pair<std::size_t, double> bracket(double lateral) const;

  double first_ = 0, step_ = 1;
  std::vector<RigidContact> rows_;
  // Start parameters, [row][side][part][wheel/rail], flattened for the lookup.
  std::vector<double> starts_;
};

}  // namespace railfe
