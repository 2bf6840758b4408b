#pragma once
/// \file
/// The module registry. The framework never names a module: physics/register_physics.cpp adds
/// every module, shared section and mesh generator in one place, and the executable calls it
/// once.

#include <string>
#include <vector>

#include "framework/app/module.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

/// Known modules, sections and mesh generators.
class ModuleRegistry {
 public:
  /// Registers \p module; a second module of the same name is a programming error.
  void add_module(ModuleDescriptor module);
  /// Registers a shared top-level section.
  void add_section(SectionDescriptor section);
  /// Registers a mesh generator (Mesh/Type <name>, sublist Mesh/<Name>); a name that is taken,
  /// by the framework's own types or another generator, is a programming error.
  void add_mesh_generator(MeshGeneratorDescriptor generator);
  /// The module called \p name, or nullptr.
  const ModuleDescriptor* find_module(const std::string& name) const;
  /// All modules in registration order.
  const std::vector<ModuleDescriptor>& modules() const { return modules_; }
  /// All sections in registration order.
  const std::vector<SectionDescriptor>& sections() const { return sections_; }
  /// All mesh generators in registration order.
  const std::vector<MeshGeneratorDescriptor>& mesh_generators() const { return generators_; }
  /// Names of all modules.
  std::vector<std::string> module_names() const;

 private:
  std::vector<ModuleDescriptor> modules_;
  std::vector<SectionDescriptor> sections_;
  std::vector<MeshGeneratorDescriptor> generators_;
};

/// Adds every physics module, shared section and mesh generator. Defined by the physics layer
/// (physics/register_physics.cpp): the single place where modules are named.
void register_physics(ModuleRegistry& registry);

}  // namespace railfe
