#pragma once
/// \file
/// Belos Krylov solvers (CG, GMRES) with an optional preconditioner.

#include <memory>
#include <optional>
#include <string>

#include "framework/solvers/linear_solver.hpp"

namespace railfe {

/// How a Krylov solve is configured.
struct KrylovSettings {
  std::string method = "cg";             ///< "cg" or "gmres"
  std::string preconditioner = "muelu";  ///< "muelu", "ilu", "jacobi" or "none"
  double relative_tolerance = 1e-10;     ///< stop when ||r|| / ||b|| falls below it
  int maximum_iterations = 1000;         ///< give up (with an error) after this many
  int restart = 100;                     ///< GMRES Krylov space size before restart
};

/// A Belos solver configured by \p settings. Its solve() throws RunError when it does not reach
/// the tolerance, checking the true residual, not only Belos' recursive one.
std::unique_ptr<LinearSolver> make_krylov_solver(const KrylovSettings& settings);

/// CG on A x = b from the guess in \p x, preconditioned by \p preconditioner, to
/// \p relative_tolerance (the true residual) within \p maximum_iterations (collective). Made for
/// a matrix close to one already factorized, whose factor is the preconditioner: unlike a
/// LinearSolver it does not throw when it misses or breaks down but returns nothing (x is then
/// undefined), and the caller factorizes instead.
std::optional<SolveReport> try_preconditioned_cg(const Teuchos::RCP<const TpetraMatrix>& A,
                                                 const Teuchos::RCP<TpetraOperator>& preconditioner,
                                                 const TpetraVector& b, TpetraVector& x,
                                                 double relative_tolerance, int maximum_iterations);

}  // namespace railfe
