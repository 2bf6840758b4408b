#include "physics/implicit/implicit_module.hpp"

#include "framework/solvers/linear_solver.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/implicit/implicit_settings.hpp"
#include "physics/implicit/implicit_step.hpp"
#include "physics/implicit/moving_contact_settings.hpp"
#include "physics/implicit/moving_loads.hpp"

namespace railfe {

namespace {

ParameterSpec implicit_parameters() {
  ParameterSpec spec(
      "Implicit structural dynamics: HHT-alpha or Newmark with Newton iterations on "
      "M a + C v + K u = f(t).");
  add_solid_condition_parameters(spec);
  add_implicit_parameters(spec);
  add_moving_load_parameters(spec);
  add_moving_contact_parameters(spec);
  spec.sublist("Linear solver", linear_solver_parameters("cholmod"),
               "How each Newton correction is solved (the matrix is factored once per step size "
               "for a linear model).");
  return spec;
}

}  // namespace

ModuleDescriptor implicit_module() {
  ModuleDescriptor module;
  module.name = "implicit";
  module.summary = "implicit dynamics: HHT-alpha / Newmark with Newton iterations";
  module.parameters = implicit_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<ImplicitStep>(parameters);
  };
  return module;
}

}  // namespace railfe
