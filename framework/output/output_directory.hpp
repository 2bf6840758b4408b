#pragma once
/// \file
/// Where a run writes, and the rule that a failed run never leaves output that looks complete:
/// files are written as NAME.part and renamed to NAME only when the whole run succeeds.

#include <string>
#include <vector>

#include "framework/base/parallel.hpp"

namespace railfe {

/// The results directory of one run. Rank 0 does the file-system work.
class OutputDirectory {
 public:
  /// Creates \p path if needed (collective) and removes what an earlier run left there: the
  /// files listed in its manifest (its results, or the .part files of a failed run), the
  /// manifest and FAILED.txt. Nothing else is touched, so a results directory may be shared
  /// with other files. Throws RunError if the directory cannot be created or written.
  OutputDirectory(std::string path, const Communicator& comm);

  /// The directory.
  const std::string& path() const { return path_; }
  /// Names the step whose files are registered from now on ("" for the run's own files), so that
  /// no step can overwrite another's results.
  void begin_step(const std::string& step_name) { current_step_ = step_name; }
  /// Path to write \p name to during the run (NAME.part); registers it for finalize(). Asking
  /// again from the same step returns the same path; a file registered by another step is a
  /// RunError naming both steps (one step's results never overwrite another's).
  std::string staging_path(const std::string& name);
  /// Where an earlier step staged \p name, to read it during the run (a chart comparing two
  /// steps); registers nothing. Throws RunError when no step has registered \p name.
  std::string staged_path_of(const std::string& name) const;
  /// Final path of \p name (valid after finalize()).
  std::string final_path(const std::string& name) const;
  /// Checks that no registered file holds NaN or inf (a RunError naming the file and where, on
  /// every rank), then renames every registered file to its final name and writes the manifest
  /// (collective).
  void finalize();
  /// Records the failure in FAILED.txt; staged files keep their .part names and are listed in
  /// the manifest for the next run to remove (rank 0 only).
  void mark_failed(const std::string& message) const;
  /// Names registered so far.
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::string path_;
  Communicator comm_;
  std::vector<std::string> names_;
  std::vector<std::string> owners_;  // the step that registered names_[i]
  std::string current_step_;
};

}  // namespace railfe
