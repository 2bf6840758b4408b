#include "framework/time/constraint_set.hpp"

#include <algorithm>

namespace railfe {

void ConstraintRows::clear() {
  offsets.assign(1, 0);
  columns.clear();
  values.clear();
  rhs.clear();
}

void ConstraintRows::start_row(double g) {
  rhs.push_back(g);
  offsets.push_back(columns.size());
}

void ConstraintRows::add_entry(std::size_t column, double value) {
  if (value == 0)
    return;
  columns.push_back(column);
  values.push_back(value);
  ++offsets.back();
}

void ConstraintRows::multiply(const double* u, double* cu) const {
  for (std::size_t i = 0; i < size(); ++i) {
    double sum = 0;
    for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k)
      sum += values[k] * u[columns[k]];
    cu[i] = sum;
  }
}

void ConstraintRows::add_transpose(const double* lambda, double scale, double* f) const {
  for (std::size_t i = 0; i < size(); ++i)
    for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k)
      f[columns[k]] += scale * values[k] * lambda[i];
}

void ConstraintSet::rates(double, const double*, const double*, std::size_t n_rows,
                          double* velocity, double* acceleration) {
  std::fill(velocity, velocity + n_rows, 0.0);
  std::fill(acceleration, acceleration + n_rows, 0.0);
}

bool ConstraintRows::same_matrix(const ConstraintRows& other) const {
  return offsets == other.offsets && columns == other.columns && values == other.values;
}

}  // namespace railfe
