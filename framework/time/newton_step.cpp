#include "framework/time/newton_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace railfe {
namespace {

std::string residual_list(const std::vector<double>& residuals) {
  std::string text;
  char number[32];
  for (double r : residuals) {
    std::snprintf(number, sizeof number, "%.3e", r);
    text += (text.empty() ? "" : ", ") + std::string(number);
  }
  return "[" + text + "]";
}

}  // namespace

NewtonStepSolver::NewtonStepSolver(SecondOrderSystem& system, NewtonSettings settings,
                                   RayleighDamping rayleigh)
    : system_(system), settings_(settings), rayleigh_(rayleigh) {
  const std::size_t n = system.n_unknowns();
  for (auto* x : {&u_, &v_, &force_, &fixed_, &residual_, &correction_, &mass_a_, &scratch_})
    x->assign(n, 0.0);
}

void NewtonStepSolver::balance_force(const double* u, const double* v, double* g) {
  system_.internal_force(u, v, g);
  ++statistics_.force_evaluations;
  const std::size_t n = u_.size();
  if (rayleigh_.mass != 0) {
    system_.apply_mass(v, scratch_.data());
    for (std::size_t i = 0; i < n; ++i)
      g[i] += rayleigh_.mass * scratch_[i];
  }
  if (rayleigh_.stiffness != 0) {
    system_.apply_rayleigh_stiffness(v, scratch_.data());
    for (std::size_t i = 0; i < n; ++i)
      g[i] += rayleigh_.stiffness * scratch_[i];
  }
}

double NewtonStepSolver::norm(const std::vector<double>& x) const {
  return std::sqrt(system_.dot(x.data(), x.data()));
}

void NewtonStepSolver::constrain(ConstraintSet* constraints, SaddlePointSolver* solver) {
  if ((constraints == nullptr) != (solver == nullptr))
    throw std::logic_error("NewtonStepSolver::constrain needs both a constraint set and a solver");
  constraints_ = constraints;
  saddle_ = solver;
  rows_old_.clear();
  lambda_old_.clear();
  linear_factor_valid_ = false;
}

void NewtonStepSolver::initial_acceleration(double time, const double* u, const double* v,
                                            double* a) {
  const std::size_t n = u_.size();
  system_.external_force(time, residual_.data());
  balance_force(u, v, force_.data());
  for (std::size_t i = 0; i < n; ++i)
    residual_[i] -= force_[i];
  ++statistics_.factorizations;
  linear_factor_valid_ = false;
  if (constraints_ != nullptr) {
    // [M Cᵀ; C 0] [a; λ] = [f − g; 0]: the constraint's acceleration terms (C̈ u + 2 Ċ v, g̈)
    // are taken as zero, exact for a structure at rest under a flat path.
    rows_old_.clear();
    constraints_->rows_at(time, rows_old_);
    constraint_residual_.assign(rows_old_.size(), 0.0);
    lambda_old_.assign(rows_old_.size(), 0.0);
    saddle_->factor(u, v, {1.0, 0.0, 0.0, 0.0}, rows_old_);
    saddle_->solve(residual_.data(), constraint_residual_.data(), a, lambda_old_.data());
  } else {
    system_.factor(u, v, {1.0, 0.0, 0.0, 0.0});
    system_.solve(residual_.data(), a);
  }
  cached_u_.assign(u, u + n);
  cached_v_.assign(v, v + n);
  cached_force_ = force_;
}

bool NewtonStepSolver::after_step(double time, const double* u, double* v, double* a) {
  if (constraints_ == nullptr || !constraints_->needs_restart(time, spectral_radius_))
    return false;
  const std::size_t n = u_.size();
  rows_old_.clear();
  constraints_->rows_at(time, rows_old_);
  const std::size_t nc = rows_old_.size();
  std::vector<double> velocity_rate(nc), acceleration_rate(nc);
  constraints_->rates(time, u, v, nc, velocity_rate.data(), acceleration_rate.data());
  saddle_->factor(u, v, {1.0, 0.0, 0.0, 0.0}, rows_old_);
  ++statistics_.factorizations;
  linear_factor_valid_ = false;
  // [M Cᵀ; C 0] [Δv; μ] = [0; ġ − Ċ u − C v]: the mass-weighted projection of v.
  constraint_residual_.resize(nc);
  mu_.resize(nc);
  rows_old_.multiply(v, constraint_residual_.data());
  for (std::size_t i = 0; i < nc; ++i)
    constraint_residual_[i] = velocity_rate[i] - constraint_residual_[i];
  std::fill(residual_.begin(), residual_.end(), 0.0);
  saddle_->solve(residual_.data(), constraint_residual_.data(), correction_.data(), mu_.data());
  for (std::size_t i = 0; i < n; ++i)
    v[i] += correction_[i];
  // [M Cᵀ; C 0] [a; λ] = [f − g(u, v); g̈ − C̈ u − 2 Ċ v].
  system_.external_force(time, residual_.data());
  balance_force(u, v, force_.data());
  for (std::size_t i = 0; i < n; ++i)
    residual_[i] -= force_[i];
  lambda_old_.assign(nc, 0.0);
  saddle_->solve(residual_.data(), acceleration_rate.data(), a, lambda_old_.data());
  cached_u_.assign(u, u + n);
  cached_v_.assign(v, v + n);
  cached_force_ = force_;
  ++statistics_.restarts;
  return true;
}

void NewtonStepSolver::fail(const StepState& state, const std::string& failure) const {
  const double time_old = state.time_next - state.dt;
  char where[128];
  std::snprintf(where, sizeof where, "HHT-alpha step from t = %.9g s (dt = %.6g s): ", time_old,
                state.dt);
  const std::vector<double>& residuals = statistics_.last_residuals;
  throw StepNotConverged(
      std::string(where) + failure + "; residual norms " + residual_list(residuals), time_old,
      state.dt, residuals);
}

void NewtonStepSolver::solve_for_acceleration(const StepState& state, double* a) {
  const auto started = std::chrono::steady_clock::now();
  if (constraints_ == nullptr) {
    iterate(state, a);
  } else {
    if (state.scheme->beta == 0)
      throw std::logic_error("constraints need an implicit scheme (beta > 0)");
    spectral_radius_ = state.scheme->spectral_radius_at_infinity();
    // A constraint that releases or engages at t_{n+1} repeats the step with the new rows.
    const int most_changes = 8;
    for (int change = 0;; ++change) {
      rows_next_.clear();
      constraints_->rows_at(state.time_next, rows_next_);
      iterate(state, a);
      if (!constraints_->accept(state.time_next, u_.data(), lambda_.data()))
        break;
      if (change == most_changes)
        fail(state, "the constraints kept releasing and engaging (" + std::to_string(most_changes) +
                        " changes in one step)");
    }
    rows_old_ = rows_next_;
    lambda_old_ = lambda_;
  }
  const int iterations = statistics_.last_iterations;
  ++statistics_.steps;
  statistics_.iterations += static_cast<std::size_t>(iterations);
  statistics_.most_iterations = std::max(statistics_.most_iterations, iterations);
  statistics_.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void NewtonStepSolver::iterate(const StepState& state, double* a) {
  const NewmarkScheme& scheme = *state.scheme;
  const double alpha = scheme.alpha, beta = scheme.beta, gamma = scheme.gamma, dt = state.dt;
  const double weight = 1 + alpha, time_old = state.time_next - dt;
  const std::size_t n = u_.size();
  const bool constrained = constraints_ != nullptr;
  const std::size_t nc = constrained ? rows_next_.size() : 0;

  // The part of R that does not depend on a_{n+1} (or λ_{n+1}).
  system_.external_force(state.time_next, fixed_.data());
  for (std::size_t i = 0; i < n; ++i)
    fixed_[i] *= -weight;
  if (alpha != 0) {
    system_.external_force(time_old, residual_.data());
    const bool cached = cached_u_.size() == n &&
                        std::equal(cached_u_.begin(), cached_u_.end(), state.u_old) &&
                        std::equal(cached_v_.begin(), cached_v_.end(), state.v_old);
    if (!cached)
      balance_force(state.u_old, state.v_old, force_.data());
    const double* old_force = cached ? cached_force_.data() : force_.data();
    for (std::size_t i = 0; i < n; ++i)
      fixed_[i] += alpha * (residual_[i] - old_force[i]);
    if (constrained && lambda_old_.size() == rows_old_.size())
      rows_old_.add_transpose(lambda_old_.data(), -alpha, fixed_.data());
  }
  if (constrained) {
    if (lambda_old_.size() == nc)
      lambda_ = lambda_old_;
    else
      lambda_.assign(nc, 0.0);
    constraint_residual_.resize(nc);
    mu_.resize(nc);
    constraint_force_.resize(n);
  }

  const MatrixCoefficients coefficients{1 + weight * gamma * dt * rayleigh_.mass,
                                        weight * gamma * dt, weight * beta * dt * dt,
                                        weight * gamma * dt * rayleigh_.stiffness};
  const bool linear = system_.is_linear();
  std::copy(state.a_old, state.a_old + n, a);
  std::vector<double>& residuals = statistics_.last_residuals;
  residuals.clear();
  double increment = std::numeric_limits<double>::infinity();
  // Backtracking (settings_.line_search): the iterate before the last correction, the
  // correction and its fraction taken, and the residual there.
  std::vector<double> a_base, lambda_base, mu_taken;
  double step_fraction = 1, base_residual = std::numeric_limits<double>::infinity();
  int halvings = 0;
  for (int iteration = 0;; ++iteration) {
    for (std::size_t i = 0; i < n; ++i) {
      u_[i] = state.u_predicted[i] + beta * dt * dt * a[i];
      v_[i] = state.v_predicted[i] + gamma * dt * a[i];
    }
    balance_force(u_.data(), v_.data(), force_.data());
    system_.apply_mass(a, mass_a_.data());
    for (std::size_t i = 0; i < n; ++i)
      residual_[i] = mass_a_[i] + weight * force_[i] + fixed_[i];
    double constraint_error = 0;
    if (constrained) {
      std::fill(constraint_force_.begin(), constraint_force_.end(), 0.0);
      rows_next_.add_transpose(lambda_.data(), weight, constraint_force_.data());
      for (std::size_t i = 0; i < n; ++i)
        residual_[i] += constraint_force_[i];
      rows_next_.multiply(u_.data(), constraint_residual_.data());
      for (std::size_t i = 0; i < nc; ++i) {
        constraint_residual_[i] -= rows_next_.rhs[i];
        constraint_error = std::max(constraint_error, std::abs(constraint_residual_[i]));
      }
    }
    const double residual = norm(residual_);
    // Only from an iterate that satisfies the (linear) constraint rows: the first correction
    // moves the constrained unknowns onto them, which ‖R‖ alone does not measure.
    const bool may_backtrack = !constrained || iteration > 1;
    if (settings_.line_search && may_backtrack && residual > base_residual && halvings < 8) {
      // The full correction made things worse: take half of what was taken, from the base.
      step_fraction *= 0.5;
      ++halvings;
      for (std::size_t i = 0; i < n; ++i)
        a[i] = a_base[i] - step_fraction * correction_[i];
      for (std::size_t i = 0; i < nc; ++i)
        lambda_[i] = lambda_base[i] - step_fraction * mu_taken[i] / weight;
      increment = beta * dt * dt * step_fraction * norm(correction_);
      --iteration;
      continue;
    }
    residuals.push_back(residual);

    std::string failure;
    if (!std::isfinite(residual) || !std::isfinite(constraint_error)) {
      failure = "met a non-finite residual";
    } else if (iteration > 0) {
      double scale = std::max({norm(mass_a_), weight * norm(force_), norm(fixed_)});
      if (constrained)
        scale = std::max(scale, norm(constraint_force_));
      for (std::size_t i = 0; i < n; ++i)
        scratch_[i] = u_[i] - state.u_old[i];
      const double displacement_floor =
          std::max(settings_.increment_relative * norm(scratch_), settings_.increment_absolute);
      const bool converged =
          residual <= std::max(settings_.residual_relative * scale, settings_.residual_absolute) &&
          increment <= displacement_floor && constraint_error <= displacement_floor;
      if (converged) {
        cached_u_ = u_;
        cached_v_ = v_;
        cached_force_ = force_;
        statistics_.last_iterations = iteration;
        return;
      }
      if (iteration == settings_.max_iterations)
        failure = "did not converge in " + std::to_string(iteration) + " iterations";
    }
    if (!failure.empty())
      fail(state, "Newton iteration " + failure);

    if (constrained) {
      if ((!linear && !settings_.tangent_once_per_step) || iteration == 0) {
        saddle_->factor(u_.data(), v_.data(), coefficients, rows_next_);
        ++statistics_.factorizations;
      }
      // [A Cᵀ; C 0] [c; μ] = [R; r_c / (β Δt²)]; a −= c, λ −= μ / (1+α).
      for (std::size_t i = 0; i < nc; ++i)
        constraint_residual_[i] /= beta * dt * dt;
      saddle_->solve(residual_.data(), constraint_residual_.data(), correction_.data(), mu_.data());
      for (std::size_t i = 0; i < nc; ++i)
        lambda_[i] -= mu_[i] / weight;
    } else {
      if (!linear || !linear_factor_valid_ || !same_coefficients(coefficients, factored_)) {
        system_.factor(u_.data(), v_.data(), coefficients);
        ++statistics_.factorizations;
        factored_ = coefficients;
        linear_factor_valid_ = linear;
      }
      system_.solve(residual_.data(), correction_.data());
    }
    if (settings_.line_search) {
      a_base.assign(a, a + n);
      lambda_base = lambda_;
      if (constrained)  // the multipliers were moved by the solve above: take that back
        for (std::size_t i = 0; i < nc; ++i)
          lambda_base[i] += mu_[i] / weight;
      mu_taken = mu_;
      step_fraction = 1;
      halvings = 0;
      base_residual = residual;
    }
    for (std::size_t i = 0; i < n; ++i)
      a[i] -= correction_[i];
    increment = beta * dt * dt * norm(correction_);
    if (linear) {  // exact after one solve: no second evaluation
      for (std::size_t i = 0; i < n; ++i)
        u_[i] = state.u_predicted[i] + beta * dt * dt * a[i];
      statistics_.last_iterations = 1;
      return;
    }
  }
}

}  // namespace railfe
