#pragma once
/// \file
/// One "vehicle dynamics" step (see vehicle_dynamics_module.hpp).

#include <memory>
#include <optional>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "framework/app/module.hpp"
#include "physics/common/dense_structural_model.hpp"
#include "physics/wheelset_dynamics/rail_beams.hpp"
#include "physics/wheelset_dynamics/vehicle_sweep.hpp"
#include "physics/wheelset_dynamics/wheelset_contacts.hpp"

namespace railfe {

/// A vehicle running on rigid rails or over girders, once or as a sweep of cases.
class VehicleDynamicsStep : public AnalysisStep {
 public:
  /// Keeps the step's validated parameters.
  explicit VehicleDynamicsStep(const Teuchos::ParameterList& parameters);
  /// Reads the profiles, builds the vehicle's matrices and checks the wheelset nodes, the
  /// measuring points and the irregularities.
  void check(const CheckContext& context) override;
  /// Static balance, then the time integration; writes the histories and contact events (every
  /// rank computes, rank 0 writes). With a Sweep, each case on one rank (vehicle_sweep.hpp).
  void run(StepContext& context) override;

 private:
  // One run of case \p c under the name and summary of \p context; files written where
  // \p writes. \p alone: a run of its own, whose Newton failure throws and which draws its
  // chart; otherwise (a sweep's case) the failure is returned.
  CaseOutcome run_case(StepContext& context, const VehicleCase& c, bool writes, bool alone);
  // Writes <step>_static.csv and the summary's static loads; \p loads gets each wheel's Q.
  void write_static_loads(StepContext& context, const std::string& section,
                          const std::vector<std::array<ContactState, n_wheelset_contacts>>& states,
                          std::vector<std::array<double, 2>>& loads, bool writes) const;

  const Teuchos::ParameterList* parameters_;
  std::shared_ptr<WheelRailGeometry> geometry_;
  std::unique_ptr<DenseStructuralModel> model_;
  std::vector<GlobalIndex> wheelsets_;  // front to rear
  std::vector<GlobalIndex> points_;     // measuring points
  std::vector<std::string> point_names_;
  std::optional<GirderLayout> girders_;  // Structure/Model girders
  std::vector<VehicleCase> cases_;       // the sweep's; empty: one run
};

}  // namespace railfe
