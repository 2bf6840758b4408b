#include "physics/elements/hex8_stress_recovery.hpp"

#include <cmath>

#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8_enhanced_strain.hpp"

namespace railfe {

namespace {

// Adds the stress of the engineering strain \p strain to \p stress.
void add_hooke(const double strain[6], const LameConstants& material, double stress[6]) {
  const double volumetric = material.lambda * (strain[0] + strain[1] + strain[2]);
  for (int c = 0; c < 3; ++c) {
    stress[c] += volumetric + 2 * material.mu * strain[c];
    stress[c + 3] += material.mu * strain[c + 3];
  }
}

}  // namespace

void hex8_corner_stresses(const double x[8][3], const double* u, const LameConstants& material,
                          Hex8Strain strain, double stress[8][6]) {
  const Hex8GaussTable& table = hex8_gauss_table();
  if (strain == Hex8Strain::centre) {
    hex8_centre_stress(x, u, material, stress[0]);
    for (int a = 1; a < 8; ++a) {
      for (int c = 0; c < 6; ++c)
        stress[a][c] = stress[0][c];
    }
    return;
  }
  double gauss[8][6];  // Gauss points in kHex8NodeReference order, at ξ = node / √3
  double enhanced[8][6];
  if (strain == Hex8Strain::enhanced_strain)
    hex8_enhanced_strains(x, u, material, enhanced);
  for (int q = 0; q < 8; ++q) {
    hex8_point_stress(x, u, material, table.dN[q], gauss[q]);
    if (strain == Hex8Strain::enhanced_strain)
      add_hooke(enhanced[q], material, gauss[q]);
  }
  // The trilinear field through the Gauss points, evaluated at node a (ξ = √3 × the point's
  // coordinate): each factor is 1 + √3 where the two signs agree, 1 − √3 where they differ.
  const double root3 = std::sqrt(3.0);
  for (int a = 0; a < 8; ++a) {
    for (int c = 0; c < 6; ++c)
      stress[a][c] = 0;
    for (int q = 0; q < 8; ++q) {
      double weight = 0.125;
      for (int k = 0; k < 3; ++k)
        weight *= 1 + root3 * kHex8NodeReference[a][k] * kHex8NodeReference[q][k];
      for (int c = 0; c < 6; ++c)
        stress[a][c] += weight * gauss[q][c];
    }
  }
}

}  // namespace railfe
