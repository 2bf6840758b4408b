#pragma once
/// \file
/// M a + C v + K u = f(t) with constant sparse matrices on one rank, factored by CHOLMOD
/// (supernodal Cholesky through Eigen's CholmodSupport): the structure of small verification
/// models and benchmarks built in C++ directly. A deck-driven module implements
/// SecondOrderSystem over Tpetra objects and LinearSolver instead.

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <functional>

#include "framework/time/second_order_system.hpp"

namespace railfe {

/// ‖A‖∞, the largest absolute row sum of \p matrix.
double infinity_norm(const Eigen::SparseMatrix<double>& matrix);

/// A linear sparse second-order system; K is also the Rayleigh stiffness K_R.
class SparseLinearSystem : public SecondOrderSystem {
 public:
  using Matrix = Eigen::SparseMatrix<double>;  ///< column-major, int indices

  /// The system with mass \p mass, damping \p damping, stiffness \p stiffness (symmetric, same
  /// size; damping may be empty) and load \p load (writes f(t); empty: no load). Every solve is
  /// checked: a normwise backward error above \p backward_error_limit throws RunError.
  SparseLinearSystem(Matrix mass, Matrix damping, Matrix stiffness,
                     std::function<void(double, double*)> load = {},
                     double backward_error_limit = 1e-10);

  /// The number of rows of M.
  std::size_t n_unknowns() const override { return static_cast<std::size_t>(mass_.rows()); }
  /// True: A is factored once per set of coefficients.
  bool is_linear() const override { return true; }
  /// K u + C v.
  void internal_force(const double* u, const double* v, double* force) override;
  /// f(t), or zero.
  void external_force(double time, double* force) override;
  /// y = M x.
  void apply_mass(const double* x, double* y) override;
  /// y = K x.
  void apply_rayleigh_stiffness(const double* x, double* y) override;
  /// Forms A and factors it with CHOLMOD; throws RunError unless A is positive definite.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  /// x = A⁻¹ rhs, backward error checked.
  void solve(const double* rhs, double* x) override;
  /// All columns through CHOLMOD at once, each checked.
  void solve_columns(const double* rhs, std::size_t n_columns, double* x) override;
  /// The entries of A.
  void matrix_entries(std::vector<MatrixEntry>& entries) const override;
  /// y = A x.
  bool apply_matrix(const double* x, double* y) override;
  /// Whether every solve checks its backward error (default true). A block solver that checks
  /// the coupled solution against apply_matrix() may turn it off.
  void check_solutions(bool check) { check_ = check; }

 private:
  void check(const Eigen::MatrixXd& b, const Eigen::MatrixXd& x) const;

  Matrix mass_, damping_, stiffness_, matrix_;
  std::function<void(double, double*)> load_;
  double limit_;
  double norm_infinity_ = 0;  ///< ‖A‖∞ of the last factor()
  bool analyzed_ = false;
  bool check_ = true;  ///< whether CHOLMOD has ordered A's pattern
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> cholesky_;
};

}  // namespace railfe
