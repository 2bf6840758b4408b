#include "framework/app/registry.hpp"

#include <stdexcept>

#include "framework/deck/parameter_rule.hpp"

namespace railfe {

void ModuleRegistry::add_module(ModuleDescriptor module) {
  if (find_module(module.name) != nullptr) {
    throw std::logic_error("railfe: module '" + module.name + "' registered twice");
  }
  modules_.push_back(std::move(module));
}

void ModuleRegistry::add_section(SectionDescriptor section) {
  sections_.push_back(std::move(section));
}

void ModuleRegistry::add_mesh_generator(MeshGeneratorDescriptor generator) {
  // The names taken so far: the framework's own types and the generators registered before. The
  // spec is kept in a named variable because the rule lives inside its parameter list.
  const ParameterSpec taken = mesh_parameters(generators_);
  const auto* types = rule_of(taken.list()->getEntry("Type"));
  for (const auto& choice : types->choices()) {
    if (choice.value == generator.name) {
      throw std::logic_error("railfe: mesh type '" + generator.name + "' registered twice");
    }
  }
  generators_.push_back(std::move(generator));
}

const ModuleDescriptor* ModuleRegistry::find_module(const std::string& name) const {
  for (const auto& module : modules_) {
    if (module.name == name)
      return &module;
  }
  return nullptr;
}

std::vector<std::string> ModuleRegistry::module_names() const {
  std::vector<std::string> names;
  for (const auto& module : modules_)
    names.push_back(module.name);
  return names;
}

}  // namespace railfe
