#pragma once
/// \file
/// Direct solvers. Both gather the matrix on rank 0 and solve there, since neither runs
/// distributed here; both check the backward error of every solve.

#include <memory>

#include "framework/solvers/linear_solver.hpp"

namespace railfe {

/// CHOLMOD supernodal Cholesky with METIS ordering (SuiteSparse), for symmetric positive definite
/// matrices. \p backward_error_limit bounds the accepted backward error.
std::unique_ptr<LinearSolver> make_cholmod_solver(double backward_error_limit);

/// Amesos2 KLU2 (general sparse LU) on a one-rank communicator. Far slower than CHOLMOD on 3-D
/// elasticity; kept for unsymmetric or indefinite systems.
std::unique_ptr<LinearSolver> make_klu2_solver(double backward_error_limit);

}  // namespace railfe
