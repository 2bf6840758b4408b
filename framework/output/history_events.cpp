#include "framework/output/history_events.hpp"

#include <algorithm>
#include <cmath>

namespace railfe {

void HistoryEvents::sample(double time, double value, double arrival_level, double reference) {
  if (started) {
    if (arrival_level > 0 && arrival_time < 0 && std::abs(value) >= arrival_level) {
      // Linear interpolation between the samples that straddle the level.
      const double before = std::abs(previous_value), now = std::abs(value);
      const double fraction = now > before ? (arrival_level - before) / (now - before) : 1.0;
      arrival_time = previous_time + std::clamp(fraction, 0.0, 1.0) * (time - previous_time);
    }
    if (previous_value < reference && value >= reference) {
      const double crossing = previous_time + (reference - previous_value) /
                                                  (value - previous_value) * (time - previous_time);
      if (crossings == 0)
        first_crossing = crossing;
      last_crossing = crossing;
      crossings += 1;
    }
  }
  if (!started || std::abs(value) > std::abs(peak_value)) {
    peak_value = value;
    peak_time = time;
  }
  previous_time = time;
  previous_value = value;
  started = true;
}

}  // namespace railfe
