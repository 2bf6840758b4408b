// The one place where physics modules and shared sections are named. Adding a module: a new
// folder under physics/ and one line here.
#include "framework/app/registry.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/contact_geometry/wheelset_on_track_module.hpp"
#include "physics/contact_patch/contact_patch_module.hpp"
#include "physics/explicit/explicit_module.hpp"
#include "physics/implicit/implicit_module.hpp"
#include "physics/materials/elastic_material.hpp"
#include "physics/modal/modal_module.hpp"
#include "physics/parts/line_mesh.hpp"
#include "physics/parts/rail_mesh.hpp"
#include "physics/parts/vehicle_mesh.hpp"
#include "physics/parts/wheel_mesh.hpp"
#include "physics/statics/statics_module.hpp"
#include "physics/wheelset_dynamics/vehicle_dynamics_module.hpp"
#include "physics/wheelset_dynamics/wheelset_dynamics_module.hpp"

namespace railfe {

void register_physics(ModuleRegistry& registry) {
  registry.add_section({"Materials", "Isotropic linear elastic materials of the solid blocks.",
                        false, materials_parameters});
  registry.add_section({"Sections",
                        "Sections of the beam, spring-damper and point-mass blocks (beam2, "
                        "spring2, point_mass).",
                        false, sections_parameters});
  registry.add_module(statics_module());
  registry.add_module(modal_module());
  registry.add_module(explicit_module());
  registry.add_module(implicit_module());
  registry.add_module(wheelset_on_track_module());
  registry.add_module(contact_patch_module());
  registry.add_module(wheelset_dynamics_module());
  registry.add_module(vehicle_dynamics_module());
  registry.add_mesh_generator(wheel_mesh_generator());
  registry.add_mesh_generator(rail_mesh_generator());
  registry.add_mesh_generator(line_mesh_generator());
  registry.add_mesh_generator(vehicle_mesh_generator());
}

}  // namespace railfe
