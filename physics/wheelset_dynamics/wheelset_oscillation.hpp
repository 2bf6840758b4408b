#pragma once
/// \file
/// The lateral oscillation of a wheelset measured from its history: period (upward crossings
/// of zero, HistoryEvents) and the growth of its peaks from cycle to cycle, the quantity that
/// tells a stable run (< 1) from a hunting one (> 1); and each cycle on its own, for motions
/// whose wavelength depends on their amplitude (worn or real profiles).

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

/// One full cycle, between two upward crossings of zero.
struct OscillationCycle {
  double start = 0;      ///< time of its first crossing (s)
  double period = 0;     ///< to the next crossing (s)
  double amplitude = 0;  ///< half its peak-to-peak range
};

/// Takes a history sample by sample.
class OscillationMeter {
 public:
  /// Adds the sample \p value at \p time.
  void add(double time, double value) {
    const double crossings = events_.crossings;
    const double crossed_before = events_.last_crossing;
    events_.sample(time, value, 0.0, 0.0);
    if (events_.crossings > crossings) {
      if (events_.crossings > 1) {
        peaks_.push_back(peak_);
        cycles_.push_back(
            {crossed_before, events_.last_crossing - crossed_before, 0.5 * (peak_ - trough_)});
      }
      peak_ = trough_ = 0;
    }
    peak_ = std::max(peak_, value);
    trough_ = std::min(trough_, value);
  }
  /// The full cycles so far, in order.
  const std::vector<OscillationCycle>& cycles() const { return cycles_; }
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
  double peak_ = 0, trough_ = 0;  // of the cycle under way
  std::vector<double> peaks_;     // the positive peak of each full cycle
  std::vector<OscillationCycle> cycles_;
};

}  // namespace railfe
