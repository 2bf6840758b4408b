#include "framework/output/progress.hpp"

#include <cstdio>

namespace railfe {

Progress::Progress(std::string label, double total, const Communicator& comm, bool quiet,
                   double interval_seconds, bool total_is_bound)
    : label_(std::move(label)),
      total_(total),
      active_(comm.is_root() && !quiet),
      interval_(interval_seconds),
      total_is_bound_(total_is_bound) {}

void Progress::update(double done) {
  if (!active_)
    return;
  const double elapsed = clock_.seconds();
  if (elapsed - last_print_ < interval_)
    return;
  last_print_ = elapsed;
  const double fraction = total_ > 0 ? done / total_ : 1.0;
  if (fraction <= 0) {
    std::printf("[%s] started, %.1f s elapsed\n", label_.c_str(), elapsed);
  } else if (total_is_bound_) {
    std::printf("[%s] %.0f done (at most %.0f), %.1f s elapsed, %.1f s each\n", label_.c_str(),
                done, total_, elapsed, elapsed / done);
  } else if (done <= start_) {
    std::printf("[%s] %5.1f%% done, %.1f s elapsed\n", label_.c_str(), 100.0 * fraction, elapsed);
  } else {
    const double since = done - start_;
    const double remaining = elapsed * (total_ - done) / since;
    std::printf("[%s] %5.1f%% done, %.1f s elapsed, about %.0f s to go\n", label_.c_str(),
                100.0 * fraction, elapsed, remaining);
  }
  std::fflush(stdout);
}

void Progress::finish() {
  if (!active_)
    return;
  std::printf("[%s] done in %.2f s\n", label_.c_str(), clock_.seconds());
  std::fflush(stdout);
}

}  // namespace railfe
