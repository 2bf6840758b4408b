#include "framework/time/sparse_system.hpp"

#include <algorithm>
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

SparseLinearSystem::~SparseLinearSystem() {
  cholmod_free_dense(&solution_, &cholesky_.cholmod());
  cholmod_free_dense(&work_y_, &cholesky_.cholmod());
  cholmod_free_dense(&work_e_, &cholesky_.cholmod());
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
  map_supernodes();
}

void SparseLinearSystem::map_supernodes() {
  parent_.clear();
  const cholmod_factor* l = cholesky_.factor();
  if (!l || !l->is_super || !l->is_ll || l->itype != CHOLMOD_INT || l->xtype != CHOLMOD_REAL)
    return;  // no supernodal L Lᵀ: the triangular solves are not offered
  const int n = static_cast<int>(l->n), n_super = static_cast<int>(l->nsuper);
  const int* super = static_cast<const int*>(l->super);
  const int* pi = static_cast<const int*>(l->pi);
  const int* s = static_cast<const int*>(l->s);
  const int* perm = static_cast<const int*>(l->Perm);
  inverse_permutation_.resize(n);
  for (int k = 0; k < n; ++k)
    inverse_permutation_[perm[k]] = k;
  supernode_.resize(n);
  for (int k = 0; k < n_super; ++k)
    std::fill(supernode_.begin() + super[k], supernode_.begin() + super[k + 1], k);
  parent_.resize(n_super);
  for (int k = 0; k < n_super; ++k) {  // the supernode of the first row below the diagonal
    const int columns = super[k + 1] - super[k], rows = pi[k + 1] - pi[k];
    parent_[k] = rows > columns ? supernode_[s[pi[k] + columns]] : -1;
  }
  marked_.assign(n_super, 0);
  local_.assign(n, -1);
}

void SparseLinearSystem::forward_solve_sparse(const SparseColumns& b, ForwardSolution& w) {
  const cholmod_factor* l = cholesky_.factor();
  if (parent_.empty())
    throw RunError("SparseLinearSystem: no supernodal Cholesky factor for the triangular solves");
  const int* super = static_cast<const int*>(l->super);
  const int* pi = static_cast<const int*>(l->pi);
  const int* px = static_cast<const int*>(l->px);
  const int* s = static_cast<const int*>(l->s);
  const double* lx = static_cast<const double*>(l->x);
  reached_.clear();  // the supernodes on the paths from B's rows to the root
  for (const std::size_t row : b.rows)
    for (int k = supernode_[inverse_permutation_[row]]; k >= 0 && !marked_[k]; k = parent_[k]) {
      marked_[k] = 1;
      reached_.push_back(k);
    }
  std::sort(reached_.begin(), reached_.end());  // children before parents
  w.pattern.clear();
  for (const int k : reached_) {
    marked_[k] = 0;
    for (int c = super[k]; c < super[k + 1]; ++c) {
      local_[c] = static_cast<int>(w.pattern.size());
      w.pattern.push_back(static_cast<std::size_t>(c));
    }
  }
  const Eigen::Index n_columns = static_cast<Eigen::Index>(b.size());
  w.values.setZero(static_cast<Eigen::Index>(w.pattern.size()), n_columns);
  for (Eigen::Index j = 0; j < n_columns; ++j)
    for (std::size_t e = b.offsets[j]; e < b.offsets[j + 1]; ++e)
      w.values(local_[inverse_permutation_[b.rows[e]]], j) += b.values[e];
  for (const int k : reached_) {  // dense triangle, then the rows below it
    const Eigen::Index columns = super[k + 1] - super[k], rows = pi[k + 1] - pi[k];
    const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> block(
        lx + px[k], rows, columns, Eigen::OuterStride<>(rows));
    auto x = w.values.middleRows(local_[super[k]], columns);
    block.topRows(columns).triangularView<Eigen::Lower>().solveInPlace(x);
    if (rows == columns)
      continue;
    update_.noalias() = block.bottomRows(rows - columns) * x;
    for (Eigen::Index t = 0; t < rows - columns; ++t)
      w.values.row(local_[s[pi[k] + columns + t]]) -= update_.row(t);
  }
}

void SparseLinearSystem::triangular_solve(int system, double* y) {
  cholmod_dense b;
  b.nrow = b.nzmax = b.d = static_cast<std::size_t>(mass_.rows());
  b.ncol = 1;
  b.x = y;
  b.z = nullptr;
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(system, cholesky_.factor(), &b, nullptr, &solution_, nullptr, &work_y_,
                      &work_e_, &cholesky_.cholmod()))
    throw RunError("CHOLMOD's triangular solve with the structure's factor failed");
  std::copy_n(static_cast<const double*>(solution_->x), b.nrow, y);
}

void SparseLinearSystem::forward_solve(const double* b, double* y) {
  const int n = static_cast<int>(mass_.rows());
  for (int i = 0; i < n; ++i)
    y[inverse_permutation_[i]] = b[i];
  triangular_solve(CHOLMOD_L, y);
}

void SparseLinearSystem::backward_solve(const double* y, double* x) {
  const int n = static_cast<int>(mass_.rows());
  update_.resize(n, 1);
  std::copy_n(y, n, update_.data());
  triangular_solve(CHOLMOD_Lt, update_.data());
  for (int i = 0; i < n; ++i)
    x[i] = update_(inverse_permutation_[i], 0);
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
