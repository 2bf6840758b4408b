#include "framework/time/sparse_system.hpp"

#include <cmath>
#include <cstdio>

#include "framework/base/error.hpp"

namespace railfe {

using Vector = Eigen::Map<Eigen::VectorXd>;
using ConstVector = Eigen::Map<const Eigen::VectorXd>;

double infinity_norm(const Eigen::SparseMatrix<double>& matrix) {
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(matrix.rows());
  for (Eigen::Index j = 0; j < matrix.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, j); it; ++it)
      row_sums[it.row()] += std::abs(it.value());
  return matrix.rows() > 0 ? row_sums.maxCoeff() : 0.0;
}

SparseLinearSystem::SparseLinearSystem(Matrix mass, Matrix damping, Matrix stiffness,
                                       std::function<void(double, double*)> load,
                                       double backward_error_limit)
    : mass_(std::move(mass)),
      damping_(std::move(damping)),
      stiffness_(std::move(stiffness)),
      load_(std::move(load)),
      limit_(backward_error_limit) {
  if (damping_.rows() == 0)
    damping_.resize(mass_.rows(), mass_.cols());
}

void SparseLinearSystem::internal_force(const double* u, const double* v, double* force) {
  const Eigen::Index n = mass_.rows();
  Vector(force, n) = stiffness_ * ConstVector(u, n) + damping_ * ConstVector(v, n);
}

void SparseLinearSystem::external_force(double time, double* force) {
  if (load_)
    load_(time, force);
  else
    Vector(force, mass_.rows()).setZero();
}

void SparseLinearSystem::apply_mass(const double* x, double* y) {
  Vector(y, mass_.rows()) = mass_ * ConstVector(x, mass_.rows());
}

void SparseLinearSystem::apply_rayleigh_stiffness(const double* x, double* y) {
  Vector(y, mass_.rows()) = stiffness_ * ConstVector(x, mass_.rows());
}

void SparseLinearSystem::factor(const double*, const double*, const MatrixCoefficients& c) {
  matrix_ =
      c.mass * mass_ + c.damping * damping_ + (c.stiffness + c.rayleigh_stiffness) * stiffness_;
  if (analyzed_) {
    cholesky_.factorize(matrix_);  // same pattern: reuse the ordering
  } else {
    cholesky_.analyzePattern(matrix_);
    cholesky_.factorize(matrix_);
    analyzed_ = true;
  }
  if (cholesky_.info() != Eigen::Success)
    throw RunError("CHOLMOD could not factor the structure's matrix (not positive definite)");
  norm_infinity_ = infinity_norm(matrix_);
}

void SparseLinearSystem::check(const Eigen::MatrixXd& b, const Eigen::MatrixXd& x) const {
  const Eigen::MatrixXd r = b - matrix_ * x;
  for (Eigen::Index j = 0; j < b.cols(); ++j) {
    const double denominator =
        norm_infinity_ * x.col(j).lpNorm<Eigen::Infinity>() + b.col(j).lpNorm<Eigen::Infinity>();
    const double error = denominator > 0 ? r.col(j).lpNorm<Eigen::Infinity>() / denominator : 0;
    if (!(error <= limit_)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "CHOLMOD solve of the structure failed its check: backward error %.3e > %.1e",
                    error, limit_);
      throw RunError(text);
    }
  }
}

void SparseLinearSystem::solve(const double* rhs, double* x) {
  solve_columns(rhs, 1, x);
}

void SparseLinearSystem::solve_columns(const double* rhs, std::size_t n_columns, double* x) {
  const Eigen::Index n = mass_.rows(), m = static_cast<Eigen::Index>(n_columns);
  const Eigen::Map<const Eigen::MatrixXd> b(rhs, n, m);
  Eigen::Map<Eigen::MatrixXd> solution(x, n, m);
  solution = cholesky_.solve(Eigen::MatrixXd(b));
  if (check_)
    check(b, solution);
}

bool SparseLinearSystem::apply_matrix(const double* x, double* y) {
  Vector(y, matrix_.rows()) = matrix_ * ConstVector(x, matrix_.rows());
  return true;
}

void SparseLinearSystem::matrix_entries(std::vector<MatrixEntry>& entries) const {
  for (Eigen::Index j = 0; j < matrix_.outerSize(); ++j)
    for (Matrix::InnerIterator it(matrix_, j); it; ++it)
      entries.push_back(
          {static_cast<std::size_t>(it.row()), static_cast<std::size_t>(j), it.value()});
}

}  // namespace railfe
