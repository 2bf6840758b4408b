#pragma once
/// \file
/// What the "wheelset dynamics" and "vehicle dynamics" steps share in their runs: the deck's
/// speed, step, Newton, irregularity and history parameters and their checks, the Newton
/// settings they give, a step that stops the run, reported, when Newton fails, and the Newton
/// figures of the summary.

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "framework/deck/parameter_spec.hpp"
#include "framework/output/run_summary.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"

namespace railfe {

/// Adds Speed, End time, Time step, Alpha (documented by \p alpha_doc, default −0.05), Newton
/// iterations, Newton tolerance, Line search, with \p newton_tangent Newton tangent (full or
/// modified Newton), and History interval to \p spec.
void add_time_stepping_parameters(ParameterSpec& spec, const std::string& alpha_doc,
                                  bool newton_tangent);

/// Adds Lateral irregularity and Vertical irregularity (functions of the track position) to
/// \p spec.
void add_irregularity_parameters(ParameterSpec& spec);

/// Throws InputError naming \p source and \p path (the step's) for an irregularity that is not
/// a valid expression or a Time step longer than End time.
void check_time_stepping_parameters(const Teuchos::ParameterList& step, const std::string& source,
                                    const std::string& path);

/// The Newton settings of the validated parameters of \p step.
NewtonSettings newton_settings(const Teuchos::ParameterList& step);

/// One step of \p integrator from \p time by \p dt; a step whose Newton iteration does not
/// converge becomes a RunError naming \p path, the step's time and the residuals (the run stops
/// rather than go on with an unbalanced state).
void step_or_stop(NewmarkIntegrator& integrator, double time, double dt, NewtonStepSolver& solver,
                  double* u, double* v, double* a, const std::string& path);

/// Adds the steps, Newton iterations per step, the most in a step and the wall time per Newton
/// iteration of \p statistics to \p summary under \p section.
void add_newton_summary(RunSummary& summary, const std::string& section,
                        const NewtonStatistics& statistics);

}  // namespace railfe
