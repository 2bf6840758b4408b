#pragma once
/// \file
/// The implicit time stepper of the Newmark/HHT-α family: NewmarkIntegrator (newmark.hpp) driven
/// by NewtonStepSolver (newton_step.hpp), with the initial acceleration from the equation of
/// motion and a step cut-back. A step whose Newton iteration fails is retried with Δt halved
/// (each cut reported), down to Δt / 2^max_halvings; below that the run stops with
/// StepNotConverged (a RunError: exit status 2) naming the time, the step and the residuals.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"
#include "framework/time/second_order_system.hpp"

namespace railfe {

/// How far a step may be cut back.
struct CutBackSettings {
  int max_halvings = 10;  ///< Δt may be halved this many times: the smallest step is Δt / 2^this
};

/// One cut-back, as reported to the callback.
struct CutBack {
  double time = 0;                ///< start of the failed attempt (s)
  double failed_step = 0;         ///< its Δt (s)
  double next_step = 0;           ///< the Δt tried next (half of it) (s)
  std::vector<double> residuals;  ///< residual norms of the failed attempt
  std::string reason;             ///< the solver's message
};

/// Advances (u, v, a) of a SecondOrderSystem with HHT-α (or Newmark β, γ) and Newton iterations.
class HhtIntegrator {
 public:
  /// A stepper for \p system (not owned, must outlive the integrator).
  HhtIntegrator(NewmarkScheme scheme, SecondOrderSystem& system, NewtonSettings newton = {},
                RayleighDamping rayleigh = {}, CutBackSettings cut_back = {});

  /// Writes the acceleration that satisfies the equation of motion at \p time for (u, v) to
  /// \p a: M a = f_ext(t0) − f_int(u, v) − C_R v (M must be regular).
  void initialize(double time, const double* u, const double* v, double* a);
  /// Advances u, v, a from \p time to time + \p dt, halving the step where Newton fails and
  /// growing it back after each even number of successful sub-steps. Returns the number of
  /// sub-steps taken (1 without cut-back). Throws StepNotConverged when a sub-step of
  /// dt / 2^max_halvings fails; u, v, a then hold the last converged state.
  int advance(double time, double dt, double* u, double* v, double* a);

  /// Holds the unknowns to \p constraints, each Newton iteration solved by \p solver (neither
  /// owned); see NewtonStepSolver::constrain(). Call before initialize().
  void constrain(ConstraintSet& constraints, SaddlePointSolver& solver) {
    solver_.constrain(&constraints, &solver);
  }
  /// λ_{n+1} of the last converged step, one per row of constraint_rows().
  const std::vector<double>& multipliers() const { return solver_.multipliers(); }
  /// The constraint rows of the last converged step.
  const ConstraintRows& constraint_rows() const { return solver_.constraint_rows(); }

  /// Calls \p report at every cut-back (a module writes it to its log).
  void on_cut_back(std::function<void(const CutBack&)> report) { report_ = std::move(report); }
  /// Cut-backs so far.
  std::size_t n_cut_backs() const { return n_cut_backs_; }
  /// Newton counters so far (steps, iterations, factorizations, last residual history).
  const NewtonStatistics& newton_statistics() const { return solver_.statistics(); }
  /// The scheme.
  const NewmarkScheme& scheme() const { return integrator_.scheme(); }

 private:
  NewtonStepSolver solver_;
  NewmarkIntegrator integrator_;
  CutBackSettings cut_back_;
  std::function<void(const CutBack&)> report_;
  std::size_t n_cut_backs_ = 0;
};

}  // namespace railfe
