#include "framework/time/constraint_set.hpp"

#include <algorithm>
#include <stdexcept>

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

void rates_by_differences(ConstraintSet& set, double time, double h, const double* u,
                          const double* v, std::size_t n_rows, double* velocity,
                          double* acceleration) {
  ConstraintRows rows[3];
  std::vector<double> cu[3], cv[3];
  for (int i = 0; i < 3; ++i) {
    set.rows_at(time + (i - 1) * h, rows[i]);
    if (rows[i].size() != n_rows)
      throw std::logic_error("rates_by_differences: the rows changed in number within ±h");
    cu[i].resize(n_rows);
    cv[i].resize(n_rows);
    rows[i].multiply(u, cu[i].data());
    rows[i].multiply(v, cv[i].data());
  }
  for (std::size_t r = 0; r < n_rows; ++r) {
    // f(t) = g(t) − C(t) u at fixed u: ḟ = ġ − Ċ u, f̈ = g̈ − C̈ u.
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = rows[i].rhs[r] - cu[i][r];
    velocity[r] = (f[2] - f[0]) / (2 * h);
    acceleration[r] = (f[2] - 2 * f[1] + f[0]) / (h * h) - (cv[2][r] - cv[0][r]) / h;
  }
}

bool ConstraintRows::same_matrix(const ConstraintRows& other) const {
  return offsets == other.offsets && columns == other.columns && values == other.values;
}

}  // namespace railfe
