// Corner stresses of the hex8 against fields whose stress is known exactly: a linear displacement
// field on a distorted element (the patch test: every formulation, every corner, the same
// constant stress), and pure bending of a rectangular element (σxx = E κ z, no shear), which the
// enhanced-strain element reproduces at the corners while the fully integrated element reports
// a spurious shear there.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8_stress_recovery.hpp"

#include "physics/tests/distorted_hex8.hpp"

namespace railfe {
namespace {

TEST(Hex8StressRecovery, LinearFieldGivesItsStressAtEveryCornerInEveryFormulation) {
  double x[8][3];
  distorted(x);
  const double young = 210e9, poisson = 0.3;
  const LameConstants lame = lame_constants(young, poisson);
  // u = A x with a general (non-symmetric) gradient A.
  const double A[3][3] = {{1e-3, 2e-4, -3e-4}, {5e-4, -7e-4, 1e-4}, {-2e-4, 4e-4, 6e-4}};
  double u[24];
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i)
      u[3 * a + i] = A[i][0] * x[a][0] + A[i][1] * x[a][1] + A[i][2] * x[a][2];
  }
  const double trace = A[0][0] + A[1][1] + A[2][2];
  const double exact[6] = {lame.lambda * trace + 2 * lame.mu * A[0][0],
                           lame.lambda * trace + 2 * lame.mu * A[1][1],
                           lame.lambda * trace + 2 * lame.mu * A[2][2],
                           lame.mu * (A[0][1] + A[1][0]),
                           lame.mu * (A[1][2] + A[2][1]),
                           lame.mu * (A[0][2] + A[2][0])};
  for (Hex8Strain strain : {Hex8Strain::full, Hex8Strain::enhanced_strain, Hex8Strain::centre}) {
    double stress[8][6];
    hex8_corner_stresses(x, u, lame, strain, stress);
    for (int a = 0; a < 8; ++a) {
      for (int c = 0; c < 6; ++c)
        EXPECT_NEAR(stress[a][c], exact[c], 1e-9 * young * 1e-3) << a << " " << c;
    }
  }
}

TEST(Hex8StressRecovery, EnhancedStrainElementRecoversPureBendingAtTheCorners) {
  // Element [0, 2] × [0, 1] × [−0.1, 0.1]; ν = 0 so bending about y has no side strains. Nodal
  // values of the exact field u = κ x z, w = −κ x² / 2 (σxx = E κ z, every other stress zero).
  const double young = 1e9, kappa = 1e-3;
  const LameConstants lame = lame_constants(young, 0.0);
  double x[8][3], u[24];
  const double reference[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a) {
    x[a][0] = 1 + reference[a][0];
    x[a][1] = 0.5 + 0.5 * reference[a][1];
    x[a][2] = 0.1 * reference[a][2];
    u[3 * a] = kappa * x[a][0] * x[a][2];
    u[3 * a + 1] = 0;
    u[3 * a + 2] = -kappa * x[a][0] * x[a][0] / 2;
  }
  double enhanced[8][6], full[8][6];
  hex8_corner_stresses(x, u, lame, Hex8Strain::enhanced_strain, enhanced);
  hex8_corner_stresses(x, u, lame, Hex8Strain::full, full);
  const double scale = young * kappa * 0.1;  // the surface bending stress
  for (int a = 0; a < 8; ++a) {
    EXPECT_NEAR(enhanced[a][0], young * kappa * x[a][2], 1e-9 * scale) << a;
    for (int c = 1; c < 6; ++c)
      EXPECT_NEAR(enhanced[a][c], 0, 1e-9 * scale) << a << " " << c;
    // The locking element carries a parasitic shear σxz = μ κ (x − 1) of the surface stress's
    // size (here ±5 of it at the corners).
    EXPECT_GT(std::abs(full[a][5]), 1.0 * scale) << a;
  }
}

}  // namespace
}  // namespace railfe
