#pragma once
/// \file
/// The second-order time integrator family every dynamic module uses: Newmark(β, γ) with the
/// HHT-α extension of Hilber, Hughes and Taylor (1977). Sign convention (docs/theory.md):
/// α ∈ [−1/3, 0] and the balance is taken at t_{n+1+α}:
///
///   M a_{n+1} + (1+α)(f_int(u_{n+1}) + C v_{n+1}) − α (f_int(u_n) + C v_n)
///       = (1+α) f_ext(t_{n+1}) − α f_ext(t_n),
///   u_{n+1} = u_n + Δt v_n + Δt² ((½ − β) a_n + β a_{n+1}),
///   v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1}).
///
/// Central difference is the member β = 0, γ = ½, α = 0 (explicit, with a lumped mass); HHT-α
/// takes β = (1−α)²/4, γ = (1−2α)/2 and damps high frequencies down to a spectral radius
/// ρ∞ = (1+α)/(1−α) while staying second-order accurate and unconditionally stable.

#include <cstddef>
#include <vector>

namespace railfe {

/// The parameters of one member of the family.
struct NewmarkScheme {
  double beta = 0.25;  ///< β
  double gamma = 0.5;  ///< γ
  double alpha = 0.0;  ///< HHT α (0 for plain Newmark)

  /// Central difference: β = 0, γ = ½ (explicit, conditionally stable: ω Δt ≤ 2).
  static NewmarkScheme central_difference();
  /// Average acceleration (trapezoidal rule): β = ¼, γ = ½ (no numerical damping).
  static NewmarkScheme average_acceleration();
  /// HHT-α with α in [−1/3, 0]; throws std::invalid_argument outside that range.
  static NewmarkScheme hht(double alpha);
  /// Plain Newmark with β and γ given (α = 0); throws std::invalid_argument unless β ≥ 0 and
  /// γ ≥ ½ (γ < ½ amplifies every mode).
  static NewmarkScheme newmark(double beta, double gamma);

  /// Whether a step needs no solve with the stiffness (β = 0).
  bool is_explicit() const { return beta == 0.0; }
  /// Spectral radius of the amplification matrix as ω Δt → ∞ (1 for average acceleration,
  /// (1+α)/(1−α) for HHT-α; meaningless for conditionally stable members).
  double spectral_radius_at_infinity() const;
  /// Largest stable ω Δt for undamped systems: 2 for central difference, 1/√(γ/2 − β) for other
  /// conditionally stable members, +∞ when 2β ≥ γ ≥ ½.
  double critical_step_frequency() const;
};

/// Everything a physics module needs to find a_{n+1} in one step.
struct StepState {
  const NewmarkScheme* scheme = nullptr;  ///< the scheme
  double time_next = 0;                   ///< t_{n+1}
  double dt = 0;                          ///< Δt
  std::size_t n = 0;                      ///< number of unknowns (owned DOFs)
  const double* u_old = nullptr;          ///< u_n
  const double* v_old = nullptr;          ///< v_n
  const double* a_old = nullptr;          ///< a_n
  const double* u_predicted = nullptr;    ///< ũ = u_n + Δt v_n + Δt² (½ − β) a_n
  const double* v_predicted = nullptr;    ///< ṽ = v_n + Δt (1 − γ) a_n
};

/// The physics hook of the integrator: one method serves explicit and implicit schemes.
class SecondOrderProblem {
 public:
  virtual ~SecondOrderProblem() = default;
  /// Finds a_{n+1} such that, with u = ũ + β Δt² a and v = ṽ + γ Δt a, the HHT balance above
  /// holds. Explicit modules (β = 0) evaluate forces at ũ and divide by the lumped mass; implicit
  /// ones iterate with Newton. Writes \p acceleration (length n).
  virtual void solve_for_acceleration(const StepState& state, double* acceleration) = 0;
};

/// Advances (u, v, a) by one step of a Newmark/HHT scheme.
class NewmarkIntegrator {
 public:
  /// An integrator for \p n unknowns.
  NewmarkIntegrator(NewmarkScheme scheme, std::size_t n);
  /// The scheme.
  const NewmarkScheme& scheme() const { return scheme_; }
  /// Advances u, v, a (length n, holding t_n values) to t_n + dt.
  void step(double time, double dt, SecondOrderProblem& problem, double* u, double* v, double* a);

 private:
  NewmarkScheme scheme_;
  std::vector<double> u_old_, v_old_, u_predicted_, v_predicted_, a_new_;
};

}  // namespace railfe
