#include "framework/solvers/saddle_point_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "framework/base/error.hpp"
#include "framework/time/sparse_system.hpp"
#include "framework/time/triangular_solves.hpp"

namespace railfe {

double check_backward_error(const Eigen::VectorXd& residual, double norm_a,
                            const Eigen::VectorXd& x, const Eigen::VectorXd& b, double limit,
                            const char* method) {
  const double denominator = norm_a * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>();
  const double error =
      denominator > 0 ? residual.lpNorm<Eigen::Infinity>() / denominator : residual.norm();
  if (!(error <= limit)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%s: the solution failed its check (backward error %.3e > %.1e)", method, error,
                  limit);
    throw RunError(text);
  }
  return error;
}

BlockSaddlePointSolver::BlockSaddlePointSolver(CoupledSystem& system, double backward_error_limit)
    : system_(system), limit_(backward_error_limit) {}

void BlockSaddlePointSolver::factor(const double* u, const double* v,
                                    const MatrixCoefficients& coefficients,
                                    const ConstraintRows& rows) {
  system_.factor(u, v, coefficients);
  ++statistics_.factorizations;
  const Eigen::Index ns = static_cast<Eigen::Index>(system_.n_structure());
  const Eigen::Index nv = static_cast<Eigen::Index>(system_.n_unknowns()) - ns;
  const Eigen::Index nc = static_cast<Eigen::Index>(rows.size());
  const bool rows_moved = !rows.same_matrix(rows_) || rows.size() != rows_.size();
  const bool structure_changed = system_.structure_factorizations() != structure_version_;
  TriangularSolves* halves = dynamic_cast<TriangularSolves*>(&system_.structure());
  if (halves && !halves->has_triangular_factor())
    halves = nullptr;
  const bool method_changed = halves != halves_;
  halves_ = halves;
  rows_ = rows;
  bool vehicle_rows_moved = false;
  if (rows_moved) {  // C_sᵀ as sparse columns, C_vᵀ dense
    structure_sparse_ = SparseColumns();
    Eigen::MatrixXd vehicle_columns = Eigen::MatrixXd::Zero(nv, nc);
    for (Eigen::Index i = 0; i < nc; ++i) {
      for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k) {
        const Eigen::Index column = static_cast<Eigen::Index>(rows.columns[k]);
        if (column < ns) {
          structure_sparse_.rows.push_back(rows.columns[k]);
          structure_sparse_.values.push_back(rows.values[k]);
        } else {
          vehicle_columns(column - ns, i) += rows.values[k];
        }
      }
      structure_sparse_.offsets.push_back(structure_sparse_.rows.size());
    }
    vehicle_rows_moved =
        vehicle_columns.cols() != vehicle_columns_.cols() || vehicle_columns != vehicle_columns_;
    if (vehicle_rows_moved)
      vehicle_columns_ = std::move(vehicle_columns);
  }
  if (rows_moved || structure_changed || method_changed) {  // C_s A_s⁻¹ C_sᵀ
    if (halves_) {  // W = L⁻¹ P C_sᵀ by sparse forward solves, C_s A_s⁻¹ C_sᵀ = Wᵀ W
      halves_->forward_solve_sparse(structure_sparse_, forward_);
      structure_schur_.noalias() = forward_.values.transpose() * forward_.values;
    } else {  // Z = A_s⁻¹ C_sᵀ by full solves, C_s Z
      Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(ns, nc);
      for (Eigen::Index i = 0; i < nc; ++i)
        for (std::size_t k = structure_sparse_.offsets[i]; k < structure_sparse_.offsets[i + 1];
             ++k)
          columns(static_cast<Eigen::Index>(structure_sparse_.rows[k]), i) +=
              structure_sparse_.values[k];
      z_.resize(ns, nc);
      if (nc > 0)
        system_.structure().solve_columns(columns.data(), static_cast<std::size_t>(nc), z_.data());
      structure_schur_ = columns.transpose() * z_;
    }
    ++statistics_.constraint_blocks;
    structure_version_ = system_.structure_factorizations();
  }
  const bool vehicle_changed = system_.vehicle_versions() != vehicle_version_;
  if (vehicle_changed) {
    vehicle_version_ = system_.vehicle_versions();
    vehicle_matrix_ = system_.vehicle().matrix();
    vehicle_lu_.compute(vehicle_matrix_);
    // An unknown with no mass or stiffness leaves a zero pivot, which Eigen's LU skips and its
    // condition estimate can miss: look at the pivots too.
    const auto pivots = vehicle_lu_.matrixLU().diagonal().cwiseAbs();
    const double rcond = nv == 0 ? 1.0 : vehicle_lu_.rcond();
    vehicle_regular_ = nv == 0 || (std::isfinite(rcond) && rcond > 1e-12 &&
                                   pivots.minCoeff() > 1e-14 * pivots.maxCoeff());
    vehicle_norm_ = nv == 0 ? 0.0 : vehicle_matrix_.cwiseAbs().rowwise().sum().maxCoeff();
  }
  if (vehicle_regular_) {  // S = C_s A_s⁻¹ C_sᵀ + C_v A_v⁻¹ C_vᵀ (n_c × n_c)
    if (vehicle_rows_moved || vehicle_changed) {
      w_ = nv > 0 ? Eigen::MatrixXd(vehicle_lu_.solve(vehicle_columns_)) : Eigen::MatrixXd(0, nc);
      vehicle_schur_ = vehicle_columns_.transpose() * w_;
    }
    reduced_ = structure_schur_ + vehicle_schur_;
  } else {  // A_v singular alone (a massless vehicle point): [A_v C_vᵀ; C_v −C_s A_s⁻¹ C_sᵀ]
    reduced_.setZero(nv + nc, nv + nc);
    reduced_.topLeftCorner(nv, nv) = vehicle_matrix_;
    reduced_.topRightCorner(nv, nc) = vehicle_columns_;
    reduced_.bottomLeftCorner(nc, nv) = vehicle_columns_.transpose();
    reduced_.bottomRightCorner(nc, nc) = -structure_schur_;
  }
  reduced_lu_.compute(reduced_);
  reduced_norm_ = reduced_.size() == 0 ? 0.0 : reduced_.cwiseAbs().rowwise().sum().maxCoeff();
  if (reduced_.size() > 0 && !(reduced_lu_.rcond() > std::numeric_limits<double>::epsilon()))
    throw RunError(
        "the constrained vehicle block of the time step is singular (a vehicle unknown without "
        "mass or stiffness, or constraints that repeat each other)");
}

void BlockSaddlePointSolver::solve(const double* r, const double* r_c, double* x, double* mu) {
  const Eigen::Index ns = static_cast<Eigen::Index>(system_.n_structure());
  const Eigen::Index n = static_cast<Eigen::Index>(system_.n_unknowns()), nv = n - ns;
  const Eigen::Index nc = static_cast<Eigen::Index>(rows_.size());
  Eigen::Map<Eigen::VectorXd> xs(x, n);
  Eigen::Map<Eigen::VectorXd> multipliers(mu, nc);
  const Eigen::Map<const Eigen::VectorXd> rs(r, n), rc(r_c, nc);
  // C_s A_s⁻¹ r_s: through y = L⁻¹ P r_s and W, or through y = A_s⁻¹ r_s and C_s
  y_.resize(ns);
  Eigen::VectorXd structure_part = Eigen::VectorXd::Zero(nc);
  if (halves_) {
    halves_->forward_solve(r, y_.data());
    for (std::size_t p = 0; p < forward_.pattern.size(); ++p)
      structure_part += forward_.values.row(static_cast<Eigen::Index>(p)).transpose() *
                        y_[static_cast<Eigen::Index>(forward_.pattern[p])];
  } else {
    system_.structure().solve(r, y_.data());
    for (Eigen::Index i = 0; i < nc; ++i)
      for (std::size_t k = structure_sparse_.offsets[i]; k < structure_sparse_.offsets[i + 1]; ++k)
        structure_part[i] += structure_sparse_.values[k] * y_[structure_sparse_.rows[k]];
  }
  double error = 0;
  if (vehicle_regular_) {
    const Eigen::VectorXd yv =
        nv > 0 ? Eigen::VectorXd(vehicle_lu_.solve(rs.tail(nv))) : Eigen::VectorXd(0);
    rhs_ = structure_part + vehicle_columns_.transpose() * yv - rc;
    solution_ = reduced_lu_.solve(rhs_);
    multipliers = solution_;
    xs.tail(nv) = yv - w_ * solution_;
    if (nv > 0)  // the vehicle's equations A_v x_v + C_vᵀ μ = r_v
      error = check_backward_error(
          rs.tail(nv) - vehicle_matrix_ * xs.tail(nv) - vehicle_columns_ * solution_, vehicle_norm_,
          xs.tail(nv), rs.tail(nv), limit_, "block saddle-point solve (vehicle equations)");
  } else {
    rhs_.resize(nv + nc);
    rhs_.head(nv) = rs.tail(nv);
    rhs_.tail(nc) = rc - structure_part;
    solution_ = reduced_lu_.solve(rhs_);
    multipliers = solution_.tail(nc);
    xs.tail(nv) = solution_.head(nv);
  }
  if (halves_) {  // x_s = Pᵀ L⁻ᵀ (y − W μ)
    product_.noalias() = forward_.values * multipliers;
    for (std::size_t p = 0; p < forward_.pattern.size(); ++p)
      y_[static_cast<Eigen::Index>(forward_.pattern[p])] -= product_[static_cast<Eigen::Index>(p)];
    halves_->backward_solve(y_.data(), x);
  } else {  // x_s = A_s⁻¹ r_s − Z μ
    xs.head(ns) = y_ - z_ * multipliers;
  }
  error = std::max(error,
                   check_backward_error(rhs_ - reduced_ * solution_, reduced_norm_, solution_, rhs_,
                                        limit_, "block saddle-point solve (reduced system)"));
  // The structure's equations A_s x_s + C_sᵀ μ = r_s end to end, where the structure can
  // apply A_s (this also checks W or Z, which the constraint check below cannot see).
  product_.resize(ns);
  if (system_.structure().apply_matrix(x, product_.data())) {
    constraint_force_.setZero(ns);
    for (Eigen::Index i = 0; i < nc; ++i)
      for (std::size_t k = structure_sparse_.offsets[i]; k < structure_sparse_.offsets[i + 1]; ++k)
        constraint_force_[structure_sparse_.rows[k]] +=
            structure_sparse_.values[k] * multipliers[i];
    const double scale = product_.lpNorm<Eigen::Infinity>() +
                         constraint_force_.lpNorm<Eigen::Infinity>() +
                         rs.head(ns).lpNorm<Eigen::Infinity>();
    const double structure_error =
        scale > 0 ? (rs.head(ns) - product_ - constraint_force_).lpNorm<Eigen::Infinity>() / scale
                  : 0.0;
    if (!(structure_error <= limit_)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "block saddle-point solve (structure equations): the solution failed its "
                    "check (backward error %.3e > %.1e)",
                    structure_error, limit_);
      throw RunError(text);
    }
    error = std::max(error, structure_error);
  }
  // The constraint equations C x = r_c, which the structure's own check does not see.
  cx_.resize(nc);
  rows_.multiply(x, cx_.data());
  double row_norm = 0;
  for (Eigen::Index i = 0; i < nc; ++i) {
    double sum = 0;
    for (std::size_t k = rows_.offsets[i]; k < rows_.offsets[i + 1]; ++k)
      sum += std::abs(rows_.values[k]);
    row_norm = std::max(row_norm, sum);
  }
  error = std::max(error, check_backward_error(rc - cx_, row_norm, xs, rc, limit_,
                                               "block saddle-point solve (constraints)"));
  statistics_.worst_backward_error = std::max(statistics_.worst_backward_error, error);
  ++statistics_.solves;
}

MonolithicSaddlePointSolver::MonolithicSaddlePointSolver(SecondOrderSystem& system,
                                                         double backward_error_limit)
    : system_(system), limit_(backward_error_limit) {}

void MonolithicSaddlePointSolver::factor(const double* u, const double* v,
                                         const MatrixCoefficients& coefficients,
                                         const ConstraintRows& rows) {
  system_.factor(u, v, coefficients);
  ++statistics_.factorizations;
  entries_.clear();
  system_.matrix_entries(entries_);
  const std::size_t n = system_.n_unknowns();
  n_constraints_ = rows.size();
  const auto size = static_cast<Eigen::Index>(n + n_constraints_);
  dense_ = size <= kDenseLimit;
  if (dense_) {
    // A wheelset's 30 rows: assembled and LU-factored densely in a few µs (UMFPACK's set-up
    // and a sparse assembly cost tens).
    dense_matrix_.setZero(size, size);
    for (const MatrixEntry& e : entries_)
      dense_matrix_(static_cast<Eigen::Index>(e.row), static_cast<Eigen::Index>(e.column)) +=
          e.value;
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k) {
        const auto row = static_cast<Eigen::Index>(n + i);
        const auto column = static_cast<Eigen::Index>(rows.columns[k]);
        dense_matrix_(row, column) += rows.values[k];
        dense_matrix_(column, row) += rows.values[k];
      }
    dense_lu_.compute(dense_matrix_);
    const auto pivots = dense_lu_.matrixLU().diagonal().cwiseAbs();
    // Exact zeros only: the blocks' scales differ by many orders (the Schur complement's
    // pivots are ~1/stiffness); the backward error of every solve judges the rest.
    if (!(pivots.minCoeff() > 0) || !std::isfinite(pivots.sum()))
      throw RunError("the saddle-point matrix of the time step is singular (dense LU)");
    norm_infinity_ = dense_matrix_.cwiseAbs().rowwise().sum().maxCoeff();
    return;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries_.size() + 2 * rows.values.size());
  for (const MatrixEntry& e : entries_)
    triplets.emplace_back(static_cast<int>(e.row), static_cast<int>(e.column), e.value);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = rows.offsets[i]; k < rows.offsets[i + 1]; ++k) {
      triplets.emplace_back(static_cast<int>(n + i), static_cast<int>(rows.columns[k]),
                            rows.values[k]);
      triplets.emplace_back(static_cast<int>(rows.columns[k]), static_cast<int>(n + i),
                            rows.values[k]);
    }
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(n + n_constraints_),
                                     static_cast<Eigen::Index>(n + n_constraints_));
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  matrix.makeCompressed();
  const bool same_pattern =
      analyzed_ && matrix.rows() == matrix_.rows() && matrix.nonZeros() == matrix_.nonZeros() &&
      std::equal(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.cols() + 1,
                 matrix_.outerIndexPtr()) &&
      std::equal(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros(),
                 matrix_.innerIndexPtr());
  matrix_ = std::move(matrix);
  if (!same_pattern)
    lu_.analyzePattern(matrix_);
  lu_.factorize(matrix_);
  analyzed_ = true;
  if (lu_.info() != Eigen::Success)
    throw RunError("UMFPACK could not factor the saddle-point matrix of the time step (singular)");
  norm_infinity_ = infinity_norm(matrix_);
}

void MonolithicSaddlePointSolver::solve(const double* r, const double* r_c, double* x, double* mu) {
  const Eigen::Index n = static_cast<Eigen::Index>(system_.n_unknowns());
  const Eigen::Index nc = static_cast<Eigen::Index>(n_constraints_);
  Eigen::VectorXd b(n + nc);
  b.head(n) = Eigen::Map<const Eigen::VectorXd>(r, n);
  b.tail(nc) = Eigen::Map<const Eigen::VectorXd>(r_c, nc);
  const Eigen::VectorXd solution = dense_ ? Eigen::VectorXd(dense_lu_.solve(b)) : lu_.solve(b);
  const Eigen::VectorXd residual = dense_ ? Eigen::VectorXd(b - dense_matrix_ * solution)
                                          : Eigen::VectorXd(b - matrix_ * solution);
  const double error = check_backward_error(residual, norm_infinity_, solution, b, limit_,
                                            dense_ ? "monolithic saddle-point solve (dense LU)"
                                                   : "monolithic saddle-point solve (UMFPACK)");
  statistics_.worst_backward_error = std::max(statistics_.worst_backward_error, error);
  ++statistics_.solves;
  Eigen::Map<Eigen::VectorXd>(x, n) = solution.head(n);
  Eigen::Map<Eigen::VectorXd>(mu, nc) = solution.tail(nc);
}

}  // namespace railfe
