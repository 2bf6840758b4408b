#pragma once
/// \file
/// Time-dependent linear constraints C(t) u = g(t) on the unknowns of a SecondOrderSystem, held
/// by Lagrange multipliers λ whose forces Cᵀλ enter the balance (docs/theory.md, "Constraints in
/// HHT-α"). A ConstraintSet writes the rows at a time; NewtonStepSolver (newton_step.hpp) solves
/// each iteration's saddle-point system [A Cᵀ; C 0] through a SaddlePointSolver.

#include <cstddef>
#include <vector>

#include "framework/time/second_order_system.hpp"

namespace railfe {

/// Constraint rows C (compressed rows over the unknowns) and their right-hand side g.
struct ConstraintRows {
  std::vector<std::size_t> offsets{0};  ///< row i holds entries offsets[i] .. offsets[i+1]
  std::vector<std::size_t> columns;     ///< unknown of each entry
  std::vector<double> values;           ///< coefficient of each entry
  std::vector<double> rhs;              ///< g, one per row

  /// Number of rows.
  std::size_t size() const { return rhs.size(); }
  /// Removes every row.
  void clear();
  /// Starts a row with right-hand side \p g; add its entries with add_entry().
  void start_row(double g);
  /// Adds \p value at unknown \p column to the last row (entries with value 0 are skipped).
  void add_entry(std::size_t column, double value);
  /// cu = C u (length size()).
  void multiply(const double* u, double* cu) const;
  /// f += scale · Cᵀ λ (f of the system's length).
  void add_transpose(const double* lambda, double scale, double* f) const;
  /// Whether \p other holds the same matrix C (its right-hand sides may differ).
  bool same_matrix(const ConstraintRows& other) const;
};

/// The constraints of a model. The rows may change between steps (a point that moves, a
/// constraint that releases); they are fixed within a step.
class ConstraintSet {
 public:
  virtual ~ConstraintSet() = default;
  /// Writes C(\p time) and g(\p time) to \p rows (cleared first by the caller).
  virtual void rows_at(double time, ConstraintRows& rows) = 0;
  /// Called with the converged step's t_{n+1}, u_{n+1} and multipliers λ_{n+1} (one per row of
  /// rows_at(time)). Returns true when the set changes its rows for this time (a constraint
  /// releases or engages); the solver then repeats the step with the new rows_at(time).
  virtual bool accept(double time, const double* u, const double* lambda) {
    (void)time, (void)u, (void)lambda;
    return false;
  }
  /// Called after the step to \p time has been taken (u, v, a updated) by a scheme whose
  /// spectral radius at infinity is \p spectral_radius (1: no numerical damping). True when the
  /// set asks for a consistent restart there (an impact: a constraint engaged with a velocity
  /// jump the displacement rows cannot take); NewtonStepSolver::after_step() then projects v
  /// onto the velocity rows and solves a and λ afresh (docs/theory.md, "Constraints in HHT-α").
  virtual bool needs_restart(double time, double spectral_radius) {
    (void)time, (void)spectral_radius;
    return false;
  }
  /// The rates of the \p n_rows rows of rows_at(\p time) for (u, v): \p velocity = ġ − Ċ u,
  /// the right-hand side of C v, and \p acceleration = g̈ − C̈ u − 2 Ċ v, that of C a (one per
  /// row each). Default: zero (rows and g that do not change in time).
  virtual void rates(double time, const double* u, const double* v, std::size_t n_rows,
                     double* velocity, double* acceleration);
};

/// The rates of \p set's rows at \p time (ConstraintSet::rates()) by central differences of
/// rows_at() over \p time ± \p h: velocity = ġ − Ċ u, acceleration = g̈ − C̈ u − 2 Ċ v. For sets
/// whose rows_at() has no side effects and writes the same rows, in the same order, at the three
/// times (their entries may differ).
void rates_by_differences(ConstraintSet& set, double time, double h, const double* u,
                          const double* v, std::size_t n_rows, double* velocity,
                          double* acceleration);

/// The linear solves of a constrained Newton iteration: x and μ with
///   [A Cᵀ; C 0] [x; μ] = [r; r_c],
/// A = the system's matrix for the coefficients given (MatrixCoefficients), C the rows.
class SaddlePointSolver {
 public:
  virtual ~SaddlePointSolver() = default;
  /// Prepares for solve() with A at (\p u, \p v) and the rows \p rows (copied or referenced
  /// until the next call). Throws RunError when the saddle-point matrix is singular.
  virtual void factor(const double* u, const double* v, const MatrixCoefficients& coefficients,
                      const ConstraintRows& rows) = 0;
  /// Solves for \p x (length n) and \p mu (one per row); throws RunError when the solution
  /// fails its residual check.
  virtual void solve(const double* r, const double* r_c, double* x, double* mu) = 0;
};

}  // namespace railfe
