#include "framework/solvers/prescribed_saddle_point_solver.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "framework/base/error.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"

namespace railfe {

PrescribedSaddlePointSolver::PrescribedSaddlePointSolver(DenseSecondOrderSystem& system,
                                                         double backward_error_limit)
    : system_(system), limit_(backward_error_limit) {}

void PrescribedSaddlePointSolver::factor(const double* u, const double* v,
                                         const MatrixCoefficients& coefficients,
                                         const ConstraintRows& rows) {
  const auto n = static_cast<Eigen::Index>(system_.n_unknowns());
  is_prescribed_.assign(n, 0);
  prescribed_.resize(rows.size());
  coefficient_.resize(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows.offsets[i + 1] - rows.offsets[i] != 1)
      throw std::invalid_argument("PrescribedSaddlePointSolver: constraint row " +
                                  std::to_string(i) + " does not prescribe a single unknown");
    const auto column = static_cast<Eigen::Index>(rows.columns[rows.offsets[i]]);
    if (is_prescribed_[column])
      throw std::invalid_argument("PrescribedSaddlePointSolver: unknown " + std::to_string(column) +
                                  " is prescribed by two rows");
    is_prescribed_[column] = 1;
    prescribed_[i] = column;
    coefficient_(static_cast<Eigen::Index>(i)) = rows.values[rows.offsets[i]];
  }
  free_.clear();
  for (Eigen::Index j = 0; j < n; ++j)
    if (!is_prescribed_[j])
      free_.push_back(j);

  system_.form_matrix(u, v, coefficients);
  const Eigen::MatrixXd& a = system_.matrix();
  const auto n_free = static_cast<Eigen::Index>(free_.size());
  free_matrix_.resize(n_free, n_free);
  for (Eigen::Index j = 0; j < n_free; ++j)
    for (Eigen::Index i = 0; i < n_free; ++i)
      free_matrix_(i, j) = a(free_[i], free_[j]);
  lu_.compute(free_matrix_);
  const auto pivots = lu_.matrixLU().diagonal().cwiseAbs();
  // Exact zeros only (an unknown with neither mass nor stiffness); the backward error of every
  // solve judges the rest.
  if (n_free > 0 && (!(pivots.minCoeff() > 0) || !std::isfinite(pivots.sum())))
    throw RunError(
        "the free block of the time step's matrix is singular (an unknown without "
        "mass or stiffness that no constraint prescribes)");
  norm_ = n_free > 0 ? free_matrix_.cwiseAbs().rowwise().sum().maxCoeff() : 0.0;
  ++factorizations_;
}

void PrescribedSaddlePointSolver::solve(const double* r, const double* r_c, double* x, double* mu) {
  const Eigen::MatrixXd& a = system_.matrix();
  const auto n = a.rows();
  const auto n_free = static_cast<Eigen::Index>(free_.size());
  x_.setZero(n);
  rhs_.resize(n_free);
  for (Eigen::Index i = 0; i < n_free; ++i)
    rhs_(i) = r[free_[i]];
  // r_f − A_fp x_p, column by column of the prescribed unknowns (contiguous in A).
  for (std::size_t k = 0; k < prescribed_.size(); ++k) {
    const Eigen::Index p = prescribed_[k];
    x_(p) = r_c[k] / coefficient_(static_cast<Eigen::Index>(k));
    if (x_(p) != 0)
      for (Eigen::Index i = 0; i < n_free; ++i)
        rhs_(i) -= a(free_[i], p) * x_(p);
  }
  solution_ = lu_.solve(rhs_);
  for (Eigen::Index i = 0; i < n_free; ++i)
    x_(free_[i]) = solution_(i);
  check_backward_error(rhs_ - free_matrix_ * solution_, norm_, solution_, rhs_, limit_,
                       "prescribed-unknown saddle-point solve (dense LU of the free block)");
  // The multipliers from the prescribed rows alone.
  for (std::size_t k = 0; k < prescribed_.size(); ++k) {
    const Eigen::Index p = prescribed_[k];
    mu[k] = (r[p] - a.row(p).dot(x_)) / coefficient_(static_cast<Eigen::Index>(k));
  }
  Eigen::Map<Eigen::VectorXd>(x, n) = x_;
}

}  // namespace railfe
