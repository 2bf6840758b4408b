#include "framework/time/second_order_system.hpp"

#include <stdexcept>

namespace railfe {

void SecondOrderSystem::apply_rayleigh_stiffness(const double*, double*) {
  throw std::logic_error(
      "stiffness-proportional Rayleigh damping needs the system's apply_rayleigh_stiffness()");
}

void SecondOrderSystem::solve_columns(const double* rhs, std::size_t n_columns, double* x) {
  const std::size_t n = n_unknowns();
  for (std::size_t j = 0; j < n_columns; ++j)
    solve(rhs + j * n, x + j * n);
}

bool SecondOrderSystem::apply_matrix(const double*, double*) {
  return false;
}

void SecondOrderSystem::matrix_entries(std::vector<MatrixEntry>&) const {
  throw std::logic_error("a monolithic saddle-point solve needs the system's matrix_entries()");
}

double SecondOrderSystem::dot(const double* x, const double* y) const {
  double sum = 0;
  for (std::size_t i = 0; i < n_unknowns(); ++i)
    sum += x[i] * y[i];
  return sum;
}

}  // namespace railfe
