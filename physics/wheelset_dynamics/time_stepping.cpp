#include "physics/wheelset_dynamics/time_stepping.hpp"

#include <sstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"

namespace railfe {

void add_time_stepping_parameters(ParameterSpec& spec, const std::string& alpha_doc,
                                  bool newton_tangent) {
  spec.required_real("Speed", "Forward speed (creepages divide by it).", "m/s", Range::positive());
  spec.required_real("End time", "Simulated duration.", "s", Range::positive());
  spec.required_real("Time step", "Δt.", "s", Range::positive());
  spec.real("Alpha", -0.05, alpha_doc, "", Range::closed(-1.0 / 3.0, 0));
  spec.integer("Newton iterations", 25, "Corrections allowed per step.", Range::at_least(1));
  spec.real("Newton tolerance", 1e-6,
            "Converged when the residual is below this fraction of the step's force scale and the "
            "last correction below this fraction of the step's displacement. The creep forces "
            "are known to about this (forward-difference tangent, the creep-force table's "
            "interpolation, which is continuous but kinked between its a/b nodes).",
            "", Range::closed(1e-12, 1e-3));
  spec.flag("Line search", true,
            "Halve a Newton correction that raises the residual (saturated creep forces make "
            "full steps cycle); false: plain Newton.");
  if (newton_tangent)
    spec.choice("Newton tangent", "every iteration",
                {{"every iteration",
                  "full Newton: the tangent and its factorization anew at every iteration"},
                 {"once per step",
                  "modified Newton: the first iteration's matrix for the whole step (cheaper "
                  "iterations, usually more of them)"}},
                "How often Newton's matrix is formed.");
  spec.real("History interval", 0, "Time between rows of the histories (0: every step).", "s",
            Range::non_negative());
}

void add_irregularity_parameters(ParameterSpec& spec) {
  spec.text("Lateral irregularity", "",
            "Lateral offset of both rails (right positive) as a function of the track position s "
            "(write it with the variable x) ('' = none).");
  spec.text("Vertical irregularity", "",
            "Vertical offset of both rails (down positive) as a function of s (variable x) ('' = "
            "none).");
}

void check_time_stepping_parameters(const Teuchos::ParameterList& step, const std::string& source,
                                    const std::string& path) {
  for (const char* key : {"Lateral irregularity", "Vertical irregularity"})
    function_of_x(step.get<std::string>(key), source, path + "/" + key);
  if (step.get<double>("Time step") > step.get<double>("End time"))
    throw_input_error(source, path + "/Time step", "is longer than End time", "at most End time");
}

NewtonSettings newton_settings(const Teuchos::ParameterList& step) {
  NewtonSettings newton;
  newton.max_iterations = step.get<int>("Newton iterations");
  newton.line_search = step.get<bool>("Line search");
  newton.residual_relative = newton.increment_relative = step.get<double>("Newton tolerance");
  newton.tangent_once_per_step = step.isParameter("Newton tangent") &&
                                 step.get<std::string>("Newton tangent") == "once per step";
  return newton;
}

void step_or_stop(NewmarkIntegrator& integrator, double time, double dt, NewtonStepSolver& solver,
                  double* u, double* v, double* a, const std::string& path) {
  try {
    integrator.step(time, dt, solver, u, v, a);
  } catch (const StepNotConverged& error) {
    std::ostringstream message;
    message << path << ": Newton did not converge in the step from t = " << error.time << " s (Δt "
            << error.step << " s): " << error.what()
            << "; the run stops here rather than go on with an unbalanced state";
    throw RunError(message.str());
  }
}

void add_newton_summary(RunSummary& summary, const std::string& section,
                        const NewtonStatistics& statistics) {
  summary.add(section, "steps", static_cast<double>(statistics.steps));
  summary.add(section, "Newton iterations per step",
              statistics.steps ? double(statistics.iterations) / statistics.steps : 0.0);
  summary.add(section, "most Newton iterations in a step",
              static_cast<double>(statistics.most_iterations));
  summary.add(section, "wall time per Newton iteration (solve only)",
              statistics.iterations ? statistics.seconds / statistics.iterations : 0.0, "s");
}

}  // namespace railfe
