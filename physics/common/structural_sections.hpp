#pragma once
/// \file
/// The deck's shared Sections section: what the structural blocks (beam2, spring2, point_mass)
/// are made of. Each named sublist gives one section: a beam (a material from Materials, a
/// cross-section shape or its properties, an orientation, a mass matrix), a spring–damper (six
/// stiffnesses and dampings in a local frame; on a one-node block it ties each node to the
/// ground) or a point mass (mass and rotary inertia); its Blocks say where it applies.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "physics/elements/beam_element.hpp"
#include "physics/elements/spring_damper.hpp"

namespace railfe {

class Model;

/// What a section describes.
enum class StructuralKind {
  beam,        ///< beam2 blocks
  spring,      ///< spring2 blocks (two nodes), or one-node blocks (a spring to the ground)
  point_mass,  ///< one-node blocks
};

/// Everything a beam element needs besides its nodes.
struct BeamProperties {
  std::string material_name;             ///< the Materials entry
  double poisson = 0;                    ///< ν of that material (shear areas of the shapes)
  BeamMaterial material;                 ///< E, G, ρ
  BeamSection section;                   ///< A, I, J, shear areas
  Eigen::Vector3d orientation{0, 0, 1};  ///< a vector in the local x–y plane (local y)
  BeamMass mass = BeamMass::consistent;  ///< consistent or lumped
  bool rotary_inertia = true;            ///< ρ I in the bending mass
};

/// A point mass on a 6-DOF node (global axes), its centre of mass at an offset from the node.
struct PointMassProperties {
  double mass = 0;                                    ///< kg
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< kg m², about the centre of mass
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();   ///< centre of mass from the node (m)
};

/// One entry of Sections.
struct StructuralSection {
  std::string name;                            ///< its sublist name
  StructuralKind kind = StructuralKind::beam;  ///< what it describes
  BeamProperties beam;                         ///< kind beam
  SpringDamper spring;                         ///< kind spring
  PointMassProperties point;                   ///< kind point_mass
};

/// Valid parameters of the Sections section.
ParameterSpec sections_parameters();

/// Whether \p type is one of the structural element types (beam2, spring2, point_mass).
bool is_structural_type(ElementType type);
/// Whether \p mesh has a block of a structural type (beam2, spring2, point_mass).
bool has_structural_blocks(const Mesh& mesh);
/// Whether \p mesh has a hex8 block.
bool has_solid_blocks(const Mesh& mesh);

/// Which section each structural block uses.
class SectionTable {
 public:
  /// Reads the validated \p sections (and the validated \p materials, which may be null when
  /// the deck has none) and maps their Blocks onto \p mesh. Throws InputError naming \p deck and
  /// the parameter for a block the mesh lacks, a block with two sections, a block of the wrong
  /// type, a missing material, a parameter the chosen shape needs and lacks, or section data
  /// the element refuses.
  SectionTable(const Teuchos::ParameterList& sections, const Teuchos::ParameterList* materials,
               const Mesh& mesh, const std::string& deck);

  /// Whether block \p block (index into Mesh::blocks) has a section.
  bool has_section(int block) const { return assignment_[block] >= 0; }
  /// The section of block \p block.
  const StructuralSection& of_block(int block) const { return sections_[assignment_[block]]; }
  /// All sections, in deck order.
  const std::vector<StructuralSection>& sections() const { return sections_; }
  /// Throws InputError naming \p deck unless every beam2, spring2 and point_mass block has a
  /// section.
  void require_structural_blocks(const Mesh& mesh, const std::string& deck) const;
  /// Builds every element once and turns what the element math refuses (coincident nodes, an
  /// orientation along the beam) into an InputError naming \p deck, the section, the block and
  /// the element (1-based, as ParaView numbers them).
  void check_elements(const Mesh& mesh, const std::string& deck) const;

 private:
  std::vector<StructuralSection> sections_;
  std::vector<int> assignment_;  // per block: index into sections_, or -1
};

/// The sections of a step on a model with structural blocks: reads the deck's Sections (and
/// Materials) of \p model, requires a section for every structural block and checks every
/// element. Throws InputError naming the deck (\p step describes the step in messages, e.g.
/// "the modal step 'modes'").
SectionTable structural_sections(const Model& model, const std::string& step);

/// Per node of \p mesh, six flags (u_x .. θ_z): 1 where no element of \p sections gives the
/// component mass (a node held by springs alone, a point mass without rotary inertia). Such
/// DOFs give no finite eigenvalue: a modal analysis does not count them as free.
std::vector<char> massless_components(const Mesh& mesh, const SectionTable& sections);

/// The beam element of two nodes at \p a and \p b with \p beam's properties.
BeamElement make_beam(const double* a, const double* b, const BeamProperties& beam);

}  // namespace railfe
