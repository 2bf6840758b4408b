#pragma once
/// \file
/// What the contact pairs of an explicit step write: per pair a history
/// <step>_contact_<pair>.csv (normal and tangential force in the contact frame, friction bound,
/// area, active and slipping nodes, penetration, frictional work) every history interval, and at
/// the deck's Patch times the patch fields <step>_contact_<pair>_patch_<k>.csv (per active slave
/// node: position, pressure, shear traction, slip velocity, stick or slip). The contact frame is
/// n (the force-weighted mean normal, master towards slave), t1 (Longitudinal direction projected
/// onto the contact plane) and t2 = n x t1. Rank 0 writes; every rank holds the same contact.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "physics/common/penalty_flexibility.hpp"

namespace railfe {

class CsvWriter;
class ExplicitSolver;
class OutputDirectory;
class RunSummary;
struct ExplicitSettings;

/// Penalty flexibility ratio above which a run warns (about this fraction of the creep force
/// lost where the patch sticks).
constexpr double kFlexibilityWarning = 0.05;

/// The contact outputs of one explicit step.
class ContactRecorder {
 public:
  /// Opens the history files of every pair (rank 0 writes when \p root).
  ContactRecorder(const ExplicitSettings& settings, const ExplicitSolver& solver,
                  OutputDirectory& output, const std::string& step_name, bool root);
  ~ContactRecorder();
  /// Writes a history row when \p force_row or the step is due, and the patch fields whose time
  /// has come.
  void record(bool force_row);
  /// Staging paths of the patch files written so far and of their charts, for pairs that ask for
  /// charts: {csv, png} each.
  std::vector<std::array<std::string, 2>> patch_charts() const;
  /// Adds each frictional pair's penalty flexibility (penalty_flexibility() at the history row
  /// with the largest normal force that had a patch to compare with, rows before a restart
  /// included) to \p summary under \p section, and returns the warnings: pairs that never
  /// touched, and pairs whose penalty layer costs more than kFlexibilityWarning of the creep
  /// force where the patch sticks.
  std::vector<std::string> summarise(RunSummary& summary, const std::string& section) const;
  /// Rows written so far, the next patch, the patch files written so far and the penalty
  /// flexibility at the largest normal force so far, for checkpoints.
  std::vector<double> state() const;
  /// Restores state() and rewrites the rows and the patch files (rank 0), so that a resumed
  /// run's results directory holds every patch, also those written before the interruption.
  void restore(const std::vector<double>& values);

 private:
  /// Rows of a CSV file's numbers.
  using Rows = std::vector<std::vector<double>>;

  void write_patch(std::size_t pair, std::size_t index);
  void write_patch_file(std::size_t pair, std::size_t index, const Rows& rows) const;
  std::string patch_name(std::size_t pair, std::size_t index, const char* extension) const;

  const ExplicitSettings& settings_;
  const ExplicitSolver& solver_;
  OutputDirectory& output_;
  std::string step_name_;
  bool root_;
  std::vector<std::unique_ptr<CsvWriter>> histories_;
  std::vector<Rows> rows_;                       // per pair
  std::vector<std::size_t> next_patch_;          // per pair: index of the next patch time
  std::vector<std::vector<Rows>> patch_rows_;    // per pair and patch file (root)
  std::vector<PenaltyFlexibility> flexibility_;  // per pair
  long long last_step_ = -1;
};

}  // namespace railfe
