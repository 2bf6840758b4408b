#pragma once
/// \file
/// One implicit step of the Newmark/HHT-α family (newmark.hpp) by full Newton iteration on the
/// acceleration a_{n+1}, with the consistent tangent
///   ∂R/∂a = M + (1+α)(γ Δt (C_t + C_R) + β Δt² K_t),
/// where R(a) = M a + (1+α)(f_int(u, v) + C_R v) − α (f_int(u_n, v_n) + C_R v_n)
///              − (1+α) f_ext(t_{n+1}) + α f_ext(t_n),  u = ũ + β Δt² a,  v = ṽ + γ Δt a,
/// and C_R = a_R M + b_R K_R (Rayleigh). See docs/theory.md, "HHT-α with Newton iterations".
/// With constraints C(t) u = g(t) (constraint_set.hpp) the multipliers join the unknowns:
///   R += (1+α) C_{n+1}ᵀ λ_{n+1} − α C_nᵀ λ_n,   C_{n+1} u_{n+1} = g(t_{n+1}),
/// and each iteration solves [A Cᵀ; C 0] through a SaddlePointSolver (docs/theory.md,
/// "Constraints in HHT-α").

#include <cstddef>
#include <string>
#include <vector>

#include "framework/base/error.hpp"
#include "framework/time/constraint_set.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/second_order_system.hpp"

namespace railfe {

/// Rayleigh damping C_R = mass·M + stiffness·K_R.
struct RayleighDamping {
  double mass = 0;       ///< a_R (1/s)
  double stiffness = 0;  ///< b_R (s)
};

/// When a Newton iteration has converged: both tests hold at once, each with a relative
/// tolerance and an absolute floor (in the system's units; N and m in railfe).
struct NewtonSettings {
  /// ‖R‖ ≤ max(residual_relative · ‖force scale‖, residual_absolute), where the force scale is
  /// the largest of ‖M a‖, ‖(1+α)(f_int + C_R v)‖ and ‖the time-n and external terms‖.
  double residual_relative = 1e-8;
  double residual_absolute = 1e-10;  ///< absolute floor of the residual test
  /// ‖β Δt² δa‖ ≤ max(increment_relative · ‖u_{n+1} − u_n‖, increment_absolute) for the last
  /// correction δa (so at least one correction is always taken).
  double increment_relative = 1e-8;
  double increment_absolute = 1e-14;  ///< absolute floor of the increment test
  int max_iterations = 20;            ///< corrections allowed per step
  /// Backtracking: where a full correction raises ‖R‖, halve it (up to 8 times) until ‖R‖
  /// falls. For forces that saturate (creep forces, friction), where full Newton steps cycle.
  /// With constraints the first correction is always taken whole: it moves the unknowns onto
  /// the constraint rows, a change ‖R‖ does not see.
  bool line_search = false;
  /// Modified Newton: the matrix of the step's first iteration serves its later ones (one
  /// tangent and factorization per step; more, cheaper iterations). Constrained steps only.
  bool tangent_once_per_step = false;
};

/// A step whose Newton iteration did not converge (or met a non-finite residual).
class StepNotConverged : public RunError {
 public:
  /// The message, the start time t_n and step Δt of the attempt, and the residual norms.
  StepNotConverged(const std::string& message, double time, double step,
                   std::vector<double> residuals)
      : RunError(message), time(time), step(step), residuals(std::move(residuals)) {}
  double time;                    ///< t_n of the failed attempt (s)
  double step;                    ///< Δt of the failed attempt (s)
  std::vector<double> residuals;  ///< ‖R‖ at each iterate
};

/// Counters over the steps a solver has taken.
struct NewtonStatistics {
  std::size_t steps = 0;              ///< converged steps
  std::size_t iterations = 0;         ///< Newton corrections over all converged steps
  std::size_t factorizations = 0;     ///< factor() calls
  std::size_t force_evaluations = 0;  ///< internal_force() calls
  std::size_t restarts = 0;           ///< consistent restarts after a step (after_step())
  int last_iterations = 0;            ///< corrections in the last converged step
  int most_iterations = 0;            ///< most corrections in one converged step
  /// Wall time of the converged steps' Newton solves (residuals, matrices, linear solves; not
  /// the predictor or the output) (s).
  double seconds = 0;
  std::vector<double> last_residuals;  ///< ‖R‖ at each iterate of the last attempt
};

/// Solves the HHT-α balance for a_{n+1} by Newton's method on a SecondOrderSystem; plugs into
/// NewmarkIntegrator as its SecondOrderProblem. For a linear system (is_linear()) it factors A
/// once per step size and takes a single solve per step. Throws StepNotConverged when the
/// iteration fails; the state passed in is then untouched (NewmarkIntegrator::step updates u, v,
/// a only after a converged solve).
class NewtonStepSolver : public SecondOrderProblem {
 public:
  /// A solver for \p system (not owned, must outlive the solver).
  NewtonStepSolver(SecondOrderSystem& system, NewtonSettings settings = {},
                   RayleighDamping rayleigh = {});

  /// Finds a_{n+1}; see the file comment. The first guess is a_n.
  void solve_for_acceleration(const StepState& state, double* acceleration) override;

  /// Solves M a = f_ext(t) − f_int(u, v) − C_R v for the acceleration at \p time.
  void initial_acceleration(double time, const double* u, const double* v, double* a);

  /// Holds the unknowns to \p constraints from now on, each iteration solved by \p solver
  /// (neither owned; both must outlive this solver; nullptr for both detaches). Needs β > 0.
  /// Call before initial_acceleration(), which then finds λ_0 with a.
  void constrain(ConstraintSet* constraints, SaddlePointSolver* solver);
  /// After the step to \p time (u, v, a updated by the integrator): where the constraints ask
  /// for it (ConstraintSet::needs_restart(), an impact), projects \p v onto C v = ġ − Ċ u in
  /// the mass metric (the velocity jump of a plastic impact) and solves \p a and λ afresh from
  /// the equation of motion with C a = g̈ − C̈ u − 2 Ċ v, so that the step-to-step mode the
  /// jump would excite stays at rest. Returns whether it did; costs two saddle-point solves
  /// with M (the structure factored again).
  bool after_step(double time, const double* u, double* v, double* a);
  /// λ_{n+1} of the last converged step (one per row of constraint_rows()); λ holds the
  /// constraint forces −Cᵀλ acting on the unknowns.
  const std::vector<double>& multipliers() const { return lambda_old_; }
  /// The constraint rows of the last converged step.
  const ConstraintRows& constraint_rows() const { return rows_old_; }

  /// The counters so far.
  const NewtonStatistics& statistics() const { return statistics_; }
  /// The system.
  SecondOrderSystem& system() { return system_; }

 private:
  /// g = f_int(u, v) + C_R v, the force balanced against M a (work = Rayleigh product scratch).
  void balance_force(const double* u, const double* v, double* g);
  double norm(const std::vector<double>& x) const;
  /// The Newton iteration of one attempt at the step (rows_next_ set); throws StepNotConverged.
  void iterate(const StepState& state, double* acceleration);
  /// Throws StepNotConverged for the step of \p state with \p failure.
  [[noreturn]] void fail(const StepState& state, const std::string& failure) const;

  SecondOrderSystem& system_;
  NewtonSettings settings_;
  RayleighDamping rayleigh_;
  NewtonStatistics statistics_;
  bool linear_factor_valid_ = false;  ///< whether the linear path's factorization holds
  MatrixCoefficients factored_;       ///< the coefficients it was factored with
  // g(u_n, v_n) of the last converged iterate, reused when the next step starts from it.
  std::vector<double> cached_u_, cached_v_, cached_force_;
  std::vector<double> u_, v_, force_, fixed_, residual_, correction_, mass_a_, scratch_;
  ConstraintSet* constraints_ = nullptr;
  SaddlePointSolver* saddle_ = nullptr;
  ConstraintRows rows_old_, rows_next_;  // C_n, g_n and C_{n+1}, g_{n+1}
  std::vector<double> lambda_old_, lambda_, constraint_residual_, mu_, constraint_force_;
  double spectral_radius_ = 1;  ///< ρ∞ of the scheme of the last constrained step
};

}  // namespace railfe
