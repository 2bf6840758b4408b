#include "framework/app/registry.hpp"

#include <stdexcept>

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
