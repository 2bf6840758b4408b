#pragma once
/// \file
/// Progress of long phases, printed once per job (by rank 0): percent done, elapsed time, ETA.

#include <string>

#include "framework/base/parallel.hpp"
#include "framework/base/resources.hpp"

namespace railfe {

/// Reports progress of one phase at most every interval_seconds.
class Progress {
 public:
  /// A phase called \p label with \p total units of work. Prints nothing if \p quiet. With
  /// \p total_is_bound, \p total is only the most there can be (iterations that stop when they
  /// converge): the lines give the count and the time per unit, never a percentage or a time to
  /// go that would assume all of them.
  Progress(std::string label, double total, const Communicator& comm, bool quiet,
           double interval_seconds = 5.0, bool total_is_bound = false);
  /// Says that \p done units were complete before this phase began (a run resumed from a
  /// checkpoint), so that the time to go is reckoned from the work done since.
  void start_at(double done) { start_ = done; }
  /// Records that \p done units are complete; prints when the interval has passed.
  void update(double done);
  /// Prints the final line with the total time.
  void finish();

 private:
  std::string label_;
  double total_;
  bool active_;
  double interval_;
  bool total_is_bound_;
  Stopwatch clock_;
  double last_print_ = 0;
  double start_ = 0;
};

}  // namespace railfe
