#pragma once
/// \file
/// Hex8 shape functions and their derivatives at the 2×2×2 Gauss points, tabulated once.

namespace railfe {

/// Shape function values and reference derivatives at the eight Gauss points (weights all 1).
struct Hex8GaussTable {
  double N[8][8];       ///< N[q][a]: shape function a at point q
  double dN[8][3][8];   ///< dN[q][k][a]: ∂N_a/∂ξ_k at point q (node index last, for SIMD)
  double centre[3][8];  ///< ∂N_a/∂ξ_k at ξ = 0
  double dN_by_point[3][8][8];  ///< dN_by_point[k][a][q] = dN[q][k][a], for SIMD over points
};

/// The table (built on first use, thread-safe).
const Hex8GaussTable& hex8_gauss_table();

/// Physical gradients at one point: given reference derivatives \p dN_ref [3][8] and node
/// coordinates \p x, fills \p gradient [3][8] with ∂N_a/∂x_i and returns det J (> 0 for a valid
/// element).
double hex8_gradients(const double x[8][3], const double dN_ref[3][8], double gradient[3][8]);

}  // namespace railfe
