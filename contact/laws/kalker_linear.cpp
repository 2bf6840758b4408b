#include "contact/laws/kalker_linear.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

const char* const kColumns[4] = {"C11", "C22", "C23", "C33"};
const char* const kNu[3] = {"nu0", "nu025", "nu05"};

// Fritsch-Carlson slopes: a cubic Hermite interpolant through the points that overshoots
// nowhere (monotone stretches stay monotone, extrema stay at table points).
std::vector<double> shape_preserving_slopes(const std::vector<double>& x,
                                            const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> secant(n - 1), slope(n);
  for (std::size_t i = 0; i + 1 < n; ++i)
    secant[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  slope[0] = secant[0];
  slope[n - 1] = secant[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (secant[i - 1] * secant[i] <= 0) {
      slope[i] = 0;
    } else {
      // Weighted harmonic mean (Fritsch & Butland), which keeps the interpolant monotone.
      const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
      const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
      slope[i] = (w0 + w1) / (w0 / secant[i - 1] + w1 / secant[i]);
    }
  }
  return slope;
}

double hermite(const std::vector<double>& x, const std::vector<double>& y,
               const std::vector<double>& m, double t) {
  const std::size_t i =
      std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin(), x.size() - 1) - 1;
  const double h = x[i + 1] - x[i], s = (t - x[i]) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y[i] + h10 * h * m[i] + h01 * y[i + 1] + h11 * h * m[i + 1];
}

}  // namespace

Creepages creepages(const std::array<double, 2>& velocity_1,
                    const std::array<double, 2>& velocity_2, double normal_spin_1,
                    double normal_spin_2, double speed) {
  if (!(speed > 0))
    throw std::invalid_argument("creepages need a positive rolling speed");
  return {(velocity_1[0] - velocity_2[0]) / speed, (velocity_1[1] - velocity_2[1]) / speed,
          (normal_spin_1 - normal_spin_2) / speed};
}

KalkerTable::KalkerTable(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw_input_error(path, "", "Kalker coefficient table not found or not readable");
  std::string line;
  std::vector<std::string> header;
  std::map<double, std::vector<double>> rows;  // ln(a/b) -> values in header order
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#')
      continue;
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');)
      cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    if (cells.size() != header.size() || (cells[0] != "a/b" && cells[0] != "b/a"))
      throw_input_error(path, "line " + std::to_string(number),
                        "a row needs the case (a/b or b/a) and every column of the header");
    std::vector<double> values;
    try {
      for (std::size_t k = 1; k < cells.size(); ++k)
        values.push_back(std::stod(cells[k]));
    } catch (const std::exception&) {
      throw_input_error(path, "line " + std::to_string(number), "a value is not a number");
    }
    if (!(values[0] > 0 && values[0] <= 1))
      throw_input_error(path, "line " + std::to_string(number), "ratio outside (0, 1]");
    const double log_ratio = (cells[0] == "a/b" ? 1 : -1) * std::log(values[0]);
    rows[log_ratio] = values;  // a/b = 1 and b/a = 1 are the same point
  }
  for (const auto& [t, values] : rows)
    log_ratio_.push_back(t);
  if (log_ratio_.size() < 3)
    throw_input_error(path, "", "fewer than three semi-axis ratios");
  for (int c = 0; c < 4; ++c)
    for (int v = 0; v < 3; ++v) {
      const std::string name = std::string(kColumns[c]) + "_" + kNu[v];
      const auto column = std::find(header.begin(), header.end(), name);
      if (column == header.end())
        throw_input_error(path, "header", "no column " + name);
      const std::size_t k = static_cast<std::size_t>(column - header.begin()) - 1;
      for (const auto& [t, values] : rows)
        values_[c][v].push_back(values[k]);
      slopes_[c][v] = shape_preserving_slopes(log_ratio_, values_[c][v]);
    }
}

const KalkerTable& KalkerTable::shipped() {
  static const KalkerTable table(RAILFE_KALKER_TABLE);
  return table;
}

KalkerCoefficients KalkerTable::at(double a, double b, double nu) const {
  const double t = std::log(a / b);
  if (!(a > 0 && b > 0) || t < log_ratio_.front() - 1e-12 || t > log_ratio_.back() + 1e-12)
    throw std::invalid_argument("Kalker's table covers a/b from 0.1 to 10 only");
  if (!(nu >= 0 && nu <= 0.5))
    throw std::invalid_argument("Kalker's table covers Poisson's ratio 0 to 0.5 only");
  const double clamped = std::clamp(t, log_ratio_.front(), log_ratio_.back());
  // Quadratic Lagrange weights through nu = 0, 0.25, 0.5.
  const double w[3] = {(nu - 0.25) * (nu - 0.5) / 0.125, -nu * (nu - 0.5) / 0.0625,
                       nu * (nu - 0.25) / 0.125};
  double value[4];
  for (int c = 0; c < 4; ++c) {
    value[c] = 0;
    for (int v = 0; v < 3; ++v)
      value[c] += w[v] * hermite(log_ratio_, values_[c][v], slopes_[c][v], clamped);
  }
  return {value[0], value[1], value[2], value[3]};
}

CreepForces kalker_linear(const KalkerCoefficients& c, double G, double a, double b,
                          const Creepages& creep) {
  const double ab = a * b, root = std::sqrt(ab);
  return {-G * ab * c.C11 * creep.longitudinal,
          -G * ab * (c.C22 * creep.lateral + root * c.C23 * creep.spin),
          G * ab * root * (c.C23 * creep.lateral - root * c.C33 * creep.spin)};
}

std::array<double, 9> kalker_damping(const KalkerCoefficients& c, double G, double a, double b,
                                     double speed) {
  const double ab = a * b, root = std::sqrt(ab), k = G * ab / speed;
  return {k * c.C11, 0, 0, 0, k * c.C22, k * root * c.C23, 0, -k * root * c.C23, k * ab * c.C33};
}

}  // namespace railfe
