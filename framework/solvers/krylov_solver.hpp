#pragma once
/// \file
/// Belos Krylov solvers (CG, GMRES) with an optional preconditioner.

#include <memory>
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

}  // namespace railfe
