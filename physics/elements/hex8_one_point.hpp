#pragma once
/// \file
/// The one-point hex8 with Flanagan–Belytschko hourglass control (docs/theory.md#explicit-
/// dynamics): mean gradients, hourglass vectors, and the element's linear stiffness. The explicit
/// kernel integrates it in time; statics uses its stiffness so that a static preload is in
/// equilibrium for an explicit run that starts from it.

#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8.hpp"

namespace railfe {

/// The hourglass base vectors h_α at the nodes, [α][a]: ξη, ηζ, ζξ and ξηζ of each node's
/// reference coordinates.
struct Hex8HourglassBase {
  double h[4][8] = {};  ///< h_α at node a
  constexpr Hex8HourglassBase() {
    for (int a = 0; a < 8; ++a) {
      const double* r = kHex8NodeReference[a];
      h[0][a] = r[0] * r[1];
      h[1][a] = r[1] * r[2];
      h[2][a] = r[2] * r[0];
      h[3][a] = r[0] * r[1] * r[2];
    }
  }
};
/// The one table of hourglass base vectors.
inline constexpr Hex8HourglassBase kHex8HourglassBase{};

/// Mean gradients b_a / V = (1/V) ∫ ∂N_a/∂X dV at [i × 8 + a] (exact with 2×2×2 points); they
/// make one-point elements pass the patch test on distorted meshes. Returns the volume V.
double hex8_mean_gradients(const double x[8][3], double gradient[24]);

/// The projections h_α · X_i of an element's reference coordinates \p x, at [α × 3 + i].
void hex8_hourglass_projections(const double x[8][3], double projection[12]);

/// The hourglass vectors γ_α = h_α − Σ_i (h_α · X_i) ∇₀N̄_i at [α × 8 + a], from
/// hex8_hourglass_projections() and hex8_mean_gradients(); blind to every linear field. \p T is
/// double for one element, or a SIMD lane type (physics/explicit/solid_lanes.hpp) for a batch.
template <class T>
inline void hex8_hourglass_vectors(const T* projection, const T* gradient, T gamma[32]) {
  for (int alpha = 0; alpha < 4; ++alpha) {
    const T* p = projection + 3 * alpha;
    for (int a = 0; a < 8; ++a)
      gamma[alpha * 8 + a] = kHex8HourglassBase.h[alpha][a] - p[0] * gradient[a] -
                             p[1] * gradient[8 + a] - p[2] * gradient[16 + a];
  }
}

/// C of the stiffness hourglass form, κ (λ + 2μ) V Σ|∇₀N̄|² / 3, for mean gradients \p gradient
/// of an element of volume \p volume.
double hex8_hourglass_stiffness(const double* gradient, double volume, const LameConstants& lame,
                                double kappa);

/// The 24 × 24 row-major stiffness of the one-point element at small strain: V B̄ᵀ D B̄ plus the
/// hourglass stiffness C Σ_α γ_α γ_αᵀ ⊗ I (κ = \p kappa), DOFs node-major. It is the tangent of
/// the explicit kernel's internal force (stiffness hourglass form) at zero displacement.
void hex8_one_point_stiffness(const double x[8][3], const LameConstants& lame, double kappa,
                              double* stiffness);

}  // namespace railfe
