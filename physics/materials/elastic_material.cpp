#include "physics/materials/elastic_material.hpp"

#include "framework/app/model.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>

#include "framework/base/error.hpp"

namespace railfe {

ParameterSpec materials_parameters() {
  ParameterSpec material("An isotropic linear elastic material.");
  // From soft rubber to diamond: outside, the stiffness under- or overflows in double precision
  // long before the model means anything.
  material.required_real("Young's modulus", "Young's modulus E.", "Pa", Range::closed(1.0, 1e13));
  material.required_real("Poisson's ratio", "Poisson's ratio nu.", "", Range::open(-1.0, 0.5));
  // Up to 1e9 leaves room for explicit mass scaling (steel x 1e5).
  material.required_real("Density", "Mass density rho.", "kg/m^3", Range::open_closed(0, 1e9));
  material.text_array("Blocks", {},
                      "Solid element blocks made of this material (may be left out for a "
                      "material that only Sections name, for beams).");
  material.choice(
      "Element", "full integration",
      {{"full integration", "trilinear hex8, 2x2x2 Gauss points (locks in thin bending)"},
       {"enhanced strain",
        "hex8 with nine condensed enhanced-strain modes (Simo-Rifai): accurate in bending with "
        "one element through the thickness; statics and modal only"}},
      "Hex8 formulation of these blocks in statics and modal steps (the explicit module has its "
      "own, set in its Solid list).");
  // The section is itself the list of user-named materials.
  ParameterSpec section("Materials, one sublist each, under a name of your choice.");
  section.list()->set(kAnyName, *material.list(), material.doc());
  return section;
}

MaterialTable::MaterialTable(const Teuchos::ParameterList& materials, const Mesh& mesh,
                             const std::string& deck)
    : assignment_(mesh.blocks.size(), -1) {
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    const std::string name = materials.name(it);
    const auto& entry = materials.sublist(name);
    ElasticMaterial material{name, entry.get<double>("Young's modulus"),
                             entry.get<double>("Poisson's ratio"), entry.get<double>("Density")};
    if (entry.isParameter("Element") && entry.get<std::string>("Element") == "enhanced strain")
      material.element = SolidElement::enhanced_strain;
    const int index = static_cast<int>(materials_.size());
    materials_.push_back(material);
    for (const auto& block_name : entry.get<Teuchos::Array<std::string>>("Blocks")) {
      const std::string path = "Materials/" + name + "/Blocks";
      const int block = mesh.block_index(block_name, deck, path);
      if (assignment_[block] >= 0) {
        throw_input_error(deck, path,
                          "block '" + block_name + "' already has material '" +
                              materials_[assignment_[block]].name + "'",
                          "one material per block");
      }
      assignment_[block] = index;
    }
  }
}

void MaterialTable::require_solid_blocks(const Mesh& mesh, const std::string& deck,
                                         const std::string& path) const {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (mesh.blocks[b].type == ElementType::hex8 && assignment_[b] < 0) {
      throw_input_error(deck, path, "element block '" + mesh.blocks[b].name + "' has no material",
                        "list it under Blocks of one of the Materials");
    }
  }
}

MaterialTable solid_materials(const Model& model, const std::string& step,
                              EnhancedStrainSupport enhanced_strain) {
  const std::string& deck = model.deck().source;
  const Mesh& mesh = model.mesh();
  const bool solids = std::any_of(mesh.blocks.begin(), mesh.blocks.end(), [](const auto& block) {
    return block.type == ElementType::hex8;
  });
  if (!model.has_section("Materials") && !solids)  // beams, springs and masses alone
    return MaterialTable(Teuchos::ParameterList(), mesh, deck);
  if (!model.has_section("Materials")) {
    throw_input_error(deck, "Materials",
                      "missing: " + step + " needs a material for every solid block",
                      "a Materials section");
  }
  const Teuchos::ParameterList& section = model.section("Materials");
  if (enhanced_strain == EnhancedStrainSupport::refused) {
    for (auto it = section.begin(); it != section.end(); ++it) {
      const std::string name = section.name(it);
      const auto& entry = section.sublist(name);
      if (entry.isParameter("Element") && entry.get<std::string>("Element") != "full integration") {
        throw_input_error(deck, "Materials/" + name + "/Element",
                          "'" + entry.get<std::string>("Element") + "' is not available in " +
                              step + " (its module has its own hex8 kernel)",
                          "'full integration' (or leave Element out) for a material used by this "
                          "step; 'enhanced strain' works in statics and modal steps");
      }
    }
  }
  MaterialTable table(section, model.mesh(), deck);
  table.require_solid_blocks(model.mesh(), deck, "Materials");
  return table;
}

}  // namespace railfe
