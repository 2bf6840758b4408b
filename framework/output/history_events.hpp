#pragma once
/// \file
/// Events measured on a sampled history (arrival of a wave, peak, period of an oscillation), as
/// the dynamic modules' recorders take them from every step.

namespace railfe {

/// Events measured on one history from every step.
struct HistoryEvents {
  double previous_time = 0;    ///< time of the last sample (s)
  double previous_value = 0;   ///< the last sample
  double arrival_time = -1;    ///< first time |value| reached the arrival level (−1: never)
  double peak_time = 0;        ///< time of the largest |value| (s)
  double peak_value = 0;       ///< that value
  double first_crossing = -1;  ///< first upward crossing of the period reference (s)
  double last_crossing = -1;   ///< last one (s)
  double crossings = 0;        ///< how many
  bool started = false;        ///< whether a sample was taken
  /// Takes the sample \p value at \p time.
  void sample(double time, double value, double arrival_level, double reference);
  /// The mean period between the first and last upward crossings (0 with fewer than two).
  double period() const {
    return crossings > 1 ? (last_crossing - first_crossing) / (crossings - 1) : 0.0;
  }
};

}  // namespace railfe
