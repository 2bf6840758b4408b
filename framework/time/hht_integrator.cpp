#include "framework/time/hht_integrator.hpp"

#include <cstdio>

namespace railfe {

HhtIntegrator::HhtIntegrator(NewmarkScheme scheme, SecondOrderSystem& system, NewtonSettings newton,
                             RayleighDamping rayleigh, CutBackSettings cut_back)
    : solver_(system, newton, rayleigh),
      integrator_(scheme, system.n_unknowns()),
      cut_back_(cut_back) {}

void HhtIntegrator::initialize(double time, const double* u, const double* v, double* a) {
  solver_.initial_acceleration(time, u, v, a);
}

int HhtIntegrator::advance(double time, double dt, double* u, double* v, double* a) {
  // Progress counted exactly: `done` sub-steps of dt / 2^level.
  int level = 0, sub_steps = 0;
  long long done = 0;
  while (done < (1LL << level)) {
    const double scale = 1.0 / static_cast<double>(1LL << level);
    const double start = time + dt * static_cast<double>(done) * scale, step = dt * scale;
    try {
      integrator_.step(start, step, solver_, u, v, a);
      solver_.after_step(start + step, u, v, a);  // an impact's consistent restart, if any
    } catch (const StepNotConverged& failure) {
      if (level == cut_back_.max_halvings) {
        char limit[160];
        std::snprintf(limit, sizeof limit, "; gave up after %d halvings of dt = %.6g s", level, dt);
        throw StepNotConverged(failure.what() + std::string(limit), failure.time, failure.step,
                               failure.residuals);
      }
      ++level;
      done *= 2;
      ++n_cut_backs_;
      if (report_)
        report_({start, step, step / 2, failure.residuals, failure.what()});
      continue;
    }
    ++done;
    ++sub_steps;
    if (level > 0 && done % 2 == 0) {
      --level;
      done /= 2;
    }
  }
  return sub_steps;
}

}  // namespace railfe
