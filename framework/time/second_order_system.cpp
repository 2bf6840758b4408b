#include "framework/time/second_order_system.hpp"

#include <stdexcept>

namespace railfe {

void SecondOrderSystem::apply_rayleigh_stiffness(const double*, double*) {
  throw std::logic_error(
      "stiffness-proportional Rayleigh damping needs the system's apply_rayleigh_stiffness()");
}

double SecondOrderSystem::dot(const double* x, const double* y) const {
  double sum = 0;
  for (std::size_t i = 0; i < n_unknowns(); ++i)
    sum += x[i] * y[i];
  return sum;
}

}  // namespace railfe
