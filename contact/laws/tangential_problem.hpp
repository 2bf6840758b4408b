#pragma once
/// \file
/// Kalker's steady-rolling tangential problem on the half-space grid, given the pressures: the
/// slip s = w − ∂u/∂x (rigid slip w from the creepages, u the elastic tangential displacement
/// difference, x the rolling direction; material enters at +x) vanishes where the traction is
/// below the bound μ p (adhesion), and the traction is −μ p s/|s| where it slides. Friction may
/// fall with the slip velocity: μ = μd + (μs − μd) exp(−c |v|), |v| = V |s|. Solved by
/// Gauss–Seidel sweeps from the leading edge, each element taking its exact local solution with
/// the others held; the sweeps stop when the tractions settle, and a solve that does not
/// settle says so instead of returning forces.

#include <vector>

#include "contact/laws/halfspace.hpp"
#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// Friction: Coulomb (static = dynamic) or falling with slip velocity.
struct FrictionLaw {
  double static_coefficient = 0.3;   ///< μs
  double dynamic_coefficient = 0.3;  ///< μd
  double decay = 0;                  ///< c (s/m)
  double rolling_speed = 30;         ///< V (m/s), turns slip into slip velocity
  /// μ at slip velocity \p speed (m/s).
  double at(double speed) const;
};

/// How the transport term ∂u/∂x of the slip is discretised along the rolling direction, at the
/// element's centre where the rigid slip and the traction are.
enum class TransportScheme {
  /// (u(x) - u(x + dx)) / dx: first order. With the rigid slip at the centre it shifts the
  /// adhesion condition half an element towards the leading edge, which spin's rigid slip φx
  /// turns into a lateral creepage error φ dx / 2 (C23, C33 converge at first order).
  first_order,
  /// (3 u(x) - 4 u(x + dx) + u(x + 2 dx)) / (2 dx), the second-order upwind (BDF2) difference:
  /// slip, rigid slip and traction all at the centre, second order in ξ, η and φ; the element
  /// that leads its row takes the edge's singular form (TangentialSettings::leading_edge).
  second_order,
  /// BDF2 on every element, the leading ones too (only to show what the edge's form gains: the
  /// small-spin force then converges as dx^0.7 from below, 1.8 % low at 40 × 40).
  second_order_smooth_edge,
};

/// Settings of the tangential solve.
struct TangentialSettings {
  /// The transport term's discretisation (first order only to show the convergence gained).
  TransportScheme transport = TransportScheme::second_order;
  /// Per row of the grid, x (m) of the contact's leading edge, where the material enters (NaN
  /// where unknown). The second-order difference of the element that leads its row reads two
  /// displacements outside the contact, where ∂u/∂x has the edge's square-root singularity; it
  /// takes that form from the edge, placed here or, where unknown, at the element's leading side
  /// (HertzPatch::leading_edge gives the ellipse's).
  std::vector<double> leading_edge;
  /// Per row of the grid, the part of the longitudinal rigid slip that varies across the patch,
  /// in place of the spin's −φ y: on a conformal contact the wheel's rolling radius R(y) changes
  /// nonlinearly across it, and the rigid slip is ξ − (R(y) − R(0)) / R(0). Empty: −φ y.
  std::vector<double> row_longitudinal_slip;
  int max_sweeps = 1000;  ///< Gauss–Seidel sweeps before giving up
  /// On the largest traction change in a sweep, relative to μs max p. The forces then lie
  /// within about 1e-9 μN of the settled ones (Coulomb, Hertz patch at 40 × 40).
  double tolerance = 1e-6;
  /// Start from full slip (μs p against the rigid slip) instead of no traction: with falling
  /// friction two starts that end apart show the solution is not unique.
  bool start_in_full_slip = false;
};

/// A tangential solution.
struct TangentialSolution {
  std::vector<double> qx, qy;    ///< tractions on body 1 (Pa)
  std::vector<double> sx, sy;    ///< slip (dimensionless; times V for velocity)
  std::vector<bool> adhesion;    ///< per element in contact
  CreepForces forces;            ///< N, N m
  int sweeps = 0;                ///< sweeps taken
  bool converged = false;        ///< the tractions settled
  double adhesion_fraction = 0;  ///< of the contact area
};

/// Steady rolling with a uniqueness check: with falling friction (μd < μs and c > 0) the problem
/// is solved from no traction and from full slip, each to a tolerance of at most 1e-4 \p spread;
/// where the two settle apart by more than \p spread × μs N, the steady state is not unique and
/// the result says so (converged false, forces NaN, \p spread_found set). Coulomb friction is
/// solved once.
TangentialSolution solve_steady_rolling(const HalfSpaceKernels& kernels,
                                        const std::vector<double>& pressure, const Creepages& creep,
                                        const FrictionLaw& friction, double spread = 1e-6,
                                        double* spread_found = nullptr,
                                        const TangentialSettings& settings = {});

/// Tangential tractions for pressures \p pressure (Pa per element of \p kernels' grid),
/// creepages \p creep and friction \p friction.
TangentialSolution solve_tangential(const HalfSpaceKernels& kernels,
                                    const std::vector<double>& pressure, const Creepages& creep,
                                    const FrictionLaw& friction,
                                    const TangentialSettings& settings = {});

}  // namespace railfe
