#include "framework/mesh/hex8_shape.hpp"

#include <cmath>

#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

namespace {

Hex8GaussTable build_table() {
  Hex8GaussTable table{};
  const double g = 1.0 / std::sqrt(3.0);
  for (int q = 0; q < 8; ++q) {
    // Gauss points in the node order of the reference cube.
    const double xi[3] = {g * kHex8NodeReference[q][0], g * kHex8NodeReference[q][1],
                          g * kHex8NodeReference[q][2]};
    for (int a = 0; a < 8; ++a) {
      const double* s = kHex8NodeReference[a];
      const double f[3] = {1 + s[0] * xi[0], 1 + s[1] * xi[1], 1 + s[2] * xi[2]};
      table.N[q][a] = f[0] * f[1] * f[2] / 8;
      table.dN[q][0][a] = s[0] * f[1] * f[2] / 8;
      table.dN[q][1][a] = f[0] * s[1] * f[2] / 8;
      table.dN[q][2][a] = f[0] * f[1] * s[2] / 8;
    }
  }
  for (int a = 0; a < 8; ++a) {
    for (int k = 0; k < 3; ++k)
      table.centre[k][a] = kHex8NodeReference[a][k] / 8;
  }
  for (int q = 0; q < 8; ++q) {
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 8; ++a)
        table.dN_by_point[k][a][q] = table.dN[q][k][a];
    }
  }
  return table;
}

}  // namespace

const Hex8GaussTable& hex8_gauss_table() {
  static const Hex8GaussTable table = build_table();
  return table;
}

double hex8_gradients(const double x[8][3], const double dN_ref[3][8], double gradient[3][8]) {
  // J[d][k] = ∂x_d/∂ξ_k
  double J[3][3] = {};
  for (int a = 0; a < 8; ++a) {
    for (int d = 0; d < 3; ++d) {
      for (int k = 0; k < 3; ++k)
        J[d][k] += x[a][d] * dN_ref[k][a];
    }
  }
  const double c00 = J[1][1] * J[2][2] - J[1][2] * J[2][1];
  const double c01 = J[1][2] * J[2][0] - J[1][0] * J[2][2];
  const double c02 = J[1][0] * J[2][1] - J[1][1] * J[2][0];
  const double det = J[0][0] * c00 + J[0][1] * c01 + J[0][2] * c02;
  const double inv_det = 1.0 / det;
  // inverse[k][i] = ∂ξ_k/∂x_i
  const double inverse[3][3] = {{c00 * inv_det, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * inv_det,
                                 (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * inv_det},
                                {c01 * inv_det, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * inv_det,
                                 (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * inv_det},
                                {c02 * inv_det, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * inv_det,
                                 (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * inv_det}};
  for (int i = 0; i < 3; ++i) {
    for (int a = 0; a < 8; ++a) {
      gradient[i][a] = dN_ref[0][a] * inverse[0][i] + dN_ref[1][a] * inverse[1][i] +
                       dN_ref[2][a] * inverse[2][i];
    }
  }
  return det;
}

}  // namespace railfe
