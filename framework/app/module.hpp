#pragma once
/// \file
/// How physics plugs into the framework. A module (statics, explicit, implicit, modal...)
/// declares the parameters of a step that uses it and builds AnalysisSteps from them. A deck
/// lists its steps under Steps/<name>, each naming its module; the framework validates each step
/// with its module's spec, lets every step check itself against the mesh before anything runs,
/// then runs the steps in deck order on one shared Model.
///
/// Time-dependent modules share one second-order integrator family (framework/time): explicit
/// central difference is Newmark(β = 0, γ = ½) with a lumped mass and no global matrix; implicit
/// HHT-α assembles with FeMatrix and solves Newton steps with the solver layer (Lagrange
/// multipliers for contact constraints enter as extra unknowns); eigen-solves assemble K and M.

#include <functional>
#include <memory>
#include <string>

#include "framework/app/model.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/output/output_directory.hpp"
#include "framework/output/progress.hpp"
#include "framework/output/run_summary.hpp"

namespace railfe {

/// What a step may use when it checks itself against the mesh, before anything runs.
struct CheckContext {
  const Model& model;            ///< mesh, partition, sections
  const std::string& step_name;  ///< the name under Steps/
  const std::string& path;       ///< "Steps/<name>", for messages
  /// The deck's file name, for messages.
  const std::string& source() const { return model.deck().source; }
};

/// What a running step may use.
struct StepContext {
  Model& model;                              ///< mesh, partition, sections, shared fields
  const std::string& step_name;              ///< the name under Steps/
  const std::string& path;                   ///< "Steps/<name>", for messages
  const Teuchos::ParameterList& parameters;  ///< the step's validated list
  OutputDirectory& output;                   ///< where files go (write to staging paths)
  RunSummary& summary;                       ///< what to report at the end
  bool quiet;                                ///< suppress progress lines
  double progress_interval;                  ///< seconds between progress lines
  /// The deck's file name, for messages.
  const std::string& source() const { return model.deck().source; }
  /// A progress reporter for a phase of \p total work units, printed by rank 0 as
  /// "[<step>: <label>] 42% done ..." (nothing when quiet).
  Progress progress(const std::string& label, double total) const {
    return Progress(step_name + ": " + label, total, model.comm(), quiet, progress_interval);
  }
  /// A progress reporter for iterations that stop when they converge, at most \p most:
  /// "[<step>: <label>] 3 done (at most 30), 41.2 s elapsed, 13.7 s each".
  Progress iteration_progress(const std::string& label, int most) const {
    return Progress(step_name + ": " + label, most, model.comm(), quiet, progress_interval, true);
  }
};

/// One step of an analysis.
class AnalysisStep {
 public:
  virtual ~AnalysisStep() = default;
  /// Checks everything that depends on the mesh (set and block names, materials) and throws
  /// InputError; called for every step before the first one runs and before the results
  /// directory is touched, so a bad deck fails in seconds and writes nothing. Must give the same
  /// verdict on every rank.
  virtual void check(const CheckContext& context) = 0;
  /// Runs the step (collective). Throws RunError when the computation fails.
  virtual void run(StepContext& context) = 0;
};

/// A physics module as the registry knows it.
struct ModuleDescriptor {
  std::string name;     ///< the value of Steps/<step>/Module
  std::string summary;  ///< one line for --describe
  /// The valid parameters of a step that uses the module ("Module" itself is added by the
  /// framework).
  std::function<ParameterSpec()> parameters;
  /// Builds a step from its validated parameter list.
  std::function<std::unique_ptr<AnalysisStep>(const Teuchos::ParameterList&)> create;
  /// Whether its steps work on the mesh (a deck without a Mesh section is refused for them).
  bool needs_mesh = true;
};

/// A top-level deck section owned by physics code shared between modules (e.g. Materials).
struct SectionDescriptor {
  std::string name;                           ///< the sublist name at the top of the deck
  std::string summary;                        ///< one line for --describe
  bool required = false;                      ///< whether every deck must have it
  std::function<ParameterSpec()> parameters;  ///< its valid parameters
};

}  // namespace railfe
