#include "physics/statics/statics_module.hpp"

#include "framework/solvers/linear_solver.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/statics/statics_step.hpp"

namespace railfe {

namespace {

ParameterSpec statics_parameters() {
  ParameterSpec spec("Linear elastostatics of hex8 solids.");
  add_solid_condition_parameters(spec);
  spec.sublist("Linear solver", linear_solver_parameters(), "How K u = f is solved.");
  return spec;
}

}  // namespace

ModuleDescriptor statics_module() {
  ModuleDescriptor module;
  module.name = "statics";
  module.summary = "linear elastostatics: displacements, stresses and reactions under static loads";
  module.parameters = statics_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<StaticsStep>(parameters);
  };
  return module;
}

}  // namespace railfe
