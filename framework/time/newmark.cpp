#include "framework/time/newmark.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace railfe {

NewmarkScheme NewmarkScheme::central_difference() {
  return {0.0, 0.5, 0.0};
}

NewmarkScheme NewmarkScheme::average_acceleration() {
  return {0.25, 0.5, 0.0};
}

NewmarkScheme NewmarkScheme::hht(double alpha) {
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0)) {
    throw std::invalid_argument("HHT alpha must lie in [-1/3, 0], got " + std::to_string(alpha));
  }
  return {(1 - alpha) * (1 - alpha) / 4, (1 - 2 * alpha) / 2, alpha};
}

NewmarkScheme NewmarkScheme::newmark(double beta, double gamma) {
  if (!(beta >= 0.0 && gamma >= 0.5)) {
    throw std::invalid_argument("Newmark needs beta >= 0 and gamma >= 1/2, got beta " +
                                std::to_string(beta) + ", gamma " + std::to_string(gamma));
  }
  return {beta, gamma, 0.0};
}

double NewmarkScheme::spectral_radius_at_infinity() const {
  return (1 + alpha) / (1 - alpha);
}

double NewmarkScheme::critical_step_frequency() const {
  if (gamma >= 0.5 && 2 * beta >= gamma)
    return std::numeric_limits<double>::infinity();
  const double margin = gamma / 2 - beta;
  return margin > 0 ? 1.0 / std::sqrt(margin) : std::numeric_limits<double>::infinity();
}

NewmarkIntegrator::NewmarkIntegrator(NewmarkScheme scheme, std::size_t n)
    : scheme_(scheme), u_old_(n), v_old_(n), u_predicted_(n), v_predicted_(n), a_new_(n) {}

void NewmarkIntegrator::step(double time, double dt, SecondOrderProblem& problem, double* u,
                             double* v, double* a) {
  const std::size_t n = u_old_.size();
  const double beta = scheme_.beta, gamma = scheme_.gamma;
  for (std::size_t i = 0; i < n; ++i) {
    u_old_[i] = u[i];
    v_old_[i] = v[i];
    u_predicted_[i] = u[i] + dt * v[i] + dt * dt * (0.5 - beta) * a[i];
    v_predicted_[i] = v[i] + dt * (1 - gamma) * a[i];
  }
  StepState state;
  state.scheme = &scheme_;
  state.time_next = time + dt;
  state.dt = dt;
  state.n = n;
  state.u_old = u_old_.data();
  state.v_old = v_old_.data();
  state.a_old = a;
  state.u_predicted = u_predicted_.data();
  state.v_predicted = v_predicted_.data();
  problem.solve_for_acceleration(state, a_new_.data());
  for (std::size_t i = 0; i < n; ++i) {
    u[i] = u_predicted_[i] + beta * dt * dt * a_new_[i];
    v[i] = v_predicted_[i] + gamma * dt * a_new_[i];
    a[i] = a_new_[i];
  }
}

}  // namespace railfe
