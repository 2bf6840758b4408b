#include "framework/time/newton_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace railfe {
namespace {

bool same_coefficients(const MatrixCoefficients& a, const MatrixCoefficients& b) {
  return a.mass == b.mass && a.damping == b.damping && a.stiffness == b.stiffness &&
         a.rayleigh_stiffness == b.rayleigh_stiffness;
}

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

void NewtonStepSolver::initial_acceleration(double time, const double* u, const double* v,
                                            double* a) {
  const std::size_t n = u_.size();
  system_.external_force(time, residual_.data());
  balance_force(u, v, force_.data());
  for (std::size_t i = 0; i < n; ++i)
    residual_[i] -= force_[i];
  system_.factor(u, v, {1.0, 0.0, 0.0, 0.0});
  ++statistics_.factorizations;
  linear_factor_valid_ = false;
  system_.solve(residual_.data(), a);
  cached_u_.assign(u, u + n);
  cached_v_.assign(v, v + n);
  cached_force_ = force_;
}

void NewtonStepSolver::solve_for_acceleration(const StepState& state, double* a) {
  const NewmarkScheme& scheme = *state.scheme;
  const double alpha = scheme.alpha, beta = scheme.beta, gamma = scheme.gamma, dt = state.dt;
  const double weight = 1 + alpha, time_old = state.time_next - dt;
  const std::size_t n = u_.size();

  // The part of R that does not depend on a_{n+1}.
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
  }

  const MatrixCoefficients coefficients{1 + weight * gamma * dt * rayleigh_.mass,
                                        weight * gamma * dt, weight * beta * dt * dt,
                                        weight * gamma * dt * rayleigh_.stiffness};
  const bool linear = system_.is_linear();
  std::copy(state.a_old, state.a_old + n, a);
  std::vector<double>& residuals = statistics_.last_residuals;
  residuals.clear();
  double increment = std::numeric_limits<double>::infinity();
  for (int iteration = 0;; ++iteration) {
    for (std::size_t i = 0; i < n; ++i) {
      u_[i] = state.u_predicted[i] + beta * dt * dt * a[i];
      v_[i] = state.v_predicted[i] + gamma * dt * a[i];
    }
    balance_force(u_.data(), v_.data(), force_.data());
    system_.apply_mass(a, mass_a_.data());
    for (std::size_t i = 0; i < n; ++i)
      residual_[i] = mass_a_[i] + weight * force_[i] + fixed_[i];
    const double residual = norm(residual_);
    residuals.push_back(residual);

    std::string failure;
    if (!std::isfinite(residual)) {
      failure = "met a non-finite residual";
    } else if (iteration > 0) {
      const double scale = std::max({norm(mass_a_), weight * norm(force_), norm(fixed_)});
      for (std::size_t i = 0; i < n; ++i)
        scratch_[i] = u_[i] - state.u_old[i];
      const bool converged =
          residual <= std::max(settings_.residual_relative * scale, settings_.residual_absolute) &&
          increment <=
              std::max(settings_.increment_relative * norm(scratch_), settings_.increment_absolute);
      if (converged) {
        cached_u_ = u_;
        cached_v_ = v_;
        cached_force_ = force_;
        ++statistics_.steps;
        statistics_.iterations += iteration;
        statistics_.last_iterations = iteration;
        statistics_.most_iterations = std::max(statistics_.most_iterations, iteration);
        return;
      }
      if (iteration == settings_.max_iterations)
        failure = "did not converge in " + std::to_string(iteration) + " iterations";
    }
    if (!failure.empty()) {
      char where[128];
      std::snprintf(where, sizeof where, "HHT-alpha step from t = %.9g s (dt = %.6g s): ", time_old,
                    dt);
      throw StepNotConverged(std::string(where) + "Newton iteration " + failure +
                                 "; residual norms " + residual_list(residuals),
                             time_old, dt, residuals);
    }

    if (!linear || !linear_factor_valid_ || !same_coefficients(coefficients, factored_)) {
      system_.factor(u_.data(), v_.data(), coefficients);
      ++statistics_.factorizations;
      factored_ = coefficients;
      linear_factor_valid_ = linear;
    }
    system_.solve(residual_.data(), correction_.data());
    for (std::size_t i = 0; i < n; ++i)
      a[i] -= correction_[i];
    increment = beta * dt * dt * norm(correction_);
    if (linear) {  // exact after one solve: no second evaluation
      ++statistics_.steps;
      ++statistics_.iterations;
      statistics_.last_iterations = 1;
      statistics_.most_iterations = std::max(statistics_.most_iterations, 1);
      return;
    }
  }
}

}  // namespace railfe
