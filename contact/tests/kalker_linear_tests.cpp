// Kalker's creepage coefficients: every point of Kalker's Table E.3 reproduced, the
// interpolation smooth and free of overshoot between them, and the linear forces and damping
// matrix consistent with each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "contact/laws/kalker_linear.hpp"

namespace railfe {
namespace {

// The table's rows as (a, b) with b = 1 or a = 1, and the twelve values, read here without the
// class's parser.
struct Row {
  double a, b;
  double values[12];
};

std::vector<Row> table_rows() {
  std::ifstream in(RAILFE_KALKER_TABLE);
  std::vector<Row> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    if (header) {
      header = false;
      continue;
    }
    std::stringstream fields(line);
    std::string kind, cell;
    std::getline(fields, kind, ',');
    std::getline(fields, cell, ',');
    const double ratio = std::stod(cell);
    Row row{kind == "a/b" ? ratio : 1.0, kind == "a/b" ? 1.0 : ratio, {}};
    for (double& v : row.values) {
      std::getline(fields, cell, ',');
      v = std::stod(cell);
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(KalkerLinear, ReproducesEveryTablePoint) {
  const std::vector<Row> rows = table_rows();
  ASSERT_EQ(rows.size(), 20u);
  const double nus[3] = {0, 0.25, 0.5};
  for (const Row& row : rows)
    for (int v = 0; v < 3; ++v) {
      const KalkerCoefficients c = KalkerTable::shipped().at(row.a, row.b, nus[v]);
      EXPECT_NEAR(c.C11, row.values[v], 1e-12);
      EXPECT_NEAR(c.C22, row.values[3 + v], 1e-12);
      EXPECT_NEAR(c.C23, row.values[6 + v], 1e-12);
      EXPECT_NEAR(c.C33, row.values[9 + v], 1e-12);
    }
  // Three values as Kalker prints them (1990, Table E.3).
  const KalkerCoefficients circle = KalkerTable::shipped().at(1, 1, 0.25);
  EXPECT_DOUBLE_EQ(circle.C11, 4.12);
  EXPECT_DOUBLE_EQ(circle.C23, 1.47);
  EXPECT_DOUBLE_EQ(KalkerTable::shipped().at(5, 1, 0.5).C22, 9.79);
}

TEST(KalkerLinear, InterpolationIsSmoothAndDoesNotOvershoot) {
  // Between neighbouring table ratios every coefficient stays within its two table values
  // (shape preservation), and its slope in ln(a/b) is continuous across the table points.
  const KalkerTable& table = KalkerTable::shipped();
  std::vector<double> ratios;
  for (const Row& row : table_rows())
    ratios.push_back(row.a / row.b);
  std::sort(ratios.begin(), ratios.end());
  ratios.erase(std::unique(ratios.begin(), ratios.end()), ratios.end());
  for (double nu : {0.0, 0.25, 0.5}) {
    for (std::size_t i = 0; i + 1 < ratios.size(); ++i) {
      const KalkerCoefficients lo = table.at(ratios[i], 1, nu), hi = table.at(ratios[i + 1], 1, nu);
      for (int k = 1; k < 20; ++k) {
        const double r = std::exp(std::log(ratios[i]) +
                                  (std::log(ratios[i + 1]) - std::log(ratios[i])) * k / 20);
        const KalkerCoefficients c = table.at(r, 1, nu);
        const double got[4] = {c.C11, c.C22, c.C23, c.C33};
        const double from[4] = {lo.C11, lo.C22, lo.C23, lo.C33};
        const double to[4] = {hi.C11, hi.C22, hi.C23, hi.C33};
        for (int q = 0; q < 4; ++q) {
          EXPECT_GE(got[q], std::min(from[q], to[q]) - 1e-12) << "ratio " << r << " nu " << nu;
          EXPECT_LE(got[q], std::max(from[q], to[q]) + 1e-12) << "ratio " << r << " nu " << nu;
        }
      }
    }
    // Slope continuity across each interior table point (ln ratio): one-sided differences of
    // step h agree to O(h).
    for (std::size_t i = 1; i + 1 < ratios.size(); ++i) {
      const double t = std::log(ratios[i]);
      for (double h : {1e-4}) {
        const double left =
            (table.at(ratios[i], 1, nu).C22 - table.at(std::exp(t - h), 1, nu).C22) / h;
        const double right =
            (table.at(std::exp(t + h), 1, nu).C22 - table.at(ratios[i], 1, nu).C22) / h;
        EXPECT_NEAR(left, right, 1e-3 * (1 + std::abs(left))) << "ratio " << ratios[i];
      }
    }
  }
  // Poisson's ratio between the columns: between the neighbouring columns' values here.
  const KalkerCoefficients c0 = table.at(0.5, 1, 0.25), c1 = table.at(0.5, 1, 0.5);
  const KalkerCoefficients mid = table.at(0.5, 1, 0.3);
  EXPECT_GT(mid.C11, c0.C11);
  EXPECT_LT(mid.C11, c1.C11);
  EXPECT_THROW(table.at(0.05, 1, 0.3), std::invalid_argument);
  EXPECT_THROW(table.at(1, 1, 0.6), std::invalid_argument);
}

TEST(KalkerLinear, ForcesAndDampingMatrixAgree) {
  const KalkerCoefficients c = KalkerTable::shipped().at(7.162e-3, 5.387e-3, 0.3);
  const double G = 210e9 / (2 * 1.3), a = 7.162e-3, b = 5.387e-3, V = 30;
  const double dv[3] = {0.03, -0.02, 0.5};  // relative velocities (m/s, m/s, rad/s)
  const CreepForces f = kalker_linear(c, G, a, b, creepages({dv[0], dv[1]}, {0, 0}, dv[2], 0, V));
  const auto D = kalker_damping(c, G, a, b, V);
  const double expect[3] = {f.Fx, f.Fy, f.Mz};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(-(D[3 * i] * dv[0] + D[3 * i + 1] * dv[1] + D[3 * i + 2] * dv[2]), expect[i],
                1e-9 * std::abs(expect[i]));
  // Forces oppose the creepage; lateral creepage and spin couple antisymmetrically.
  EXPECT_LT(f.Fx, 0);
  EXPECT_NEAR(D[5], -D[7], 1e-12 * std::abs(D[5]));
  EXPECT_NEAR(f.Fx, -G * a * b * c.C11 * 0.001, 1e-9 * std::abs(f.Fx));
}

}  // namespace
}  // namespace railfe
