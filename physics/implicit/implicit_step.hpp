#pragma once
/// \file
/// One implicit dynamic step (see implicit_module.hpp).

#include <optional>

#include "framework/app/module.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/implicit/implicit_settings.hpp"
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
};

}  // namespace railfe
