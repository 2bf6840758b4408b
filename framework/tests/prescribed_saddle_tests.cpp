// The prescribed-unknown saddle-point solver against the monolithic one (the whole bordered
// matrix, dense LU) on a small nonsymmetric system: the same corrections and multipliers; and
// its refusal of rows it cannot eliminate.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <stdexcept>
#include <vector>

#include "framework/solvers/prescribed_saddle_point_solver.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"

namespace railfe {
namespace {

// M, C (nonsymmetric, as creep damping is), K of 7 unknowns; unknowns 2, 5 and 6 massless and
// unstiffened but for their coupling to the others, as a contact's internal nodes are.
LinearDenseSystem system() {
  const int n = 7;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n), c(n, n), k(n, n);
  for (int i : {0, 1, 3, 4})
    m(i, i) = 1.0 + i;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      c(i, j) = 0.1 * std::sin(1.0 + i + 2.0 * j);
      k(i, j) = (i == j ? 50.0 : 3.0 * std::cos(0.5 * i * j + 0.3 * i));
    }
  return LinearDenseSystem(m, c, k);
}

ConstraintRows prescribing(const std::vector<std::size_t>& unknowns) {
  ConstraintRows rows;
  double g = 0.01;
  for (std::size_t unknown : unknowns) {
    rows.start_row(g);
    rows.add_entry(unknown, unknown == 5 ? 2.0 : 1.0);
    g *= -1.7;
  }
  return rows;
}

TEST(PrescribedSaddlePointSolver, MatchesTheMonolithicSolve) {
  LinearDenseSystem a = system(), b = system();
  const ConstraintRows rows = prescribing({2, 5, 6});
  const std::vector<double> u(7, 0.0), v(7, 0.0);
  const MatrixCoefficients coefficients{1.0, 0.02, 1e-4, 0.0};
  PrescribedSaddlePointSolver prescribed(a);
  MonolithicSaddlePointSolver monolithic(b);
  prescribed.factor(u.data(), v.data(), coefficients, rows);
  monolithic.factor(u.data(), v.data(), coefficients, rows);
  const std::vector<double> r{1.0, -2.0, 0.5, 3.0, -1.0, 0.25, 2.0}, r_c{0.3, -0.1, 0.7};
  std::vector<double> x1(7), x2(7), mu1(3), mu2(3);
  prescribed.solve(r.data(), r_c.data(), x1.data(), mu1.data());
  monolithic.solve(r.data(), r_c.data(), x2.data(), mu2.data());
  for (int i = 0; i < 7; ++i)
    EXPECT_NEAR(x1[i], x2[i], 1e-12 * (1 + std::abs(x2[i]))) << "unknown " << i;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(mu1[i], mu2[i], 1e-12 * (1 + std::abs(mu2[i]))) << "row " << i;
  EXPECT_NEAR(x1[5], 0.5 * r_c[1], 1e-15);  // c x = g on the row of coefficient 2
}

TEST(PrescribedSaddlePointSolver, RefusesRowsItCannotEliminate) {
  LinearDenseSystem a = system();
  PrescribedSaddlePointSolver solver(a);
  const std::vector<double> u(7, 0.0);
  const MatrixCoefficients coefficients{1.0, 0.02, 1e-4, 0.0};
  ConstraintRows two_entries;
  two_entries.start_row(0.0);
  two_entries.add_entry(2, 1.0);
  two_entries.add_entry(3, -1.0);
  EXPECT_THROW(solver.factor(u.data(), u.data(), coefficients, two_entries), std::invalid_argument);
  EXPECT_THROW(solver.factor(u.data(), u.data(), coefficients, prescribing({2, 2})),
               std::invalid_argument);
}

}  // namespace
}  // namespace railfe
