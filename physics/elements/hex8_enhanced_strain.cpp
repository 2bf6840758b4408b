#include "physics/elements/hex8_enhanced_strain.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>

#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

namespace {

constexpr int kModes = 9;

// Mode m puts the reference coordinate ξ_c into the natural strain component (k, l): the three
// normal strains each grow along their own direction, each shear strain along both of its own.
// Together they complete the strain field of a bent element (Andelfinger & Ramm's EAS9).
constexpr int kModeEntry[kModes][3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}, {0, 1, 1},
                                       {1, 2, 1}, {1, 2, 2}, {0, 2, 0}, {0, 2, 2}};

using Voigt = Eigen::Matrix<double, 6, 6>;

// Isotropic elasticity in Voigt order xx, yy, zz, xy, yz, zx with engineering shear strains.
Voigt elasticity(const LameConstants& material) {
  Voigt C = Voigt::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      C(i, j) = material.lambda;
    C(i, i) += 2 * material.mu;
    C(i + 3, i + 3) = material.mu;
  }
  return C;
}

// What the condensation and the stress recovery both need: K_uα (24 × 9), K_αα (9 × 9) and the
// enhanced strain-parameter matrix G (6 × 9) at each Gauss point.
struct EnhancedParts {
  Eigen::Matrix<double, 24, kModes> coupling = Eigen::Matrix<double, 24, kModes>::Zero();
  Eigen::Matrix<double, kModes, kModes> internal = Eigen::Matrix<double, kModes, kModes>::Zero();
  std::array<Eigen::Matrix<double, 6, kModes>, 8> G;
};

EnhancedParts enhanced_parts(const double x[8][3], const LameConstants& material) {
  EnhancedParts parts;
  const Hex8GaussTable& table = hex8_gauss_table();
  Eigen::Matrix3d centre_jacobian = Eigen::Matrix3d::Zero();  // ∂x_d/∂ξ_k at ξ = 0
  for (int a = 0; a < 8; ++a) {
    for (int d = 0; d < 3; ++d) {
      for (int k = 0; k < 3; ++k)
        centre_jacobian(d, k) += x[a][d] * table.centre[k][a];
    }
  }
  const double centre_det = centre_jacobian.determinant();
  // Natural (covariant) strains map to physical ones as ε = J₀⁻ᵀ ε̂ J₀⁻¹; the centre Jacobian
  // keeps the map constant over the element, which the patch test needs.
  const Eigen::Matrix3d inverse = centre_jacobian.inverse();
  const Voigt C = elasticity(material);
  const double g = 1.0 / std::sqrt(3.0);
  double gradient[3][8];
  for (int q = 0; q < 8; ++q) {
    const double det = hex8_gradients(x, table.dN[q], gradient);
    const double xi[3] = {g * kHex8NodeReference[q][0], g * kHex8NodeReference[q][1],
                          g * kHex8NodeReference[q][2]};
    // Enhanced strain-parameter matrix (6 × 9), scaled by det J₀ / det J so that ∫ G dV = 0.
    Eigen::Matrix<double, 6, kModes>& G = parts.G[q];
    for (int m = 0; m < kModes; ++m) {
      const int k = kModeEntry[m][0], l = kModeEntry[m][1];
      const double value = xi[kModeEntry[m][2]] * centre_det / det;
      Eigen::Matrix3d natural = Eigen::Matrix3d::Zero();
      natural(k, l) += value;
      natural(l, k) += value;
      const Eigen::Matrix3d physical = inverse.transpose() * natural * inverse;
      G.col(m) << physical(0, 0), physical(1, 1), physical(2, 2), 2 * physical(0, 1),
          2 * physical(1, 2), 2 * physical(0, 2);
    }
    Eigen::Matrix<double, 6, 24> B = Eigen::Matrix<double, 6, 24>::Zero();
    for (int a = 0; a < 8; ++a) {
      const double gx = gradient[0][a], gy = gradient[1][a], gz = gradient[2][a];
      B(0, 3 * a) = gx;
      B(1, 3 * a + 1) = gy;
      B(2, 3 * a + 2) = gz;
      B(3, 3 * a) = gy;
      B(3, 3 * a + 1) = gx;
      B(4, 3 * a + 1) = gz;
      B(4, 3 * a + 2) = gy;
      B(5, 3 * a) = gz;
      B(5, 3 * a + 2) = gx;
    }
    const Eigen::Matrix<double, 6, kModes> stress = det * (C * G);
    parts.coupling.noalias() += B.transpose() * stress;
    parts.internal.noalias() += G.transpose() * stress;
  }
  return parts;
}

}  // namespace

void hex8_enhanced_strain_stiffness(const double x[8][3], const LameConstants& material,
                                    double* stiffness) {
  hex8_stiffness(x, material, stiffness);
  const EnhancedParts parts = enhanced_parts(x, material);
  // Static condensation of the internal modes (K_αα is symmetric positive definite for a valid
  // element).
  const Eigen::Matrix<double, kModes, 24> solved =
      parts.internal.llt().solve(parts.coupling.transpose());
  Eigen::Map<Eigen::Matrix<double, 24, 24, Eigen::RowMajor>> K(stiffness);
  const Eigen::Matrix<double, 24, 24> condensed = parts.coupling * solved;
  // The product is symmetric only to round-off; CG and Cholesky want it exactly.
  K -= 0.5 * (condensed + condensed.transpose());
}

void hex8_enhanced_strains(const double x[8][3], const double* u, const LameConstants& material,
                           double strain[8][6]) {
  const EnhancedParts parts = enhanced_parts(x, material);
  const Eigen::Map<const Eigen::Matrix<double, 24, 1>> displacement(u);
  // The internal modes make the element's residual orthogonal to them: K_αu u + K_αα α = 0.
  const Eigen::Matrix<double, kModes, 1> alpha =
      -parts.internal.llt().solve(parts.coupling.transpose() * displacement);
  for (int q = 0; q < 8; ++q) {
    const Eigen::Matrix<double, 6, 1> enhanced = parts.G[q] * alpha;
    for (int c = 0; c < 6; ++c)
      strain[q][c] = enhanced(c);
  }
}

}  // namespace railfe
