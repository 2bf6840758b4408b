#pragma once
/// \file
/// Test fixture shared by the hex8 element tests: one distorted element.

#include "physics/elements/hex8.hpp"

namespace railfe {

/// A 2 x 1 x 1 element with every corner moved a little (all corner Jacobians positive), so
/// that tests see a general trilinear map rather than a box.
inline void distorted(double x[8][3]) {
  const double perturbation[8][3] = {
      {0.1, -0.05, 0.02},   {-0.08, 0.03, 0.1}, {0.05, 0.07, -0.04},  {0.02, -0.06, 0.05},
      {-0.04, 0.05, -0.03}, {0.06, 0.02, 0.04}, {-0.02, -0.08, 0.06}, {0.03, 0.04, -0.07}};
  for (int a = 0; a < 8; ++a) {
    for (int d = 0; d < 3; ++d) {
      x[a][d] = (kHex8NodeReference[a][d] + 1) / 2 * (d == 0 ? 2.0 : 1.0) + perturbation[a][d];
    }
  }
}

}  // namespace railfe
