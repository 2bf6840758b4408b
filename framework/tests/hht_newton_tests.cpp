// HHT-α Newton iterations (framework/time/hht_integrator.hpp) on nonlinear and damped systems: the
// cubic-spring period from the complete elliptic integral, quadratic Newton convergence, the linear
// fast path, Rayleigh damping, step cut-back and the report of a step that does not converge.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/tests/hht_test_systems.hpp"

namespace railfe {
namespace {

using hht_test::history;
using hht_test::linear_spring;
using hht_test::ScalarSystem;

// ẍ + x³ = 0 from x = A, ẋ = 0: period 4 K(½) / A with K the complete elliptic integral of the
// first kind at parameter ½ (K = 1.854074677301372).
double cubic_period(double amplitude) {
  return 4 * 1.854074677301372 / amplitude;
}

// Mean period from the zero crossings (linear interpolation) of u_n spaced dt.
double mean_period(const std::vector<double>& u, double dt) {
  std::vector<double> crossings;
  for (std::size_t n = 0; n + 1 < u.size(); ++n)
    if (u[n] > 0 && u[n + 1] <= 0)
      crossings.push_back(dt * (n + u[n] / (u[n] - u[n + 1])));
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

ScalarSystem cubic_spring(bool consistent = true) {
  return ScalarSystem([](double u) { return u * u * u; },
                      [consistent](double u) { return consistent ? 3 * u * u : 1.0; });
}

TEST(HhtNewton, CubicSpringPeriodFromTheEllipticIntegral) {
  const double amplitude = 2.0, period = cubic_period(amplitude);
  double previous = 0;
  for (int per_period : {100, 200, 400}) {
    const double dt = period / per_period;
    ScalarSystem spring = cubic_spring();
    const double error =
        mean_period(history(spring, NewmarkScheme::hht(0.0), dt, 10 * per_period, amplitude, 0),
                    dt) /
            period -
        1;
    std::printf("cubic spring: T/dt %d period error %.3e\n", per_period, error);
    EXPECT_LT(std::abs(error), 2e-3);
    if (previous != 0) {
      EXPECT_NEAR(previous / error, 4.0, 0.2);
    }
    previous = error;
  }
}

// The smallest ratio log(r_{k+1}/r_k) / log(r_k/r_{k-1}) over iterates well above round-off.
double convergence_order(const std::vector<double>& r, double floor) {
  double order = 10;
  for (std::size_t k = 1; k + 1 < r.size(); ++k)
    if (r[k + 1] > floor)
      order = std::min(order, std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]));
  return order;
}

TEST(HhtNewton, NewtonConvergesQuadraticallyOnACubicSpring) {
  // Large steps (T/10) so that each step needs several iterations; the consistent tangent gives
  // order 2, the constant tangent of modified Newton order 1 (which proves the check can fail).
  const double dt = cubic_period(2.0) / 10;
  NewtonSettings tight;
  tight.residual_relative = 1e-13;
  tight.increment_relative = 1e-13;
  tight.max_iterations = 60;
  for (bool consistent : {true, false}) {
    ScalarSystem spring = cubic_spring(consistent);
    HhtIntegrator integrator(NewmarkScheme::hht(-0.1), spring, tight);
    double u = 2, v = 0, a = 0, worst_order = 10;
    int most = 0;
    integrator.initialize(0, &u, &v, &a);
    for (int n = 0; n < 30; ++n) {
      integrator.advance(n * dt, dt, &u, &v, &a);
      const NewtonStatistics& s = integrator.newton_statistics();
      most = std::max(most, s.last_iterations);
      worst_order = std::min(worst_order, convergence_order(s.last_residuals, 1e-9));
      if (n == 3) {
        std::printf("%s tangent, step 4 residuals:", consistent ? "consistent" : "constant");
        for (double r : s.last_residuals)
          std::printf(" %.3e", r);
        std::printf("\n");
      }
    }
    std::printf("%s tangent: most iterations %d, lowest order %.2f\n",
                consistent ? "consistent" : "constant", most, worst_order);
    if (consistent) {
      EXPECT_LE(most, 6);
      EXPECT_GT(worst_order, 1.8);
    } else {
      EXPECT_GT(most, 10);
      EXPECT_LT(worst_order, 1.3);
    }
    EXPECT_EQ(integrator.n_cut_backs(), 0u);
  }
}

TEST(HhtNewton, LinearFastPathFactorsOncePerStepSize) {
  // Two unknowns, a load, Rayleigh damping; flagged linear: one factorization while Δt stays,
  // one solve per step; the Newton path reaches the same state.
  Eigen::MatrixXd m(2, 2), c = Eigen::MatrixXd::Zero(2, 2), k(2, 2);
  m << 2, 0, 0, 1;
  k << 300, -100, -100, 100;
  auto load = [](double t, double* f) {
    f[0] = 0;
    f[1] = 10 * std::sin(7 * t);
  };
  LinearDenseSystem linear(m, c, k, load);
  struct NotFlagged : LinearDenseSystem {
    using LinearDenseSystem::LinearDenseSystem;
    bool is_linear() const override { return false; }
  } newton(m, c, k, load);
  const RayleighDamping rayleigh{0.5, 1e-3};
  HhtIntegrator fast(NewmarkScheme::hht(-0.2), linear, {}, rayleigh);
  HhtIntegrator full(NewmarkScheme::hht(-0.2), newton, {}, rayleigh);
  double u1[2] = {0.01, 0}, v1[2] = {0, 0.5}, a1[2], u2[2] = {0.01, 0}, v2[2] = {0, 0.5}, a2[2];
  fast.initialize(0, u1, v1, a1);
  full.initialize(0, u2, v2, a2);
  // The initial acceleration solves M a = f(0) − K u − C_R v.
  const Eigen::Vector2d a0 =
      m.lu().solve(-k * Eigen::Vector2d(0.01, 0) - (0.5 * m + 1e-3 * k) * Eigen::Vector2d(0, 0.5));
  EXPECT_NEAR(a1[0], a0(0), 1e-12);
  EXPECT_NEAR(a1[1], a0(1), 1e-12);
  for (int n = 0; n < 100; ++n) {
    const double dt = n < 50 ? 0.01 : 0.005;
    fast.advance(n * dt, dt, u1, v1, a1);
    full.advance(n * dt, dt, u2, v2, a2);
  }
  EXPECT_EQ(fast.newton_statistics().factorizations, 3u);  // initial a, Δt = 0.01, Δt = 0.005
  EXPECT_EQ(fast.newton_statistics().iterations, 100u);
  EXPECT_GT(full.newton_statistics().factorizations, 150u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(u1[i], u2[i], 1e-10 * std::abs(u2[i]) + 1e-15);
    EXPECT_NEAR(v1[i], v2[i], 1e-9 * std::abs(v2[i]) + 1e-13);
  }
  // The time-n forces are reused from the converged iterate, not evaluated again: one
  // evaluation per iteration plus the initial one.
  const NewtonStatistics& s = full.newton_statistics();
  EXPECT_EQ(s.force_evaluations, s.iterations + s.steps + 1);
}

TEST(HhtNewton, RayleighDampingDecaysAtItsRatio) {
  // ü + 2ζω u̇ + ω² u = 0 with C_R = a M + b K: ζ = (a/ω + b ω)/2. Amplitude after 5 periods
  // against exp(−ζ ω t), trapezoidal rule with 400 steps a period; and the same run with C
  // in the system instead of Rayleigh damping is identical.
  const double w = 2 * M_PI, a_r = 0.3, b_r = 0.01, zeta = (a_r / w + b_r * w) / 2;
  const double dt = 1.0 / 400;
  Eigen::MatrixXd one = Eigen::MatrixXd::Identity(1, 1);
  LinearDenseSystem bare(one, 0 * one, w * w * one),
      damped(one, (a_r + b_r * w * w) * one, w * w * one);
  HhtIntegrator rayleigh(NewmarkScheme::average_acceleration(), bare, {}, {a_r, b_r});
  HhtIntegrator explicit_c(NewmarkScheme::average_acceleration(), damped);
  double u = 1, v = -zeta * w, a, u2 = 1, v2 = -zeta * w, a2;
  rayleigh.initialize(0, &u, &v, &a);
  explicit_c.initialize(0, &u2, &v2, &a2);
  for (int n = 0; n < 2000; ++n) {
    rayleigh.advance(n * dt, dt, &u, &v, &a);
    explicit_c.advance(n * dt, dt, &u2, &v2, &a2);
  }
  const double wd = w * std::sqrt(1 - zeta * zeta);
  EXPECT_NEAR(u, std::exp(-zeta * w * 5) * std::cos(wd * 5), 1e-4);
  EXPECT_NEAR(u, u2, 1e-13);
}

// A saturating spring f = F atan(u): from a fast start, Newton at a large step overshoots into
// the flat part of the curve and diverges.
ScalarSystem saturating_spring(double f) {
  return ScalarSystem([f](double u) { return f * std::atan(u); },
                      [f](double u) { return f / (1 + u * u); });
}

TEST(HhtNewton, StepCutBackHalvesAndRecovers) {
  ScalarSystem spring = saturating_spring(100);
  NewtonSettings settings;
  settings.max_iterations = 8;
  HhtIntegrator integrator(NewmarkScheme::hht(-0.1), spring, settings);
  std::vector<CutBack> cuts;
  integrator.on_cut_back([&](const CutBack& cut) { cuts.push_back(cut); });
  double u = 0, v = 5, a = 0;
  integrator.initialize(0, &u, &v, &a);
  std::vector<int> sub_steps;
  const double dt = 0.4;
  for (int n = 0; n < 20; ++n)
    sub_steps.push_back(integrator.advance(n * dt, dt, &u, &v, &a));
  ASSERT_FALSE(cuts.empty());
  EXPECT_EQ(cuts.size(), integrator.n_cut_backs());
  EXPECT_DOUBLE_EQ(cuts.front().next_step, cuts.front().failed_step / 2);
  EXPECT_FALSE(cuts.front().residuals.empty());
  EXPECT_NE(cuts.front().reason.find("t = "), std::string::npos);
  EXPECT_EQ(sub_steps.back(), 1);  // recovered: the last steps run at the nominal Δt
  int total = 0;
  for (int s : sub_steps)
    total += s;
  std::printf("cut-backs %zu, sub-steps %d over 20 steps; first cut at t = %.2f\n", cuts.size(),
              total, cuts.front().time);
  // Energy ½v² + F (u atan u − ½ ln(1 + u²)) does not grow (HHT-α only dissipates).
  const double energy = 0.5 * v * v + 100 * (u * std::atan(u) - 0.5 * std::log1p(u * u));
  std::printf("energy %.4f of 12.5\n", energy);
  EXPECT_LT(energy, 12.5 * (1 + 1e-9));
}

TEST(HhtNewton, ReportsAStepThatDoesNotConverge) {
  ScalarSystem spring = saturating_spring(1000);
  NewtonSettings settings;
  settings.max_iterations = 8;
  CutBackSettings cut_back;
  cut_back.max_halvings = 1;
  HhtIntegrator integrator(NewmarkScheme::hht(-0.1), spring, settings, {}, cut_back);
  double u = 0, v = 20, a = 0;
  integrator.initialize(0, &u, &v, &a);
  try {
    integrator.advance(1.0, 0.4, &u, &v, &a);
    FAIL() << "the step should not converge";
  } catch (const StepNotConverged& failure) {
    const std::string message = failure.what();
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find("t = 1"), std::string::npos);
    EXPECT_NE(message.find("residual norms ["), std::string::npos);
    EXPECT_NE(message.find("gave up after 1 halvings of dt = 0.4 s"), std::string::npos);
    EXPECT_FALSE(failure.residuals.empty());
    EXPECT_EQ(integrator.n_cut_backs(), 1u);
  }
  EXPECT_EQ(u, 0.0);  // the last converged state is kept
  EXPECT_EQ(v, 20.0);
}

TEST(HhtNewton, LineSearchConvergesWhereFullStepsCycle) {
  // The step above, where full Newton corrections on F atan(u) overshoot from one flat branch
  // to the other: halving the corrections that raise the residual converges without any cut
  // back of the step, and the result satisfies the step's equation.
  for (bool line_search : {false, true}) {
    ScalarSystem spring = saturating_spring(1000);
    NewtonSettings settings;
    settings.max_iterations = 30;
    settings.line_search = line_search;
    CutBackSettings cut_back;
    cut_back.max_halvings = 0;
    HhtIntegrator integrator(NewmarkScheme::hht(-0.1), spring, settings, {}, cut_back);
    double u = 0, v = 20, a = 0;
    integrator.initialize(0, &u, &v, &a);
    if (!line_search) {
      EXPECT_THROW(integrator.advance(1.0, 0.4, &u, &v, &a), StepNotConverged);
      continue;
    }
    ASSERT_NO_THROW(integrator.advance(1.0, 0.4, &u, &v, &a));
    // HHT-α balance of the step from (0, 20, a0 = 0): m a1 + (1+α) f(u1) − α f(u0) = 0.
    const double alpha = -0.1, f1 = 1000 * std::atan(u);
    EXPECT_NEAR(a + (1 + alpha) * f1, 0.0, 1e-6 * std::abs(f1));
    std::printf("converged in %d corrections: u = %.6f\n",
                integrator.newton_statistics().last_iterations, u);
  }
}

TEST(HhtNewton, NewmarkParametersAreChecked) {
  EXPECT_NO_THROW(NewmarkScheme::newmark(0.3025, 0.6));
  EXPECT_THROW(NewmarkScheme::newmark(0.25, 0.4), std::invalid_argument);
  EXPECT_THROW(NewmarkScheme::newmark(-0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(NewmarkScheme::hht(0.05), std::invalid_argument);  // railfe's α is ≤ 0
}

}  // namespace
}  // namespace railfe
