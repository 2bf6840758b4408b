#pragma once
/// \file
/// The inverse steady-rolling problem, as Kalker's CONTACT solves it with prescribed forces:
/// given the pressures, the spin and the tangential forces Fx, Fy, find the creepages ξ and η
/// whose exact steady-rolling solution (tangential_problem.hpp) carries those forces. Used to
/// set an exact-solver patch beside a finite-element one that reports forces, not creepages.

#include <string>
#include <vector>

#include "contact/laws/tangential_problem.hpp"

namespace railfe {

/// The creepages found for prescribed forces.
struct InverseCreepageResult {
  Creepages creepages;          ///< ξ, η found; φ as given
  TangentialSolution solution;  ///< the exact solution at those creepages
  int iterations = 0;           ///< Newton iterations (each three tangential solves)
  bool converged = false;       ///< the forces were met to the tolerance
  std::string failure;          ///< why not, when not converged
};

/// Creepages (ξ, η) for tangential forces \p Fx, \p Fy (N, on body 1, the sign convention of
/// CreepForces) under pressures \p pressure on \p kernels' grid, with spin \p spin (1/m) and
/// friction \p friction. Newton's method on (ξ, η) with a finite-difference Jacobian and
/// backtracking, from zero creepage; converged when |F − F*| ≤ \p tolerance μs N. Forces at or
/// beyond the traction bound μs N have no steady-rolling solution with finite creepage: the
/// result then says so without iterating. With falling friction the creepage found is the one
/// reached from zero (the smallest), where several carry the same force.
InverseCreepageResult solve_for_creepages(const HalfSpaceKernels& kernels,
                                          const std::vector<double>& pressure, double Fx, double Fy,
                                          double spin, const FrictionLaw& friction,
                                          double tolerance = 1e-6,
                                          const TangentialSettings& settings = {});

}  // namespace railfe
