#pragma once
/// \file
/// One modal analysis (see modal_module.hpp).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/app/module.hpp"
#include "physics/common/rigid_links.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/elements/node_set_springs.hpp"
#include "physics/materials/elastic_material.hpp"
#include "physics/modal/mode_checks.hpp"
#include "physics/modal/mode_classifier.hpp"

namespace railfe {

class FeMatrix;

/// A fixed node set of a modal step.
struct ModalSupport {
  std::string name;             ///< its name in the deck
  std::string node_set;         ///< the nodes
  std::vector<int> components;  ///< fixed components (0 = x, 1 = y, 2 = z; 3..5 rotations)
};

/// A reference frequency to compare a computed mode with.
struct ReferenceMode {
  std::string name;         ///< its name in the deck
  std::string family;       ///< axial, radial or circumferential
  int nodal_circles = 0;    ///< m
  int nodal_diameters = 0;  ///< n
  double frequency = 0;     ///< Hz
};

/// Everything known about one returned mode, for the output files.
struct ModeRecord {
  double eigenvalue = 0;  ///< λ = ω² (rad²/s²)
  double frequency = 0;   ///< sign(λ) √|λ| / 2π (Hz); 0 for rigid-body modes
  ModeCheck check;        ///< residual, orthogonality, masses, partner
  ModeClass shape;        ///< classification (family "" when not classified)
  std::string status;     ///< "ok", or what failed
  bool rigid = false;     ///< below the rigid-body limit
};

/// A modal analysis step.
class ModalStep : public AnalysisStep {
 public:
  /// A step configured by its validated parameter list.
  explicit ModalStep(const Teuchos::ParameterList& parameters);
  void check(const CheckContext& context) override;
  void run(StepContext& context) override;

 private:
  // The DOFs the step computes on: the model's, or those of the Blocks' own partition (made on
  // first use, collective).
  const DofMap& step_dofs(Model& model);
  // Reads Sections for a model of beams, springs and point masses (6 DOFs per node).
  void check_structural(const CheckContext& context);
  // Reads Blocks and Supports; returns the nodes that carry unknowns.
  std::vector<char> check_blocks_and_supports(const CheckContext& context);
  // Reads Springs; refuses a node set with nodes outside the Blocks (\p kept names them).
  void check_springs(const CheckContext& context, const std::vector<char>& active,
                     const std::string& kept);
  // The assembled stiffness with the Springs added (the matrix itself where there are none).
  Teuchos::RCP<TpetraMatrix> with_springs(FeMatrix& stiffness, const DofMap& dofs,
                                          const StepContext& context);
  // Modes of the first eigensolver batch: Modes, or its automatic value.
  int first_batch(long long free_dofs) const;
  void classify(const DofMap& dofs, const TpetraMultiVector& modes,
                std::vector<ModeRecord>& records) const;
  void write_results(StepContext& context, const DofMap& dofs,
                     const std::vector<ModeRecord>& records, const TpetraMultiVector* modes) const;
  void write_validation(StepContext& context, const std::vector<ModeRecord>& records) const;
  static void export_matrices(StepContext& context, const TpetraMatrix& K, const TpetraMatrix& M);
  void draw_chart(StepContext& context, const std::string& csv_path) const;

  const Teuchos::ParameterList* parameters_;
  std::optional<MaterialTable> materials_;
  std::optional<SectionTable> sections_;  // a model of beams, springs and point masses
  int dofs_per_node_ = 3;                 // 6 for a structural model, 0 for a mixed one
  bool mixed_ = false;  // solids and structural elements: 3 or 6 DOFs per node (mesh_dofs())
  std::vector<RigidLink> links_;  // the mesh's rigid_link blocks and the Solid-beam ties
  std::string links_path_;        // where their errors point
  std::vector<ModalSupport> supports_;
  std::vector<NodeSetSpring> springs_;    // Springs (pairs indexed on the step's partition)
  std::vector<std::string> block_names_;  // Blocks (empty = the whole mesh)
  std::unique_ptr<Mesh> block_mesh_;      // the mesh of Blocks, if given
  std::unique_ptr<MeshPartition> block_partition_;  // its partition
  std::unique_ptr<DofMap> block_dofs_;              // its DOFs
  std::vector<ReferenceMode> references_;
  AxisymmetricFrame frame_;
  ClassifierSettings classifier_;
  bool classify_ = false;
  long long free_dofs_ = 0;      // DOFs not fixed by a support that carry mass
  long long massless_dofs_ = 0;  // free DOFs that carry no mass (springs alone): no eigenvalue
};

}  // namespace railfe
