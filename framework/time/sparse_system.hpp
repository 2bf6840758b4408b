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
#include "framework/time/triangular_solves.hpp"

namespace railfe {

/// ‖A‖∞, the largest absolute row sum of \p matrix.
double infinity_norm(const Eigen::SparseMatrix<double>& matrix);

/// A linear sparse second-order system; K is also the Rayleigh stiffness K_R. Its supernodal
/// factor also offers the triangular solves (TriangularSolves) of a block saddle-point solver.
class SparseLinearSystem : public SecondOrderSystem, public TriangularSolves {
 public:
  using Matrix = Eigen::SparseMatrix<double>;  ///< column-major, int indices

  /// The system with mass \p mass, damping \p damping, stiffness \p stiffness (symmetric, same
  /// size; damping may be empty) and load \p load (writes f(t); empty: no load). Every solve is
  /// checked: a normwise backward error above \p backward_error_limit throws RunError.
  SparseLinearSystem(Matrix mass, Matrix damping, Matrix stiffness,
                     std::function<void(double, double*)> load = {},
                     double backward_error_limit = 1e-10);
  /// Frees CHOLMOD's solve workspace.
  ~SparseLinearSystem() override;

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

  /// Whether A is factored as a supernodal L Lᵀ (CHOLMOD may choose so; normally true).
  bool has_triangular_factor() const override { return !parent_.empty(); }
  /// W = L⁻¹ P B over the supernodes on the paths from B's rows to the root.
  void forward_solve_sparse(const SparseColumns& b, ForwardSolution& w) override;
  /// y = L⁻¹ P b.
  void forward_solve(const double* b, double* y) override;
  /// x = Pᵀ L⁻ᵀ y.
  void backward_solve(const double* y, double* x) override;

 private:
  /// Eigen's CHOLMOD wrapper with its factor in reach.
  class Cholesky : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
   public:
    /// CHOLMOD's factor (null before factorize()).
    cholmod_factor* factor() const { return m_cholmodFactor; }
  };
  void check(const Eigen::MatrixXd& b, const Eigen::MatrixXd& x) const;
  void map_supernodes();
  void triangular_solve(int system, double* y);

  Matrix mass_, damping_, stiffness_, matrix_;
  std::function<void(double, double*)> load_;
  double limit_;
  double norm_infinity_ = 0;  ///< ‖A‖∞ of the last factor()
  bool analyzed_ = false;     ///< whether CHOLMOD has ordered A's pattern
  bool check_ = true;         ///< whether solve() checks its backward error
  Cholesky cholesky_;
  std::vector<int> inverse_permutation_;  // row of P A Pᵀ of each unknown
  std::vector<int> supernode_, parent_;   // supernode of each row; each supernode's parent
  std::vector<int> local_, reached_;      // forward_solve_sparse() workspace
  std::vector<char> marked_;
  Eigen::MatrixXd update_;
  cholmod_dense *solution_ = nullptr, *work_y_ = nullptr, *work_e_ = nullptr;
};

}  // namespace railfe
