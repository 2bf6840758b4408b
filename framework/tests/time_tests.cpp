// The Newmark / HHT-alpha family on a single-degree-of-freedom oscillator, against the closed-form
// properties of each scheme (Hughes, The Finite Element Method, ch. 9; Hilber, Hughes & Taylor
// 1977): exact discrete solutions, stability limits, spectral radius and order of accuracy.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/time/newmark.hpp"

namespace railfe {
namespace {

// m a + c v + k u = 0 balanced at t_{n+1+α}, solved for a_{n+1} in closed form.
class Oscillator : public SecondOrderProblem {
 public:
  Oscillator(double mass, double damping, double stiffness)
      : m_(mass), c_(damping), k_(stiffness) {}

  void solve_for_acceleration(const StepState& state, double* acceleration) override {
    const NewmarkScheme& s = *state.scheme;
    const double dt = state.dt, alpha = s.alpha;
    const double rhs = -(1 + alpha) * (c_ * state.v_predicted[0] + k_ * state.u_predicted[0]) +
                       alpha * (c_ * state.v_old[0] + k_ * state.u_old[0]);
    acceleration[0] = rhs / (m_ + (1 + alpha) * (s.gamma * dt * c_ + s.beta * dt * dt * k_));
  }

 private:
  double m_, c_, k_;
};

struct Motion {
  double u, v;
};

// Integrates from u = 1, v = 0 (unit frequency unless given) for n steps.
Motion integrate(const NewmarkScheme& scheme, double omega_dt, int steps, double omega = 1.0) {
  Oscillator oscillator(1.0, 0.0, omega * omega);
  NewmarkIntegrator integrator(scheme, 1);
  double u = 1, v = 0, a = -omega * omega;
  const double dt = omega_dt / omega;
  for (int n = 0; n < steps; ++n)
    integrator.step(n * dt, dt, oscillator, &u, &v, &a);
  return {u, v};
}

TEST(Newmark, CentralDifferenceFollowsItsDiscreteSolution) {
  // u_n = cos(n Ω Δt) with sin(Ω Δt / 2) = ω Δt / 2, exactly, for any ω Δt < 2.
  for (double omega_dt : {0.1, 0.9, 1.9}) {
    const double discrete = 2 * std::asin(omega_dt / 2);
    for (int steps : {1, 7, 500}) {
      EXPECT_NEAR(integrate(NewmarkScheme::central_difference(), omega_dt, steps).u,
                  std::cos(steps * discrete), 1e-10)
          << omega_dt << " " << steps;
    }
  }
}

TEST(Newmark, CentralDifferenceBreaksAboveItsLimit) {
  EXPECT_DOUBLE_EQ(NewmarkScheme::central_difference().critical_step_frequency(), 2.0);
  EXPECT_LT(std::abs(integrate(NewmarkScheme::central_difference(), 1.99, 2000).u), 1.5);
  EXPECT_GT(std::abs(integrate(NewmarkScheme::central_difference(), 2.05, 200).u), 1e6);
}

TEST(Newmark, AverageAccelerationKeepsAmplitudeAtAnyStep) {
  // Trapezoidal rule: |amplification| = 1 and tan(Ω Δt / 2) = ω Δt / 2.
  const NewmarkScheme scheme = NewmarkScheme::average_acceleration();
  EXPECT_TRUE(std::isinf(scheme.critical_step_frequency()));
  for (double omega_dt : {0.5, 3.0, 100.0}) {
    const double discrete = 2 * std::atan(omega_dt / 2);
    const Motion run = integrate(scheme, omega_dt, 301);
    EXPECT_NEAR(run.u, std::cos(301 * discrete), 1e-9) << omega_dt;
    EXPECT_NEAR(run.u * run.u + run.v * run.v, 1.0, 1e-9) << omega_dt;  // ω = 1: energy
  }
}

// Spectral radius of the one-step amplification matrix of (u, Δt v, Δt² a), built column by
// column by stepping the three unit states.
double spectral_radius(const NewmarkScheme& scheme, double omega_dt) {
  Oscillator oscillator(1.0, 0.0, 1.0);
  NewmarkIntegrator integrator(scheme, 1);
  const double dt = omega_dt;
  Eigen::Matrix3d amplification;
  for (int column = 0; column < 3; ++column) {
    double state[3] = {0, 0, 0};
    state[column] = 1;
    double u = state[0], v = state[1] / dt, a = state[2] / (dt * dt);
    integrator.step(0.0, dt, oscillator, &u, &v, &a);
    amplification(0, column) = u;
    amplification(1, column) = v * dt;
    amplification(2, column) = a * dt * dt;
  }
  return amplification.eigenvalues().cwiseAbs().maxCoeff();
}

TEST(Newmark, HhtSpectralRadiusAtInfinity) {
  for (double alpha : {-0.05, -0.1, -0.2, -1.0 / 3.0}) {
    const NewmarkScheme scheme = NewmarkScheme::hht(alpha);
    EXPECT_DOUBLE_EQ(scheme.beta, (1 - alpha) * (1 - alpha) / 4);
    EXPECT_DOUBLE_EQ(scheme.gamma, (1 - 2 * alpha) / 2);
    const double expected = (1 + alpha) / (1 - alpha);
    EXPECT_DOUBLE_EQ(scheme.spectral_radius_at_infinity(), expected);
    EXPECT_NEAR(spectral_radius(scheme, 1e6), expected, 1e-4) << "alpha " << alpha;
    // Unconditionally stable: never above 1, and dissipative only at high frequency.
    for (double omega_dt : {0.01, 0.3, 3.0, 30.0, 300.0}) {
      EXPECT_LE(spectral_radius(scheme, omega_dt), 1.0 + 1e-12) << omega_dt;
    }
    EXPECT_GT(spectral_radius(scheme, 0.01), 0.9999);
  }
  EXPECT_NEAR(spectral_radius(NewmarkScheme::average_acceleration(), 1e6), 1.0, 1e-9);
  EXPECT_GT(spectral_radius(NewmarkScheme::central_difference(), 2.1), 1.5);
  EXPECT_THROW(NewmarkScheme::hht(0.1), std::invalid_argument);
  EXPECT_THROW(NewmarkScheme::hht(-0.4), std::invalid_argument);
}

TEST(Newmark, HhtIsSecondOrderAccurate) {
  // Largest error over one period against the exact cos(t), halving Δt: ratio → 4. (At t = 2π
  // alone the O(Δt²) phase error vanishes with sin(2π) and the O(Δt³) damping shows instead.)
  const NewmarkScheme scheme = NewmarkScheme::hht(-0.1);
  Oscillator oscillator(1.0, 0.0, 1.0);
  double previous = 0;
  for (int steps : {100, 200, 400}) {
    const double dt = 2 * M_PI / steps;
    NewmarkIntegrator integrator(scheme, 1);
    double u = 1, v = 0, a = -1, error = 0;
    for (int n = 0; n < steps; ++n) {
      integrator.step(n * dt, dt, oscillator, &u, &v, &a);
      error = std::max(error, std::abs(u - std::cos((n + 1) * dt)));
    }
    if (previous > 0) {
      EXPECT_NEAR(previous / error, 4.0, 0.1) << steps;
    }
    previous = error;
  }
}

TEST(Newmark, HhtWithZeroAlphaIsAverageAcceleration) {
  const Motion a = integrate(NewmarkScheme::hht(0.0), 0.7, 50);
  const Motion b = integrate(NewmarkScheme::average_acceleration(), 0.7, 50);
  EXPECT_DOUBLE_EQ(a.u, b.u);
  EXPECT_DOUBLE_EQ(a.v, b.v);
}

}  // namespace
}  // namespace railfe
