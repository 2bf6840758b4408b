#include "physics/explicit/explicit_module.hpp"

#include "physics/explicit/explicit_settings.hpp"
#include "physics/explicit/explicit_step.hpp"

namespace railfe {

ModuleDescriptor explicit_module() {
  ModuleDescriptor module;
  module.name = "explicit";
  module.summary =
      "explicit dynamics: central difference on hex8 solids, rigid bodies, masses and springs";
  module.parameters = explicit_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<ExplicitStep>(parameters);
  };
  return module;
}

}  // namespace railfe
