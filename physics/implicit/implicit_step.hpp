#pragma once
/// \file
/// One implicit dynamic step (see implicit_module.hpp).

#include <optional>

#include "framework/app/module.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/implicit/implicit_settings.hpp"
#include "physics/implicit/moving_contact_settings.hpp"
#include "physics/implicit/moving_loads.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

/// An implicit dynamic step.
class ImplicitStep : public AnalysisStep {
 public:
  /// A step configured by its validated parameter list.
  explicit ImplicitStep(const Teuchos::ParameterList& parameters);
  void check(const CheckContext& context) override;
  void run(StepContext& context) override;

 private:
  const Teuchos::ParameterList* parameters_;
  ImplicitSettings settings_;
  SolidConditions conditions_;
  std::optional<MaterialTable> materials_;
  std::optional<SectionTable> sections_;  // for a model of beams, springs and point masses
  int dofs_per_node_ = 3;
  std::vector<MovingLoadSpec> moving_loads_;
  std::vector<MovingContactSpec> contacts_;
};

}  // namespace railfe
