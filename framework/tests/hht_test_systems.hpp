#pragma once
/// \file
/// Test helpers for the HHT-α integrator tests: a one-unknown system m a + f(u) = load(t) with any
/// force law and tangent, and a run that records u_n.

#include <Eigen/Dense>

#include <functional>
#include <vector>

#include "framework/time/dense_system.hpp"
#include "framework/time/hht_integrator.hpp"

namespace railfe {
namespace hht_test {

/// m a + f(u) = load(t) for one unknown, with the tangent df (a wrong one makes modified Newton).
class ScalarSystem : public DenseSecondOrderSystem {
 public:
  /// The system with force \p f, tangent \p df, linearity flag and load (none when empty).
  ScalarSystem(std::function<double(double)> f, std::function<double(double)> df,
               bool linear = false, std::function<double(double)> load = {})
      : DenseSecondOrderSystem(Eigen::MatrixXd::Identity(1, 1)),
        f_(std::move(f)),
        df_(std::move(df)),
        load_(std::move(load)),
        linear_(linear) {}
  /// As given to the constructor.
  bool is_linear() const override { return linear_; }
  /// f(u).
  void internal_force(const double* u, const double*, double* force) override {
    force[0] = f_(u[0]);
  }
  /// load(t), or zero.
  void external_force(double time, double* force) override { force[0] = load_ ? load_(time) : 0; }
  /// df(u); no damping.
  void tangent(const double* u, const double*, Eigen::MatrixXd& k, Eigen::MatrixXd&) override {
    k(0, 0) = df_(u[0]);
  }

 private:
  std::function<double(double)> f_, df_, load_;
  bool linear_;
};

/// f = k u, flagged linear unless \p flagged_linear is false (then solved by Newton).
inline ScalarSystem linear_spring(double k, bool flagged_linear = true) {
  return ScalarSystem([k](double u) { return k * u; }, [k](double) { return k; }, flagged_linear);
}

/// u_n of n steps of dt from (u0, v0), the acceleration from the equation of motion.
inline std::vector<double> history(SecondOrderSystem& system, NewmarkScheme scheme, double dt,
                                   int steps, double u0, double v0) {
  HhtIntegrator integrator(scheme, system);
  double u = u0, v = v0, a = 0;
  integrator.initialize(0.0, &u, &v, &a);
  std::vector<double> us{u};
  for (int n = 0; n < steps; ++n) {
    integrator.advance(n * dt, dt, &u, &v, &a);
    us.push_back(u);
  }
  return us;
}

}  // namespace hht_test
}  // namespace railfe
