#pragma once
/// \file
/// What an explicit step writes: <step>_energy.csv (the energy balance), <step>_histories.csv
/// (node-set means and element stresses), <step>_measurements.csv (arrival, peak and period of
/// each history, measured from every step), <step>_wave_speeds.csv and <step>.exo snapshots.
/// Rows already written are kept (rank 0) so that a run resumed from a checkpoint rewrites
/// complete files.

#include <memory>
#include <string>
#include <vector>

#include "framework/base/types.hpp"
#include "framework/output/history_events.hpp"
#include "physics/explicit/explicit_settings.hpp"

namespace railfe {

class ContactRecorder;
class CsvWriter;
class ExodusWriter;
class ExplicitSolver;
class MeshPartition;
class OutputDirectory;
struct EnergyBalance;

/// Writes the outputs of one explicit step.
class ExplicitRecorder {
 public:
  /// Opens the files of step \p step_name in \p output (collective); \p title names the Exodus
  /// file.
  ExplicitRecorder(const ExplicitSettings& settings, const ExplicitSolver& solver,
                   const MeshPartition& partition, OutputDirectory& output,
                   const std::string& step_name, const std::string& title, bool write_exodus);
  ~ExplicitRecorder();
  /// Samples histories at the solver's current state and writes the rows that are due
  /// (collective). Returns false, writing nothing, when a value is not finite or the run blows
  /// up: the energy error exceeds its limit and the stored and dissipated energy has grown past
  /// the growth limit times the energy put in, or the error exceeds its limit at a step above the
  /// stable limit (the run must stop).
  bool record(bool force_rows);
  /// The energy balance at the last energy row.
  const EnergyBalance& last_balance() const;
  /// Stored and dissipated energy over the energy put in (initial energy and work of the loads),
  /// last row: about 1 while the balance holds.
  double energy_growth() const { return growth_; }
  /// The energy put in: initial energy plus the largest |work of the loads| so far (J).
  double energy_put_in() const { return energy_put_in_; }
  /// Whether the last judged step was above the stable limit (then the error alone fails).
  bool beyond_stable_step() const { return beyond_stable_step_; }
  /// Writes an Exodus snapshot if one is due at the current time (collective); \p last forces it.
  void snapshot(bool last);
  /// Writes the measurements and wave speeds and closes every file (collective).
  void finish();
  /// The contact outputs.
  const ContactRecorder& contact() const { return *contact_; }
  /// What a checkpoint must hold to resume the files (rank 0's rows and every rank's events).
  std::vector<double> state() const;
  /// Restores state() and rewrites the rows so far (collective).
  void restore(const std::vector<double>& values);

 private:
  void write_energy_row();
  void write_history_row();
  std::vector<double> element_stresses() const;

  const ExplicitSettings& settings_;
  const ExplicitSolver& solver_;
  const MeshPartition& partition_;
  std::vector<std::vector<LocalIndex>> history_nodes_;
  std::vector<double> history_counts_;
  std::vector<LocalIndex> element_rows_;  // kernel index of each element history, or −1
  std::vector<HistoryEvents> events_;
  std::unique_ptr<CsvWriter> energy_, histories_;
  std::unique_ptr<ExodusWriter> exodus_;
  std::unique_ptr<ContactRecorder> contact_;
  std::string measurements_path_, wave_speeds_path_;
  std::vector<std::vector<double>> energy_rows_, history_rows_;
  std::unique_ptr<EnergyBalance> balance_;
  double next_snapshot_ = 0;
  double energy_put_in_ = 0;  // initial energy + largest |work of the loads| so far
  bool beyond_stable_step_ = false;
  double growth_ = 0;  // stored + dissipated energy / energy_put_in_ at the last energy row
  long long last_energy_step_ = -1, last_history_step_ = -1;
  bool root_;
};

}  // namespace railfe
