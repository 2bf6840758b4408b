#pragma once
/// \file
/// The implicit module's SecondOrderSystem (framework/time/second_order_system.hpp) over Tpetra:
/// M a + C v + K u = s(t) F on the owned DOFs of a DofMap, with fixed DOFs held at zero. The
/// fixed DOFs are masked out of every force and product (their rows read zero, so the Newton
/// residual and the energy see the free DOFs only) and eliminated symmetrically from the
/// matrix, which therefore stays symmetric positive definite for CHOLMOD and CG.

#include <functional>
#include <memory>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/expression.hpp"
#include "framework/solvers/linear_solver.hpp"
#include "framework/time/second_order_system.hpp"

namespace railfe {

/// The assembled matrices and loads of a linear structural model.
struct LinearModelMatrices {
  Teuchos::RCP<TpetraMatrix> stiffness;  ///< K
  Teuchos::RCP<TpetraMatrix> mass;       ///< M
  Teuchos::RCP<TpetraMatrix> damping;    ///< discrete dampers' C (null when there are none)
  Teuchos::RCP<TpetraVector> load;       ///< F, the load at scale 1
};

/// M a + C v + K u = s(t) F with fixed DOFs.
class ImplicitSystem : public SecondOrderSystem {
 public:
  /// A system of \p matrices on \p dofs; \p fixed lists the owned local DOFs held at zero,
  /// \p load_scale is s(t), \p solver solves with A (its setup is called by factor()).
  ImplicitSystem(const DofMap& dofs, LinearModelMatrices matrices,
                 const std::vector<LocalIndex>& fixed, Expression load_scale,
                 std::unique_ptr<LinearSolver> solver, ProblemTraits traits);

  std::size_t n_unknowns() const override { return n_; }
  bool is_linear() const override { return true; }
  void internal_force(const double* u, const double* v, double* force) override;
  void external_force(double time, double* force) override;
  void apply_mass(const double* x, double* y) override;
  void apply_rayleigh_stiffness(const double* x, double* y) override;
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  void solve(const double* rhs, double* x) override;
  double dot(const double* x, const double* y) const override;

  /// Adds \p load(t, owned_force) to the external force (moving loads), before fixed DOFs are
  /// masked.
  void add_time_load(std::function<void(double, double*)> load) { time_load_ = std::move(load); }
  /// ½ vᵀ M v (J), over every rank.
  double kinetic_energy(const double* v);
  /// ½ uᵀ K u (J), over every rank.
  double strain_energy(const double* u);
  /// The last solve's report (method, backward error, timings).
  const SolveReport& last_solve() const { return last_solve_; }
  /// Seconds spent in factor() and solve() so far.
  double factor_seconds() const { return factor_seconds_; }
  /// Seconds spent in solve() so far.
  double solve_seconds() const { return solve_seconds_; }

 private:
  // y = A x for one of the matrices, masked.
  void apply(const TpetraMatrix& matrix, const double* x, double* y);
  void mask(double* y) const;

  const DofMap& dofs_;
  std::size_t n_;
  LinearModelMatrices matrices_;
  std::vector<LocalIndex> fixed_;
  Expression load_scale_;
  std::function<void(double, double*)> time_load_;
  std::unique_ptr<LinearSolver> solver_;
  ProblemTraits traits_;
  Teuchos::RCP<TpetraMatrix> effective_;
  Teuchos::RCP<TpetraVector> x_, y_;
  std::vector<double> damping_force_;  // C v, scratch of internal_force()
  SolveReport last_solve_;
  double factor_seconds_ = 0, solve_seconds_ = 0;
};

}  // namespace railfe
