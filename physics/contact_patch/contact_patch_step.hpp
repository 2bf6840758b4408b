#pragma once
/// \file
/// One "contact patch" step (see contact_patch_module.hpp).

#include <array>
#include <string>
#include <vector>

#include "contact/laws/kalker_linear.hpp"
#include "contact/laws/normal_problem.hpp"
#include "framework/app/module.hpp"

namespace railfe {

/// Contact patch under several theories.
class ContactPatchStep : public AnalysisStep {
 public:
  /// Keeps the step's validated parameters.
  explicit ContactPatchStep(const Teuchos::ParameterList& parameters);
  /// Checks the theory names, the creepage (or force) arrays, that prescribed forces stay below
  /// the traction bound, and that Hertz and Kalker's table apply (Geometry separation: reads the
  /// Separation file, and only the exact solver may run).
  void check(const CheckContext& context) override;
  /// Evaluates every case under every theory and writes the files.
  void run(StepContext& context) override;

 private:
  const Teuchos::ParameterList* parameters_;
  std::vector<std::string> theories_;
  std::vector<Creepages> cases_;               // per case; found at run time from forces_
  std::vector<std::array<double, 2>> forces_;  // Prescribe forces: Fx, Fy per case (N)
  LateralSeparation lateral_;                  // Geometry separation: the Separation file
};

}  // namespace railfe
