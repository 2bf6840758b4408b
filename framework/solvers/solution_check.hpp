#pragma once
/// \file
/// Independent check of a returned solution: residual recomputed with the distributed matrix.

#include <string>

#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

/// Norms of the residual of x for A x = b.
struct ResidualNorms {
  double relative_residual = 0;  ///< ||b − A x||₂ / ||b||₂ (0 when b = 0 and x solves it)
  double backward_error = 0;     ///< ||b − A x||∞ / (||A||∞ ||x||∞ + ||b||∞)
};

/// Computes both norms (collective).
ResidualNorms residual_norms(const TpetraMatrix& A, const TpetraVector& x, const TpetraVector& b);

/// Throws RunError naming \p method when \p norms.backward_error exceeds \p limit. Used after
/// every direct solve: a backward-stable factorization gives round-off level (~1e-16), so
/// anything far above it is a broken solve, not an ill-conditioned matrix.
void require_backward_error(const ResidualNorms& norms, double limit, const std::string& method);

}  // namespace railfe
