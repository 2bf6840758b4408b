#pragma once
/// \file
/// The elastic wheelset on track: under a vertical load the wheelset sinks into the rails by the
/// contact approach. Each local minimum of a wheel's gap that lies below zero (the tread's and
/// the flange's, so a wheel can carry two patches) is a Hertzian patch: its normal force follows
/// Hertz's force-approach law N = K(A, B) δ^{3/2}, with δ the penetration and A, B the relative
/// curvatures of both profiles at that point. Newton's method finds the vertical position and
/// roll at which the patches carry the load with no roll moment; the lateral shift and yaw are
/// prescribed, so the lateral force that holds the wheelset there is an output.

#include <array>
#include <string>

#include "contact/geometry/contact_table.hpp"
#include "contact/laws/hertz.hpp"

namespace railfe {

/// One patch of the elastic solution.
struct ElasticPatch {
  ContactPoint point;    ///< the gap minimum at the final pose (gap < 0 where it carries load)
  HertzContact hertz;    ///< Hertz's contact at that approach (all zero when it carries none)
  double force_y = 0;    ///< lateral force of the rail on the wheel (N, to the right)
  double force_z = 0;    ///< vertical force of the rail on the wheel (N, down; negative = up)
  bool loaded() const {  ///< whether the patch carries a normal force
    return hertz.load > 0;
  }
};

/// The elastic equilibrium of one lateral shift.
struct ElasticContact {
  WheelsetPose pose;       ///< lateral and yaw as given; vertical and roll solved
  bool converged = false;  ///< the force and moment residuals met the tolerance
  int iterations = 0;      ///< Newton iterations taken
  /// Patches [side][part] (part 0 tread, 1 flange).
  std::array<std::array<ElasticPatch, 2>, 2> patches;
  double vertical_residual = 0;  ///< load + sum of the patches' vertical forces (N)
  double roll_residual = 0;      ///< sum of the patches' moments about the wheelset centre (N m)
  double lateral_force = 0;      ///< sum of the patches' lateral forces (N): held by the axle
  /// Why it failed when it did (a contact that is not Hertzian, no contact found); else empty.
  std::string failure;
};

/// Solves the elastic equilibrium of a wheelset carrying \p load (N, per wheelset, down) at the
/// lateral shift of \p rigid and \p yaw (the rigid vertical position and roll are the start), with
/// contact modulus \p modulus (Pa, see contact_modulus). Converges when the force residual is below
/// 1e-10 of the load and the roll moment below 1e-10 load x gauge; at most 100 iterations.
ElasticContact solve_elastic_contact(const WheelRailGeometry& geometry, const RigidContact& rigid,
                                     double yaw, double load, double modulus);

}  // namespace railfe
