#pragma once
/// \file
/// How much the penalty layer softens a rolling contact's tangential response. A stuck slave
/// node moves A/k against the master per unit of shear traction (A its area, k its face's
/// penalty stiffness), in series with the bodies' own elastic flexibility. For a patch of
/// semi-axes a (rolling) and b, Kalker's simplified theory puts that flexibility at
/// L = 8a / (3 C11 G) (Kalker, Three-dimensional elastic bodies in rolling contact, 1990, §5.2),
/// so where the patch sticks the creep force at a given creepage is low by about
/// r / (1 + r), r = (A/k) / L. docs/theory.md#penalty-contact-explicit has the measurement.

#include <array>

namespace railfe {

class PenaltyContactPair;

/// The penalty layer's tangential flexibility against the patch's own, at one instant.
struct PenaltyFlexibility {
  double normal_force = 0;       ///< the pair's normal force (N)
  double rolling_semi_axis = 0;  ///< a = √(5 ⟨s1²⟩), pressure-weighted about the centre (m)
  double lateral_semi_axis = 0;  ///< b = √(5 ⟨s2²⟩) (m)
  double penalty = 0;  ///< normal-force-weighted mean of A/k over the active slave nodes (m/Pa)
  double patch = 0;    ///< Kalker's simplified-theory flexibility 8a / (3 C11 G) (m/Pa)
  /// penalty / patch: 0.05 costs about 5 % of the creep force where the patch sticks.
  double ratio() const { return patch > 0 ? penalty / patch : 0; }
};

/// Largest ratio of the pressure-weighted to the area-weighted ⟨s1²⟩ of a patch the comparison
/// is made for: 0.8 on a Hertz ellipse, 1 under a uniform pressure (a block on a plane).
constexpr double kPeakedPatch = 0.9;

/// The flexibilities of \p pair at its last evaluation, for bodies of shear modulus
/// \p shear_modulus (Pa) and Poisson's ratio \p poisson; a zero ratio where fewer than four
/// slave nodes touch, none sticks, the pressure does not peak inside the patch along the
/// rolling direction (kPeakedPatch), or the patch lies outside Kalker's table (a/b from 0.1 to
/// 10).
PenaltyFlexibility penalty_flexibility(const PenaltyContactPair& pair, double shear_modulus,
                                       double poisson);

}  // namespace railfe
