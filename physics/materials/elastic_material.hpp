#pragma once
/// \file
/// Isotropic linear elastic materials and their assignment to element blocks: the deck's shared
/// Materials section, used by every module that has solids.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "physics/elements/hex8.hpp"

namespace railfe {

class Model;

/// The hex8 formulation of a material's blocks in the implicit modules (statics, modal).
enum class SolidElement {
  full_integration,  ///< trilinear, 2×2×2 Gauss points (hex8.hpp): locks in thin bending
  enhanced_strain,   ///< plus nine condensed strain modes (hex8_enhanced_strain.hpp)
};

/// Whether a module can use the enhanced-strain hex8 (the explicit module has its own kernel).
enum class EnhancedStrainSupport { refused, supported };

/// An isotropic linear elastic material.
struct ElasticMaterial {
  std::string name;    ///< the name of its sublist in Materials
  double young = 0;    ///< Young's modulus E (Pa)
  double poisson = 0;  ///< Poisson's ratio ν
  double density = 0;  ///< mass density ρ (kg/m³)
  /// the hex8 formulation of its blocks
  SolidElement element = SolidElement::full_integration;
  /// λ and μ.
  LameConstants lame() const { return lame_constants(young, poisson); }
};

/// Valid parameters of the Materials section.
ParameterSpec materials_parameters();

/// Which material each element block uses.
class MaterialTable {
 public:
  /// Reads the validated Materials section and maps its Blocks onto \p mesh. Throws InputError
  /// (naming \p deck) for a block the mesh lacks or a block given two materials.
  MaterialTable(const Teuchos::ParameterList& materials, const Mesh& mesh, const std::string& deck);

  /// Whether block \p block (index into Mesh::blocks) has a material.
  bool has_material(int block) const { return assignment_[block] >= 0; }
  /// The material of block \p block.
  const ElasticMaterial& of_block(int block) const { return materials_[assignment_[block]]; }
  /// Throws InputError naming \p deck and \p path unless every hex8 block has a material.
  void require_solid_blocks(const Mesh& mesh, const std::string& deck,
                            const std::string& path) const;

 private:
  std::vector<ElasticMaterial> materials_;
  std::vector<int> assignment_;  // per block: index into materials_, or -1
};

/// The materials of a step that needs one for every solid (hex8) block: reads the deck's
/// Materials section of \p model (an empty table when the deck has none and the mesh no solid
/// block). Throws InputError naming the deck when the section is missing
/// (\p step describes the step in the message, e.g. "the statics step 'load'"), a solid block
/// has no material, or a material asks for the enhanced-strain element and \p enhanced_strain
/// says the step's module cannot use it (a choice is refused rather than silently ignored).
MaterialTable solid_materials(
    const Model& model, const std::string& step,
    EnhancedStrainSupport enhanced_strain = EnhancedStrainSupport::refused);

}  // namespace railfe
