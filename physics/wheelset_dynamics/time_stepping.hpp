#pragma once
/// \file
/// What the "wheelset dynamics" and "vehicle dynamics" steps share in their time stepping: the
/// deck's speed, step and Newton parameters, the Newton settings they give, and a step that
/// stops the run, reported, when Newton fails.

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "framework/deck/parameter_spec.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"

namespace railfe {

/// Adds Speed, End time, Time step, Alpha (documented by \p alpha_doc, default −0.05), Newton
/// iterations, Newton tolerance, Line search and, with \p newton_tangent, Newton tangent (full or
/// modified Newton) to \p spec.
void add_time_stepping_parameters(ParameterSpec& spec, const std::string& alpha_doc,
                                  bool newton_tangent);

/// The Newton settings of the validated parameters of \p step.
NewtonSettings newton_settings(const Teuchos::ParameterList& step);

/// One step of \p integrator from \p time by \p dt; a step whose Newton iteration does not
/// converge becomes a RunError naming \p path, the step's time and the residuals (the run stops
/// rather than go on with an unbalanced state).
void step_or_stop(NewmarkIntegrator& integrator, double time, double dt, NewtonStepSolver& solver,
                  double* u, double* v, double* a, const std::string& path);

}  // namespace railfe
