#pragma once
/// \file
/// Two SaddlePointSolvers (framework/time/constraint_set.hpp) for the direct method's
/// [A Cᵀ; C 0] [x; μ] = [r; r_c]:
///  - BlockSaddlePointSolver: A = diag(A_s, A_v) of a CoupledSystem. The structure's A_s is
///    factored once (while its coefficients hold) and the constraints are eliminated through it.
///    Where the structure offers its factor's halves A_s = Pᵀ L Lᵀ P (TriangularSolves, e.g.
///    SparseLinearSystem) each time the rows move costs sparse forward solves W = L⁻¹ P C_sᵀ
///    (only the supernodes on the paths from the rows' unknowns to the root) and
///    C_s A_s⁻¹ C_sᵀ = Wᵀ W; a solve is then one forward and one backward solve,
///    x_s = Pᵀ L⁻ᵀ (L⁻¹ P r_s − W μ). Otherwise Z = A_s⁻¹ C_sᵀ by full solves (solve_columns)
///    and x_s = A_s⁻¹ r_s − Z μ. The dense vehicle block A_v is LU-factored when it changes;
///    the Schur complement S = C_s A_s⁻¹ C_sᵀ + C_v A_v⁻¹ C_vᵀ (n_c × n_c) gives μ. Where A_v
///    alone is singular (a massless vehicle point) the bordered
///    [A_v C_vᵀ; C_v −C_s A_s⁻¹ C_sᵀ] is factored instead.
///  - MonolithicSaddlePointSolver: the whole saddle-point matrix assembled and factored at
///    every factor(), by UMFPACK (sparse LU), or by a dense LU with partial pivoting up to
///    MonolithicSaddlePointSolver::kDenseLimit rows (a wheelset): the reference and fallback.
/// Both check every solution's normwise backward error and throw RunError above the limit.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>

#include "framework/time/constraint_set.hpp"
#include "framework/time/coupled_system.hpp"
#include "framework/time/triangular_solves.hpp"

namespace railfe {

/// Counters of a saddle-point solver.
struct SaddlePointStatistics {
  std::size_t factorizations = 0;     ///< factor() calls
  std::size_t constraint_blocks = 0;  ///< C_s A_s⁻¹ C_sᵀ formed (block solver, W or Z)
  std::size_t solves = 0;             ///< solve() calls
  double worst_backward_error = 0;    ///< largest backward error checked
};

/// Factor-once structure, constraints through the Schur complement (see the file comment).
class BlockSaddlePointSolver : public SaddlePointSolver {
 public:
  /// A solver for \p system (not owned); \p backward_error_limit bounds every check.
  explicit BlockSaddlePointSolver(CoupledSystem& system, double backward_error_limit = 1e-10);
  /// Factors the coupled system (the structure only when its A changed), recomputes W (or Z)
  /// and C_s A_s⁻¹ C_sᵀ when the rows or A_s changed, and LU-factors the reduced system.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients,
              const ConstraintRows& rows) override;
  /// One structure solve (or its two triangular halves) and one vehicle solve. Checked: the reduced
  /// system's backward error, the vehicle equations, C x = r_c, and where the structure can apply
  /// A_s (SecondOrderSystem::apply_matrix) its equations A_s x_s + C_sᵀ μ = r_s end to end, so the
  /// structure's own per-solve check may be turned off.
  void solve(const double* r, const double* r_c, double* x, double* mu) override;
  /// The counters so far.
  const SaddlePointStatistics& statistics() const { return statistics_; }

 private:
  CoupledSystem& system_;
  double limit_;
  ConstraintRows rows_;
  std::size_t structure_version_ = static_cast<std::size_t>(-1);
  SparseColumns structure_sparse_;      // C_sᵀ
  Eigen::MatrixXd vehicle_columns_;     // C_vᵀ (n_v × n_c)
  TriangularSolves* halves_ = nullptr;  // the structure's factor halves, where it has them
  ForwardSolution forward_;             // L⁻¹ P C_sᵀ on its pattern (with halves_)
  Eigen::MatrixXd z_, w_;               // A_s⁻¹ C_sᵀ (without halves_), A_v⁻¹ C_vᵀ
  Eigen::MatrixXd structure_schur_, vehicle_schur_;  // C_s Z, C_v W
  Eigen::MatrixXd vehicle_matrix_;                   // A_v last factored
  std::size_t vehicle_version_ = 0;                  // CoupledSystem::vehicle_versions() of it
  Eigen::PartialPivLU<Eigen::MatrixXd> vehicle_lu_;
  bool vehicle_regular_ = false;
  double vehicle_norm_ = 0;
  Eigen::MatrixXd reduced_;  // S, or the bordered matrix where A_v is singular
  Eigen::PartialPivLU<Eigen::MatrixXd> reduced_lu_;
  double reduced_norm_ = 0;
  Eigen::VectorXd y_, rhs_, solution_, cx_, product_, constraint_force_;
  SaddlePointStatistics statistics_;
};

/// The whole saddle-point matrix through UMFPACK (see the file comment).
class MonolithicSaddlePointSolver : public SaddlePointSolver {
 public:
  /// A solver for \p system (not owned; it must implement matrix_entries()).
  explicit MonolithicSaddlePointSolver(SecondOrderSystem& system,
                                       double backward_error_limit = 1e-10);
  /// Factors the system (for its matrix), assembles [A Cᵀ; C 0] and LU-factors it (the
  /// symbolic analysis reused while the pattern holds).
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients,
              const ConstraintRows& rows) override;
  /// Solves and checks the backward error against the assembled matrix.
  void solve(const double* r, const double* r_c, double* x, double* mu) override;
  /// Saddle-point matrices of at most this many rows are factored densely.
  static constexpr Eigen::Index kDenseLimit = 100;
  /// The counters so far.
  const SaddlePointStatistics& statistics() const { return statistics_; }

 private:
  SecondOrderSystem& system_;
  double limit_;
  std::size_t n_constraints_ = 0;
  std::vector<MatrixEntry> entries_;
  Eigen::SparseMatrix<double> matrix_;
  double norm_infinity_ = 0;
  bool analyzed_ = false;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
  bool dense_ = false;  // assembled and factored densely (small matrices)
  Eigen::MatrixXd dense_matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> dense_lu_;
  SaddlePointStatistics statistics_;
};

/// ‖b − A x‖∞ / (‖A‖∞ ‖x‖∞ + ‖b‖∞) with ‖A‖∞ given; throws RunError naming \p method above
/// \p limit. Returns the error.
double check_backward_error(const Eigen::VectorXd& residual, double norm_a,
                            const Eigen::VectorXd& x, const Eigen::VectorXd& b, double limit,
                            const char* method);

}  // namespace railfe
