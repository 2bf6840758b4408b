// railfe-hht-study: where HHT-α with Newton iterations holds and where it fails on a stiffening
// contact. A 1 kg ball dropped 10 mm onto a 10 kg block on a 100 kN/m spring, Hertz contact
// F = k δ^{3/2} (k = 1e9 N/m^1.5, no tension), gravity; about a dozen impacts in 1 s, each ~1 ms.
// "impact-map OUT.csv" maps Δt × α: energy balance error, Newton iterations, cut-backs and the
// first step that did not converge, with 20 Newton iterations allowed per step and again with 5
// (regression/studies/hht_impact_stability.py). Δt may be halved 4 times.
// "impact-history OUT.csv" writes the energy and positions over time for a few (Δt, α), at most
// about 1000 rows a run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "framework/time/dense_system.hpp"
#include "framework/time/hht_integrator.hpp"
#include "framework/tools/study_main.hpp"

namespace railfe {
namespace {

constexpr double kBall = 1.0, kBlock = 10.0, kSpring = 1e5, kHertz = 1e9, kGravity = 9.81;
constexpr double kDrop = 0.01, kEndTime = 1.0;

// Unknowns (x_ball, x_block), upward, zero where the spring is free and the two just touch.
class BouncingBall : public DenseSecondOrderSystem {
 public:
  BouncingBall() : DenseSecondOrderSystem(Eigen::Vector2d(kBall, kBlock).asDiagonal()) {}
  static double overlap(const double* u) { return std::max(0.0, u[1] - u[0]); }
  static double contact_force(const double* u) { return kHertz * std::pow(overlap(u), 1.5); }
  void internal_force(const double* u, const double*, double* force) override {
    const double f = contact_force(u);
    force[0] = -f;
    force[1] = kSpring * u[1] + f;
  }
  void external_force(double, double* force) override {
    force[0] = -kBall * kGravity;
    force[1] = -kBlock * kGravity;
  }
  void tangent(const double* u, const double*, Eigen::MatrixXd& k, Eigen::MatrixXd&) override {
    const double s = 1.5 * kHertz * std::sqrt(overlap(u));
    k << s, -s, -s, kSpring + s;
  }
  // Kinetic, spring, contact and gravity energy (J).
  static double energy(const double* u, const double* v) {
    return 0.5 * (kBall * v[0] * v[0] + kBlock * v[1] * v[1] + kSpring * u[1] * u[1]) +
           0.4 * kHertz * std::pow(overlap(u), 2.5) + kGravity * (kBall * u[0] + kBlock * u[1]);
  }
};

struct Outcome {
  double max_gain = 0, max_loss = 0, final_error = 0;  // (E − E0) / (m g h)
  std::size_t iterations = 0, steps = 0, cut_backs = 0;
  int most_iterations = 0;
  double failed_at = -1, seconds = 0;
  std::string failure;
};

Outcome run(double alpha, double dt, int max_iterations, std::ostream* history = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  BouncingBall system;
  NewtonSettings newton;  // the defaults: 1e-8 relative on force and increment
  newton.max_iterations = max_iterations;
  CutBackSettings cut_back;
  cut_back.max_halvings = 4;
  HhtIntegrator integrator(NewmarkScheme::hht(alpha), system, newton, {}, cut_back);
  const double rest = -kBlock * kGravity / kSpring;
  double u[2] = {rest + kDrop, rest}, v[2] = {0, 0}, a[2];
  integrator.initialize(0, u, v, a);
  const double e0 = BouncingBall::energy(u, v), scale = kBall * kGravity * kDrop;
  Outcome out;
  const int steps = static_cast<int>(std::lround(kEndTime / dt));
  for (int n = 0; n < steps; ++n) {
    try {
      integrator.advance(n * dt, dt, u, v, a);
    } catch (const StepNotConverged& failure) {
      out.failed_at = failure.time;
      out.failure = failure.what();
      break;
    }
    out.most_iterations =
        std::max(out.most_iterations, integrator.newton_statistics().last_iterations);
    const double error = (BouncingBall::energy(u, v) - e0) / scale;
    out.max_gain = std::max(out.max_gain, error);
    out.max_loss = std::min(out.max_loss, error);
    out.final_error = error;
    if (history && (n + 1) % std::max(1, steps / 1000) == 0)
      *history << alpha << ',' << dt << ',' << (n + 1) * dt << ',' << error << ',' << u[0] << ','
               << u[1] << ',' << BouncingBall::contact_force(u) << '\n';
  }
  out.most_iterations = integrator.newton_statistics().most_iterations;
  out.iterations = integrator.newton_statistics().iterations;
  out.steps = integrator.newton_statistics().steps;
  out.cut_backs = integrator.n_cut_backs();
  out.seconds = seconds_since(start);
  return out;
}

const std::vector<double> kAlphas{0.0, -0.05, -0.1, -0.2, -0.3};

int impact_map(const std::string& path) {
  std::ofstream csv(path);
  csv << "max_iterations_allowed,alpha,dt_s,max_energy_gain,max_energy_loss,final_energy_error,"
         "newton_iterations,"
         "converged_steps,most_iterations,cut_backs,status,failed_at_s,seconds\n";
  for (int limit : {20, 5})
    for (int k = 0; k <= 14; ++k) {
      const double dt = 1e-5 * std::pow(10.0, k / 4.0);
      for (double alpha : kAlphas) {
        const Outcome o = run(alpha, dt, limit);
        const char* status = o.failed_at >= 0  ? "failed"
                             : o.cut_backs > 0 ? "cut back"
                                               : "converged";
        csv << limit << ',' << alpha << ',' << dt << ',' << o.max_gain << ',' << o.max_loss << ','
            << o.final_error << ',' << o.iterations << ',' << o.steps << ',' << o.most_iterations
            << ',' << o.cut_backs << ',' << status << ',' << o.failed_at << ',' << o.seconds
            << '\n';
        std::cerr << "limit " << limit << " alpha " << alpha << " dt " << dt << ": " << status
                  << ", energy " << o.final_error << (o.failure.empty() ? "" : "\n  " + o.failure)
                  << '\n';
      }
    }
  std::cout << "wrote " << path << '\n';
  return 0;
}

int impact_history(const std::string& path) {
  std::ofstream csv(path);
  csv << "alpha,dt_s,time_s,energy_error,x_ball_m,x_block_m,contact_force_N\n";
  for (double dt : {1e-4, 1e-3})
    for (double alpha : {0.0, -0.3})
      run(alpha, dt, 20, &csv);
  std::cout << "wrote " << path << '\n';
  return 0;
}

}  // namespace
}  // namespace railfe

int main(int argc, char** argv) {
  return railfe::run_study(
      argc, argv, "railfe-hht-study",
      {{"impact-map", railfe::impact_map}, {"impact-history", railfe::impact_history}});
}
