#pragma once
/// \file
/// Running a deck from start to end: read, validate, build the mesh, check every step, run the
/// steps, write the summary. Input problems stop the run before anything is written.

#include <string>

#include "framework/app/registry.hpp"
#include "framework/base/parallel.hpp"

namespace railfe {

/// Command-line choices for one run.
struct RunOptions {
  std::string deck;    ///< path of the deck
  std::string output;  ///< results directory ("" = from the deck or <deck name>_results)
  bool quiet = false;  ///< no progress lines and no summary on the terminal
};

/// Process exit statuses of railfe.
enum ExitStatus { kSuccess = 0, kBadInput = 1, kRunFailed = 2, kInternalError = 3 };

/// Runs the deck (collective) and returns the exit status. The error message, if any, is printed
/// once, by rank 0, to standard error; the results directory then holds FAILED.txt and only
/// files named *.part.
int run_deck(const RunOptions& options, const ModuleRegistry& registry, const Communicator& comm);

}  // namespace railfe
