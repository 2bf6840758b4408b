#pragma once
/// \file
/// Wall-clock timing and memory readings for the run summary and benchmarks.

#include <chrono>
#include <cstddef>

namespace railfe {

/// Measures elapsed wall-clock time from construction (or the last restart()).
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  /// Resets the start to now.
  void restart() { start_ = std::chrono::steady_clock::now(); }
  /// Seconds since the start.
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Peak resident set size of this process so far, in bytes (from getrusage).
std::size_t peak_resident_bytes();

}  // namespace railfe
