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
  /// Path to write \p name to during the run (NAME.part); registers it for finalize().
  std::string staging_path(const std::string& name);
  /// Final path of \p name (valid after finalize()).
  std::string final_path(const std::string& name) const;
  /// Renames every registered file to its final name and writes the manifest (collective).
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
};

}  // namespace railfe
