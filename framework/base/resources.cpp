#include "framework/base/resources.hpp"

#include <sys/resource.h>

namespace railfe {

std::size_t peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes.
}

}  // namespace railfe
