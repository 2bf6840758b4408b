#pragma once
/// \file
/// One "wheelset on track" step (see wheelset_on_track_module.hpp).

#include <memory>
#include <string>
#include <vector>

#include "contact/geometry/wheel_rail_geometry.hpp"

#include "framework/app/module.hpp"

namespace railfe {

/// A pose of the deck's Poses list.
struct DeckPose {
  std::string name;   ///< its name in the deck
  WheelsetPose pose;  ///< lateral and yaw; vertical and roll when not rigid
  bool rigid = true;  ///< vertical and roll solved so both wheels touch
};

/// Contact geometry of one wheelset on one track.
class WheelsetOnTrackStep : public AnalysisStep {
 public:
  /// Keeps the step's validated parameters.
  explicit WheelsetOnTrackStep(const Teuchos::ParameterList& parameters);
  /// Reads and checks the profiles and places them (errors name the file and the point).
  void check(const CheckContext& context) override;
  /// Searches every pose, builds the table, computes the conicity and writes the files.
  void run(StepContext& context) override;

 private:
  /// Solves every pose elastically under \p load (N per wheelset) and writes
  /// elastic_contacts.csv (one row per patch) and elastic_poses.csv (balances per pose).
  void write_elastic_contacts(StepContext& context, double load);

  const Teuchos::ParameterList* parameters_;
  std::shared_ptr<WheelRailGeometry> geometry_;
  std::vector<DeckPose> poses_;
};

}  // namespace railfe
