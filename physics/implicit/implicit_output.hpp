#pragma once
/// \file
/// What an implicit step writes: <step>_histories.csv (node-set means), <step>_measurements.csv
/// (peak and period of each history), <step>_energy.csv (the energy balance), <step>_newton.csv
/// (iterations and cut-backs per step) and <step>.exo snapshots. Every value is checked finite
/// before it is written: a non-finite one stops the run (exit status 2) instead of reaching a
/// file.

#include <memory>
#include <string>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/output/output_directory.hpp"
#include "physics/implicit/implicit_settings.hpp"

namespace railfe {

class CsvWriter;
class ExodusWriter;

/// The state handed to the recorder (owned DOFs of this rank).
struct ImplicitState {
  double time = 0;            ///< t (s)
  const double* u = nullptr;  ///< displacement
  const double* v = nullptr;  ///< velocity
  const double* a = nullptr;  ///< acceleration
};

/// The energy balance at one time (J, summed over ranks).
struct ImplicitEnergy {
  double kinetic = 0;        ///< ½ vᵀ M v
  double strain = 0;         ///< ½ uᵀ K u
  double external_work = 0;  ///< ∫ f_ext · du since the start (trapezoidal)
  double damping_work = 0;   ///< ∫ (C v) · du since the start (trapezoidal), dissipated
  double initial = 0;        ///< kinetic + strain at the start
  /// initial + external work − kinetic − strain − damping work: the numerical dissipation of
  /// the scheme (zero for the average-acceleration rule on a linear model, to round-off).
  double balance() const { return initial + external_work - kinetic - strain - damping_work; }
};

/// Writes the outputs of one implicit step.
class ImplicitRecorder {
 public:
  /// Opens the files of step \p step_name (collective); \p title names the Exodus file.
  ImplicitRecorder(const ImplicitSettings& settings, const DofMap& dofs, OutputDirectory& output,
                   const std::string& step_name, const std::string& title, bool exodus);
  ~ImplicitRecorder();

  /// Samples the histories at \p state and writes a row when \p write_row (collective). Throws
  /// RunError naming the history and the time when a value is not finite.
  void sample(const ImplicitState& state, bool write_row);
  /// Writes an energy row (rank 0), RunError when not finite.
  void write_energy(double time, const ImplicitEnergy& energy);
  /// Writes a Newton row: step number, time reached, Δt, sub-steps, corrections, and the first
  /// and last ‖R‖ of \p residuals (the last sub-step's; a linear model takes one exact solve,
  /// checked by the solver's backward error, so its residual is only evaluated before it).
  void write_newton(long step, double time, double dt, int substeps, int iterations,
                    const std::vector<double>& residuals);
  /// Writes an Exodus snapshot when one is due at \p state.time; \p last forces it (collective).
  void snapshot(const ImplicitState& state, bool last);
  /// Writes the measurements and closes the files (collective).
  void finish();

 private:
  struct History;
  const ImplicitSettings& settings_;
  const DofMap& dofs_;
  bool root_;
  std::vector<History> histories_;
  std::unique_ptr<CsvWriter> history_file_, energy_file_, newton_file_;
  std::unique_ptr<ExodusWriter> exodus_;
  std::string measurements_path_;
  double next_snapshot_ = 0;
  int exodus_width_ = 9;  // nodal fields per node in the Exodus file
};

}  // namespace railfe
