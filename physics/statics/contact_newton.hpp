#pragma once
/// \file
/// A static solve with penalty contact: K u = f + f_c(u), K linear elastic, f_c the frictionless
/// penalty force of the contact pairs. Each iteration linearises the contact about the current
/// state (active set and projections frozen) and solves for the total displacement, so the
/// prescribed values and ties are applied as in a linear solve (with a direct solver, by CG on
/// the last factorization where that converges), then cuts a step that overshoots back to the
/// energy's minimum along it (line search); it stops when the out-of-balance
/// force on the free DOFs falls below the tolerance times the largest of the load, reaction and
/// contact force norms (docs/theory.md#penalty-contact-in-statics).

#include <string>

#include "framework/assembly/dof_map.hpp"
#include "framework/solvers/linear_solver.hpp"

namespace railfe {

class ContactPairs;
class LinearConstraints;
class Progress;

/// What the iterations did.
struct ContactNewtonReport {
  int iterations = 0;             ///< linear solves
  int factorizations = 0;         ///< of those, solved after a solver set-up (a factorization)
  int reused_factorizations = 0;  ///< solved by CG preconditioned by an earlier factorization
  double residual = 0;            ///< out-of-balance force on free DOFs over the force scale
  long long active = 0;           ///< active slave nodes at the end
  double contact_force = 0;       ///< 2-norm of the contact forces at the end (N)
  int shortened_steps = 0;        ///< halvings of steps that lifted every contact off
  int line_searches = 0;          ///< steps shortened to the energy's minimum along them
  SolveReport solve;              ///< the last linear solve; setup and solve seconds summed
};

/// Solves for \p u (owned DOFs; its start value is the first linearisation point). \p K is the
/// assembled elastic stiffness (unchanged), \p f the loads, \p constraints finalized, \p contact
/// initialised. Throws RunError naming \p path when \p max_iterations pass without reaching
/// \p tolerance, with the residual and active-set history. Collective.
ContactNewtonReport solve_with_contact(const Teuchos::RCP<TpetraMatrix>& K, const TpetraVector& f,
                                       LinearConstraints& constraints, LinearSolver& solver,
                                       const ProblemTraits& traits, ContactPairs& contact,
                                       const DofMap& dofs, int max_iterations, double tolerance,
                                       const std::string& path, TpetraVector& u,
                                       Progress& progress);

}  // namespace railfe
