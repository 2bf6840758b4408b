// The enhanced-strain hex8 against references nobody here wrote: rigid-body modes and rank, the
// patch test on a distorted element (a linear field loads it exactly as the trilinear element),
// and pure bending of a slender beam, which beam theory solves exactly (M L² / 2EI) and the
// enhanced element must reproduce with one element through the depth where the fully
// integrated element locks.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <vector>

#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8_enhanced_strain.hpp"

#include "physics/tests/distorted_hex8.hpp"

namespace railfe {
namespace {

using Matrix24 = Eigen::Matrix<double, 24, 24, Eigen::RowMajor>;

Matrix24 enhanced(const double x[8][3], double young = 210e9, double poisson = 0.3) {
  Matrix24 K;
  hex8_enhanced_strain_stiffness(x, lame_constants(young, poisson), K.data());
  return K;
}

Matrix24 full(const double x[8][3], double young = 210e9, double poisson = 0.3) {
  Matrix24 K;
  hex8_stiffness(x, lame_constants(young, poisson), K.data());
  return K;
}

TEST(Hex8EnhancedStrain, SymmetricWithExactlySixRigidBodyModes) {
  double x[8][3];
  distorted(x);
  const Matrix24 K = enhanced(x);
  EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 24, 24>> eigen(K);
  const auto& values = eigen.eigenvalues();
  const double largest = values(23);
  for (int k = 0; k < 6; ++k)
    EXPECT_LT(std::abs(values(k)), 1e-10 * largest) << k;
  // No spurious zero-energy mode: the seventh eigenvalue is a genuine deformation.
  EXPECT_GT(values(6), 1e-4 * largest);
  // Rigid motions carry no force.
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::Matrix<double, 24, 1> u;
    for (int a = 0; a < 8; ++a) {
      const double* p = x[a];
      const double rigid[6][3] = {{1, 0, 0},        {0, 1, 0},        {0, 0, 1},
                                  {0, -p[2], p[1]}, {p[2], 0, -p[0]}, {-p[1], p[0], 0}};
      for (int d = 0; d < 3; ++d)
        u(3 * a + d) = rigid[mode][d];
    }
    EXPECT_LT((K * u).norm(), 1e-10 * K.norm() * u.norm()) << mode;
  }
}

TEST(Hex8EnhancedStrain, LinearFieldLoadsTheElementLikeTheTrilinearOne) {
  // Patch test at element level: a linear displacement (constant strain) must leave the enhanced
  // modes unexcited, so the nodal forces are exactly ∫ Bᵀ σ dV of the trilinear element.
  double x[8][3];
  distorted(x);
  const double gradient[3][3] = {{1.0, 0.5, 0.5}, {0.5, 1.0, 0.5}, {0.5, 0.5, 1.0}};
  Eigen::Matrix<double, 24, 1> u;
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      u(3 * a + i) =
          1e-3 * (gradient[i][0] * x[a][0] + gradient[i][1] * x[a][1] + gradient[i][2] * x[a][2]);
    }
  }
  const Eigen::Matrix<double, 24, 1> expected = full(x) * u;
  EXPECT_LT((enhanced(x) * u - expected).norm(), 1e-12 * expected.norm());
}

// Tip deflection of a beam of \p n rectangular elements (length L, one element of h × h through
// the section, ν = 0), clamped by symmetry at x = 0 (u_x = u_y = u_z = 0 there: with ν = 0 the
// exact pure-bending field has no section distortion) and bent by a moment M at x = L applied as
// axial nodal force pairs.
double pure_bending_tip(int n, double L, double h, double young, bool enhanced_strain) {
  const int nodes = 4 * (n + 1);
  const int dofs = 3 * nodes;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  auto node = [](int i, int j, int k) { return 4 * i + 2 * k + j; };
  const double dx = L / n;
  for (int e = 0; e < n; ++e) {
    double x[8][3];
    int global[8];
    for (int a = 0; a < 8; ++a) {
      const double* s = kHex8NodeReference[a];
      const int i = e + (s[0] > 0), j = s[1] > 0, k = s[2] > 0;
      x[a][0] = i * dx;
      x[a][1] = j * h;
      x[a][2] = k * h;
      global[a] = node(i, j, k);
    }
    const Matrix24 Ke = enhanced_strain ? enhanced(x, young, 0.0) : full(x, young, 0.0);
    for (int a = 0; a < 8; ++a) {
      for (int b = 0; b < 8; ++b)
        K.block<3, 3>(3 * global[a], 3 * global[b]) += Ke.block<3, 3>(3 * a, 3 * b);
    }
  }
  const double moment = 1.0;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs);
  const double pair = moment / (2 * h);  // four axial forces ±pair at z = h and z = 0
  for (int j = 0; j < 2; ++j) {
    f(3 * node(n, j, 1)) += pair;
    f(3 * node(n, j, 0)) -= pair;
  }
  std::vector<int> free;
  for (int i = 1; i <= n; ++i) {
    for (int j = 0; j < 2; ++j) {
      for (int k = 0; k < 2; ++k) {
        free.push_back(3 * node(i, j, k));
        free.push_back(3 * node(i, j, k) + 2);
      }
    }
  }
  const int m = static_cast<int>(free.size());
  Eigen::MatrixXd Kf(m, m);
  Eigen::VectorXd ff(m);
  for (int r = 0; r < m; ++r) {
    ff(r) = f(free[r]);
    for (int c = 0; c < m; ++c)
      Kf(r, c) = K(free[r], free[c]);
  }
  const Eigen::VectorXd u = Kf.ldlt().solve(ff);
  for (int r = 0; r < m; ++r) {
    if (free[r] == 3 * node(n, 0, 0) + 2)
      return u(r);
  }
  return 0;
}

TEST(Hex8EnhancedStrain, PureBendingOfASlenderBeamIsExactWithOneElementThroughTheDepth) {
  const double L = 2.0, h = 0.1, young = 210e9;
  const double inertia = h * h * h * h / 12;
  const double beam_theory = -1.0 * L * L / (2 * young * inertia);  // z is up, M bends it down
  for (int n : {1, 4, 10}) {
    const double tip = pure_bending_tip(n, L, h, young, true);
    EXPECT_NEAR(tip / beam_theory, 1.0, 1e-9) << n << " elements";
  }
  // The fully integrated element locks: parasitic shear at the Gauss points leaves it the
  // fraction 1 / (1 + a²/2) of the deflection at ν = 0, a = element length / depth (the bilinear
  // element's closed form, e.g. Cook, Malkus & Plesha, Concepts and Applications of FEA).
  for (int n : {1, 4, 10}) {
    const double aspect = L / n / h;
    EXPECT_NEAR(pure_bending_tip(n, L, h, young, false) / beam_theory,
                1 / (1 + aspect * aspect / 2), 1e-9)
        << n << " elements";
  }
}

}  // namespace
}  // namespace railfe
