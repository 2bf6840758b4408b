#pragma once
/// \file
/// The linear solver layer. Every solver checks the answer it returns: iterative solvers the true
/// residual, direct solvers the normwise backward error. A solve that misses its target throws
/// RunError rather than returning a wrong answer.

#include <functional>
#include <memory>
#include <string>

#include "framework/assembly/tpetra_types.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/output/progress.hpp"

namespace railfe {

/// What a solver may assume about, and use from, the problem.
struct ProblemTraits {
  /// The matrix is symmetric positive definite (CG, CHOLMOD and MueLu's defaults rely on it).
  bool symmetric_positive_definite = true;
  /// Unknowns per mesh node (MueLu aggregates node blocks).
  int dofs_per_node = 1;
  /// Names global DOF \p dof in messages ("node N component c"); when empty, describe_dof() with
  /// dofs_per_node does (right for uniform layouts only).
  std::function<std::string(GlobalIndex)> name_dof;
  /// Coordinates of the owned nodes, one column per axis (optional; helps MueLu).
  Teuchos::RCP<const TpetraMultiVector> node_coordinates;
  /// Near null space over the owned DOFs, e.g. the six rigid-body modes of elasticity (optional;
  /// MueLu smoothed aggregation needs it to be efficient on elasticity).
  Teuchos::RCP<const TpetraMultiVector> near_null_space;
};

/// What one solve did, for the run summary.
struct SolveReport {
  std::string method;            ///< e.g. "CG + MueLu SA" or "CHOLMOD supernodal (rank 0)"
  int iterations = 0;            ///< Krylov iterations (0 for direct solvers)
  double relative_residual = 0;  ///< ||b − A x|| / ||b||, recomputed from the returned x
  double backward_error = 0;     ///< ||b − A x||∞ / (||A||∞ ||x||∞ + ||b||∞)
  double setup_seconds = 0;      ///< factorization or preconditioner set-up
  double solve_seconds = 0;      ///< the solve itself, including the residual check
};

/// A configured solver for A x = b.
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Prepares for \p A: factorizes, or builds the preconditioner (collective). \p A must stay
  /// alive and unchanged until the next setup().
  virtual void setup(const Teuchos::RCP<const TpetraMatrix>& A, const ProblemTraits& traits) = 0;
  /// Solves A x = b, x holding the initial guess for iterative methods (collective). Throws
  /// RunError if the solution does not meet the configured accuracy.
  virtual SolveReport solve(const TpetraVector& b, TpetraVector& x) = 0;
  /// Solves A X = B for every column of \p B (collective); the report gives the worst column.
  /// The default solves the columns one after another; direct solvers override it to pass over
  /// their factor once for all columns (eigensolvers apply the inverse to blocks of vectors).
  virtual SolveReport solve_block(const TpetraMultiVector& B, TpetraMultiVector& X);
  /// The inverse of the last set-up matrix as an operator, from its factorization, for use as a
  /// preconditioner of a nearby matrix (it skips the backward-error check); null for solvers
  /// without a factorization. It stays valid while the solver lives and follows later setups.
  virtual Teuchos::RCP<TpetraOperator> factor_operator() { return Teuchos::null; }
  /// Reports the progress of later solves to \p progress (may be null; it must outlive the
  /// solves). Iterative solvers report the share of the residual reduction achieved.
  void report_progress_to(Progress* progress) { progress_ = progress; }
  /// Whether direct solvers recompute the backward error of every solution (default true).
  /// Callers that verify their end result independently, such as an eigensolver that checks
  /// every eigenpair against K and M, may turn it off: it costs a matrix product per column,
  /// a third of a shift-inverted Krylov step.
  void check_solutions(bool check) { check_solutions_ = check; }
  /// Whether direct solvers check every solution (see check_solutions(bool)).
  bool checks_solutions() const { return check_solutions_; }

 protected:
  Progress* progress_ = nullptr;  ///< where solves report progress, or null
  bool check_solutions_ = true;   ///< see check_solutions()
};

/// The valid parameters of a "Linear solver" sublist, with \p default_method as the Method
/// when none is given (the implicit module factors once and defaults to "cholmod").
ParameterSpec linear_solver_parameters(const std::string& default_method = "cg");

/// Creates the solver a validated "Linear solver" sublist describes.
std::unique_ptr<LinearSolver> create_linear_solver(const Teuchos::ParameterList& parameters);

}  // namespace railfe
