#pragma once
/// \file
/// One "wheelset dynamics" step (see wheelset_dynamics_module.hpp).

#include <memory>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "framework/app/module.hpp"

namespace railfe {

/// A wheelset running on rigid rails.
class WheelsetDynamicsStep : public AnalysisStep {
 public:
  /// Keeps the step's validated parameters.
  explicit WheelsetDynamicsStep(const Teuchos::ParameterList& parameters);
  /// Reads the profiles and checks the irregularities and the contact settings.
  void check(const CheckContext& context) override;
  /// Static balance, then the time integration; writes the histories, the contact events and
  /// the measurements (every rank computes, rank 0 writes).
  void run(StepContext& context) override;

 private:
  const Teuchos::ParameterList* parameters_;
  std::shared_ptr<WheelRailGeometry> geometry_;
};

}  // namespace railfe
