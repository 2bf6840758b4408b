// The hex8 element against independent references: rigid-body modes, symmetry and rank of the
// stiffness, the constant-strain patch, a textbook B^T D B integration, and load resultants.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8.hpp"

#include "physics/tests/distorted_hex8.hpp"

namespace railfe {
namespace {

using Matrix24 = Eigen::Matrix<double, 24, 24, Eigen::RowMajor>;

Matrix24 stiffness(const double x[8][3], double young = 210e9, double poisson = 0.3) {
  Matrix24 K;
  hex8_stiffness(x, lame_constants(young, poisson), K.data());
  return K;
}

// Textbook integration: K = Σ_q Bᵀ D B det J with B the 6×24 strain-displacement matrix.
Matrix24 reference_stiffness(const double x[8][3], double young, double poisson) {
  const double g = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  const double mu = young / (2 * (1 + poisson));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      D(i, j) = lambda;
    D(i, i) += 2 * mu;
    D(i + 3, i + 3) = mu;
  }
  Matrix24 K = Matrix24::Zero();
  for (int q = 0; q < 8; ++q) {
    const double xi[3] = {g * kHex8NodeReference[q][0], g * kHex8NodeReference[q][1],
                          g * kHex8NodeReference[q][2]};
    Eigen::Matrix<double, 3, 8> dN_ref;
    for (int a = 0; a < 8; ++a) {
      const double* s = kHex8NodeReference[a];
      dN_ref(0, a) = s[0] * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8;
      dN_ref(1, a) = (1 + s[0] * xi[0]) * s[1] * (1 + s[2] * xi[2]) / 8;
      dN_ref(2, a) = (1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) * s[2] / 8;
    }
    Eigen::Matrix<double, 8, 3> X;
    for (int a = 0; a < 8; ++a)
      X.row(a) << x[a][0], x[a][1], x[a][2];
    const Eigen::Matrix3d J = dN_ref * X;  // J(k, d) = ∂x_d/∂ξ_k
    const Eigen::Matrix<double, 3, 8> dN = J.inverse() * dN_ref;
    Eigen::Matrix<double, 6, 24> B = Eigen::Matrix<double, 6, 24>::Zero();
    for (int a = 0; a < 8; ++a) {
      B(0, 3 * a) = dN(0, a);
      B(1, 3 * a + 1) = dN(1, a);
      B(2, 3 * a + 2) = dN(2, a);
      B(3, 3 * a) = dN(1, a);  // γ_xy
      B(3, 3 * a + 1) = dN(0, a);
      B(4, 3 * a + 1) = dN(2, a);  // γ_yz
      B(4, 3 * a + 2) = dN(1, a);
      B(5, 3 * a) = dN(2, a);  // γ_xz
      B(5, 3 * a + 2) = dN(0, a);
    }
    K += B.transpose() * D * B * J.determinant();
  }
  return K;
}

TEST(Hex8, StiffnessMatchesTextbookIntegration) {
  double x[8][3];
  distorted(x);
  for (double poisson : {0.0, 0.3, 0.49}) {
    const Matrix24 K = stiffness(x, 210e9, poisson);
    const Matrix24 reference = reference_stiffness(x, 210e9, poisson);
    EXPECT_LT((K - reference).norm() / reference.norm(), 1e-14) << poisson;
  }
}

TEST(Hex8, SymmetricWithExactlySixRigidBodyModes) {
  double x[8][3];
  distorted(x);
  const Matrix24 K = stiffness(x);
  EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-15);
  // Translations and infinitesimal rotations produce no force.
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::Matrix<double, 24, 1> u;
    for (int a = 0; a < 8; ++a) {
      const Eigen::Vector3d r(x[a][0], x[a][1], x[a][2]);
      Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
      if (mode < 3) {
        displacement[mode] = 1;
      } else {
        displacement = Eigen::Vector3d::Unit(mode - 3).cross(r);
      }
      u.segment<3>(3 * a) = displacement;
    }
    EXPECT_LT((K * u).norm() / (K.norm() * u.norm()), 1e-14) << "mode " << mode;
  }
  const Eigen::SelfAdjointEigenSolver<Matrix24> eigen(K);
  const double largest = eigen.eigenvalues().maxCoeff();
  int zero = 0;
  for (int k = 0; k < 24; ++k) {
    if (std::abs(eigen.eigenvalues()[k]) < 1e-12 * largest)
      ++zero;
    EXPECT_GT(eigen.eigenvalues()[k], -1e-12 * largest);
  }
  EXPECT_EQ(zero, 6);
}

TEST(Hex8, LinearFieldGivesExactStress) {
  double x[8][3];
  distorted(x);
  // u = G r with a general (unsymmetric) gradient G.
  const double G[3][3] = {{1e-3, 2e-4, -3e-4}, {5e-4, -2e-3, 1e-4}, {-1e-4, 3e-4, 1.5e-3}};
  double u[24];
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      u[3 * a + i] = G[i][0] * x[a][0] + G[i][1] * x[a][1] + G[i][2] * x[a][2];
    }
  }
  const LameConstants m = lame_constants(1e6, 0.25);
  double stress[6];
  hex8_centre_stress(x, u, m, stress);
  const double trace = G[0][0] + G[1][1] + G[2][2];
  const double expected[6] = {m.lambda * trace + 2 * m.mu * G[0][0],
                              m.lambda * trace + 2 * m.mu * G[1][1],
                              m.lambda * trace + 2 * m.mu * G[2][2],
                              m.mu * (G[0][1] + G[1][0]),
                              m.mu * (G[1][2] + G[2][1]),
                              m.mu * (G[0][2] + G[2][0])};
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(stress[k], expected[k], 1e-9 * 2000) << k;
}

TEST(Hex8, LoadResultants) {
  double x[8][3];
  distorted(x);
  const double body[3] = {1.0, -2.0, 9.81};
  double forces[24];
  hex8_body_force(x, body, forces);
  const double volume = hex8_volume(x);
  for (int d = 0; d < 3; ++d) {
    double sum = 0;
    for (int a = 0; a < 8; ++a)
      sum += forces[3 * a + d];
    EXPECT_NEAR(sum, body[d] * volume, 1e-13 * std::abs(body[d] * volume) + 1e-15);
  }
  // Unit cube: volume 1, face areas 1, pressure resultant along the outward normal.
  const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  EXPECT_NEAR(hex8_volume(cube), 1.0, 1e-15);
  const double outward[6][3] = {{0, -1, 0}, {1, 0, 0},  {0, 1, 0},
                                {-1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  for (int face = 0; face < 6; ++face) {
    EXPECT_NEAR(hex8_face_area(cube, face), 1.0, 1e-15);
    double pressure_forces[12];
    hex8_face_pressure(cube, face, 3.0, pressure_forces);
    for (int d = 0; d < 3; ++d) {
      double sum = 0;
      for (int k = 0; k < 4; ++k)
        sum += pressure_forces[3 * k + d];
      EXPECT_NEAR(sum, -3.0 * outward[face][d], 1e-14) << face << " " << d;
    }
  }
}

}  // namespace
}  // namespace railfe

namespace railfe {
namespace {

// The consistent mass of a rectangular brick has the closed form ρV/216 · 2^(shared coordinates)
// per node pair (Zienkiewicz & Taylor): diagonal ρV/27, edge neighbours ρV/54, face diagonals
// ρV/108, body diagonals ρV/216.
TEST(Hex8, ConsistentMassOfABrickMatchesClosedForm) {
  double x[8][3];
  const double lengths[3] = {2.0, 0.5, 1.5};
  for (int a = 0; a < 8; ++a) {
    for (int d = 0; d < 3; ++d)
      x[a][d] = (kHex8NodeReference[a][d] + 1) / 2 * lengths[d];
  }
  const double density = 7850, mass = density * 2.0 * 0.5 * 1.5;
  Matrix24 M;
  hex8_mass(x, density, false, M.data());
  for (int a = 0; a < 8; ++a) {
    for (int b = 0; b < 8; ++b) {
      int shared = 0;
      for (int d = 0; d < 3; ++d)
        shared += kHex8NodeReference[a][d] == kHex8NodeReference[b][d] ? 1 : 0;
      const double expected = mass / 216 * std::pow(2.0, shared);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          EXPECT_NEAR(M(3 * a + i, 3 * b + j), i == j ? expected : 0.0, 1e-12 * mass);
        }
      }
    }
  }
}

// Lumping keeps the total mass in each direction and leaves a diagonal; on a distorted element
// the consistent matrix still carries the element's mass ρV in each direction.
TEST(Hex8, LumpedMassIsDiagonalWithTheElementMass) {
  double x[8][3];
  distorted(x);
  const double density = 7850, mass = density * hex8_volume(x);
  Matrix24 consistent, lumped;
  hex8_mass(x, density, false, consistent.data());
  hex8_mass(x, density, true, lumped.data());
  for (int d = 0; d < 3; ++d) {
    double consistent_sum = 0, lumped_sum = 0;
    for (int a = 0; a < 8; ++a) {
      for (int b = 0; b < 8; ++b) {
        consistent_sum += consistent(3 * a + d, 3 * b + d);
        lumped_sum += lumped(3 * a + d, 3 * b + d);
      }
      EXPECT_GT(lumped(3 * a + d, 3 * a + d), 0.0);
    }
    EXPECT_NEAR(consistent_sum, mass, 1e-12 * mass);
    EXPECT_NEAR(lumped_sum, mass, 1e-12 * mass);
  }
  EXPECT_NEAR((lumped - Matrix24(lumped.diagonal().asDiagonal())).norm(), 0.0, 1e-14 * mass);
}

}  // namespace
}  // namespace railfe
