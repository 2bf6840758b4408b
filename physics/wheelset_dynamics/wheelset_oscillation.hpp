#pragma once
/// \file
/// The lateral oscillation of a wheelset measured from its history: period (upward crossings
/// of zero, HistoryEvents) and the growth of its peaks from cycle to cycle, the quantity that
/// tells a stable run (< 1) from a hunting one (> 1).

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/output/history_events.hpp"

namespace railfe {

/// Period, amplitude and growth of an oscillation about zero.
struct OscillationMeasure {
  int cycles = 0;               ///< full cycles between the first and last upward crossings
  double period = 0;            ///< mean period over them (s)
  double amplitude = 0;         ///< the peak of the last full cycle
  double growth_per_cycle = 0;  ///< geometric mean ratio of successive peaks
};

/// Takes a history sample by sample.
class OscillationMeter {
 public:
  /// Adds the sample \p value at \p time.
  void add(double time, double value) {
    const double crossings = events_.crossings;
    events_.sample(time, value, 0.0, 0.0);
    if (events_.crossings > crossings) {
      if (events_.crossings > 1)
        peaks_.push_back(peak_);
      peak_ = 0;
    }
    peak_ = std::max(peak_, value);
  }
  /// The measures so far.
  OscillationMeasure measure() const {
    OscillationMeasure m;
    m.cycles = events_.crossings > 1 ? static_cast<int>(events_.crossings) - 1 : 0;
    m.period = events_.period();
    if (!peaks_.empty())
      m.amplitude = peaks_.back();
    if (peaks_.size() > 1 && peaks_.front() > 0)
      m.growth_per_cycle =
          std::pow(peaks_.back() / peaks_.front(), 1.0 / static_cast<double>(peaks_.size() - 1));
    return m;
  }

 private:
  HistoryEvents events_;
  double peak_ = 0;
  std::vector<double> peaks_;  // the positive peak of each full cycle
};

}  // namespace railfe
