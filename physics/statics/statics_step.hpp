#pragma once
/// \file
/// One linear static solve (see statics_module.hpp).

#include <optional>
#include <utility>
#include <vector>

#include "framework/app/module.hpp"
#include "physics/common/contact_settings.hpp"
#include "physics/common/rigid_links.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/elements/node_set_springs.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

class ContactPairs;
class DofMap;
class LinearConstraints;

/// A linear elastostatic step.
class StaticsStep : public AnalysisStep {
 public:
  /// A step configured by its validated parameter list.
  explicit StaticsStep(const Teuchos::ParameterList& parameters);
  void check(const CheckContext& context) override;
  void run(StepContext& context) override;

 private:
  void write_results(StepContext& context, const DofMap& dofs, const TpetraVector& u,
                     const TpetraVector& reactions, const ContactPairs* contact) const;
  void write_contact(StepContext& context, const ContactPairs& contact) const;
  void write_probes(StepContext& context, const DofMap& dofs, const TpetraVector& u,
                    const double* u_overlap) const;
  void write_springs(StepContext& context, const std::vector<std::array<double, 3>>& forces) const;

  const Teuchos::ParameterList* parameters_;
  SolidConditions conditions_;
  std::optional<MaterialTable> materials_;
  std::optional<SectionTable> sections_;  // a model of beams, springs and point masses
  int dofs_per_node_ = 3;                 // 6 for a structural model
  bool mixed_ = false;  // solids and structural elements: 3 or 6 DOFs per node (mesh_dofs())
  std::vector<RigidLink> links_;  // the mesh's rigid_link blocks and the Solid-beam ties
  std::string links_path_;        // where their errors point
  std::vector<std::vector<std::pair<GlobalIndex, GlobalIndex>>> tie_pairs_;
  std::vector<ContactPairSpec> contact_pairs_;
  std::vector<NodeSetSpring> springs_;
  double one_point_kappa_ = -1;  // ≥ 0: the one-point hex8 with this hourglass coefficient
};

}  // namespace railfe
