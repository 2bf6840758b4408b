#pragma once
/// \file
/// A SaddlePointSolver for a dense system whose constraint rows each prescribe one unknown
/// (c_i x_{p_i} = g_i, every row a single entry on an unknown of its own): the internal nodes
/// of contact elements on rigid rails. The prescribed unknowns are eliminated rather than
/// bordered: x_p = r_c / c, A_ff x_f = r_f − A_fp x_p (a dense LU of the free block only), and
/// the multipliers follow from the prescribed rows, μ_i = (r_{p_i} − (A x)_{p_i}) / c_i. For a
/// vehicle of 42 free unknowns and 48 prescribed this factors a 42-row matrix where the bordered
/// one has 138.

#include <Eigen/Dense>

#include <vector>

#include "framework/time/constraint_set.hpp"
#include "framework/time/dense_system.hpp"

namespace railfe {

/// Elimination of prescribed unknowns (see the file comment).
class PrescribedSaddlePointSolver : public SaddlePointSolver {
 public:
  /// A solver for \p system (not owned); \p backward_error_limit bounds every solve's check.
  explicit PrescribedSaddlePointSolver(DenseSecondOrderSystem& system,
                                       double backward_error_limit = 1e-10);
  /// Forms A at (u, v) and LU-factors its free block. Throws std::invalid_argument when a row
  /// has other than one entry or two rows prescribe the same unknown, RunError when the free
  /// block is singular.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients,
              const ConstraintRows& rows) override;
  /// Solves and checks the backward error of A x + Cᵀ μ = r on the free rows.
  void solve(const double* r, const double* r_c, double* x, double* mu) override;
  /// Number of factor() calls so far.
  std::size_t factorizations() const { return factorizations_; }

 private:
  DenseSecondOrderSystem& system_;
  double limit_;
  std::vector<Eigen::Index> free_, prescribed_;  // unknowns; prescribed_[i] by row i
  Eigen::VectorXd coefficient_;                  // c_i of row i
  std::vector<char> is_prescribed_;
  Eigen::MatrixXd free_matrix_;  // A_ff
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  double norm_ = 0;  // ‖A_ff‖∞
  Eigen::VectorXd rhs_, solution_, x_;
  std::size_t factorizations_ = 0;
};

}  // namespace railfe
