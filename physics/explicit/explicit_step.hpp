#pragma once
/// \file
/// One explicit dynamics step (see explicit_module.hpp): checks, the time loop, checkpoints.

#include <optional>

#include "framework/app/module.hpp"
#include "physics/explicit/explicit_settings.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

/// An explicit dynamics step.
class ExplicitStep : public AnalysisStep {
 public:
  /// A step configured by its validated parameter list.
  explicit ExplicitStep(const Teuchos::ParameterList& parameters);
  void check(const CheckContext& context) override;
  void run(StepContext& context) override;

 private:
  const Teuchos::ParameterList* parameters_;
  std::optional<ExplicitSettings> settings_;
  std::optional<MaterialTable> materials_;
  double estimated_hours_ = 0;  // lower estimate of the run's wall time, from check()
};

}  // namespace railfe
