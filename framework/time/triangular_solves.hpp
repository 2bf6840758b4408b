#pragma once
/// \file
/// The halves of a factored symmetric positive definite A = Pᵀ L Lᵀ P, for solvers that
/// eliminate a few sparse columns B through A (BlockSaddlePointSolver): W = L⁻¹ P B by sparse
/// forward solves touches only the factor's columns on the paths from B's rows to the root of
/// the elimination tree, and Bᵀ A⁻¹ B = Wᵀ W. A SecondOrderSystem whose factor offers this
/// implements the interface too (SparseLinearSystem).

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace railfe {

/// Sparse columns over the unknowns: column i holds entries offsets[i] .. offsets[i+1].
struct SparseColumns {
  std::vector<std::size_t> offsets{0};  ///< column i's entries start at offsets[i]
  std::vector<std::size_t> rows;        ///< unknown of each entry
  std::vector<double> values;           ///< coefficient of each entry
  /// Number of columns.
  std::size_t size() const { return offsets.size() - 1; }
};

/// W = L⁻¹ P B kept on its pattern: the rows (of P A Pᵀ's numbering) where W may be nonzero.
struct ForwardSolution {
  std::vector<std::size_t> pattern;  ///< rows of W that may be nonzero, ascending
  Eigen::MatrixXd values;            ///< W on the pattern (pattern.size() × B's columns)
};

/// Triangular solves with the factor of A = Pᵀ L Lᵀ P.
class TriangularSolves {
 public:
  virtual ~TriangularSolves() = default;
  /// Whether the last factorization can do the solves below (e.g. a supernodal Cholesky factor).
  virtual bool has_triangular_factor() const = 0;
  /// \p w = L⁻¹ P \p b, visiting only the factor's columns reached from \p b's rows.
  virtual void forward_solve_sparse(const SparseColumns& b, ForwardSolution& w) = 0;
  /// \p y = L⁻¹ P \p b (dense, length n).
  virtual void forward_solve(const double* b, double* y) = 0;
  /// \p x = Pᵀ L⁻ᵀ \p y (dense, length n).
  virtual void backward_solve(const double* y, double* x) = 0;
};

}  // namespace railfe
