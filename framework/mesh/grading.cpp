#include "framework/mesh/grading.hpp"

#include <algorithm>

namespace railfe {

std::vector<double> graded_lengths(double distance, double first, double largest, double growth) {
  std::vector<double> lengths;
  double sum = 0, next = first * growth;
  while (sum < distance * (1 - 1e-12)) {
    const double length = std::min(next, largest);
    lengths.push_back(length);
    sum += length;
    next = length * growth;
  }
  if (lengths.size() > 1 && sum - distance > 0.5 * lengths.back()) {
    sum -= lengths.back();
    lengths.pop_back();
  }
  for (double& length : lengths)
    length *= distance / sum;
  return lengths;
}

}  // namespace railfe
