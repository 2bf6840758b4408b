#pragma once
/// \file
/// Saturation laws that vehicle-dynamics codes put on top of Kalker's linear theory so that the
/// creep force cannot exceed μN.
///
/// Shen, Hedrick & Elkins (1983): with β = |F_linear| / (μN), the resultant becomes
/// μN (β − β²/3 + β³/27) for β < 3 and μN beyond, both components and the spin moment scaled
/// alike.
///
/// Polach (VSD 33 suppl., 1999; Wear 258, 2005): the resultant creepage s_C = √(ξ² + η_C²), with
/// η_C = η + φa where spin adds to the lateral creepage (|η + φa| > |η|) and η otherwise, gives
///   F = (2μQ/π) (k_A ε / (1 + (k_A ε)²) + arctan(k_S ε)),  ε = π G a b c_jj s_C / (4μQ),
/// c_jj = √((C11 ξ/s)² + (C22 η/s)²), s = √(ξ² + η²), shared as Fx = −F ξ/s_C, Fy = −F η/s_C;
/// spin adds the lateral force (9/16) a μ Q K_M (1 + 6.3 (1 − e^(−a/b))) φ / s_C with
///   K_M = |ε_M| (δ³/3 − δ²/2 + 1/6) − (1 − δ²)^(3/2) / 3,  δ = (ε_M² − 1) / (ε_M² + 1),
///   ε_M = 8 G b √(ab) C23 |η_C| / (3 μ Q (1 + 6.3 (1 − e^(−a/b)))).
/// Friction may fall with the slip velocity w = V s_C: μ = μ0 ((1 − A) e^(−B w) + A). Polach's
/// model has no spin moment.

#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// The Shen-Hedrick-Elkins saturation of the linear forces \p linear under normal force \p load
/// (N > 0) and friction coefficient \p friction.
CreepForces shen_hedrick_elkins(const CreepForces& linear, double load, double friction);

/// The parameters of Polach's model beyond the contact's own.
struct PolachParameters {
  double friction = 0.3;          ///< μ0, friction at zero slip velocity
  double adhesion_reduction = 1;  ///< k_A: reduces the slope in the area of adhesion (0 to 1]
  double slip_reduction = 1;      ///< k_S: reduces it in the area of slip (0 to k_A]
  double friction_ratio = 1;      ///< A = μ∞ / μ0 (0 to 1]; 1: friction independent of speed
  double friction_decay = 0;      ///< B (s/m), the exponential decrease of friction with w
  double rolling_speed = 30;      ///< V (m/s), turns creepage into slip velocity
};

/// Polach's creep forces on body 1 for an ellipse \p a × \p b (a along the rolling direction)
/// under normal force \p load (N > 0), combined shear modulus \p G, Kalker coefficients \p c and
/// creepages \p creep. Mz is NaN: the model gives none. Throws std::invalid_argument for
/// parameters outside their ranges.
CreepForces polach(const KalkerCoefficients& c, double G, double a, double b, double load,
                   const Creepages& creep, const PolachParameters& parameters = {});

}  // namespace railfe
