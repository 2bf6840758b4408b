#pragma once
/// \file
/// The one-point hex8 with Flanagan–Belytschko hourglass control (docs/theory.md#explicit-
/// dynamics): mean gradients, hourglass vectors, and the element's linear stiffness. The explicit
/// kernel integrates it in time; statics uses its stiffness so that a static preload is in
/// equilibrium for an explicit run that starts from it.

#include "physics/elements/hex8.hpp"

namespace railfe {

/// Mean gradients b_a / V = (1/V) ∫ ∂N_a/∂X dV at [i × 8 + a] (exact with 2×2×2 points); they
/// make one-point elements pass the patch test on distorted meshes. Returns the volume V.
double hex8_mean_gradients(const double x[8][3], double gradient[24]);

/// The projections h_α · X_i of an element's reference coordinates \p x, at [α × 3 + i].
void hex8_hourglass_projections(const double x[8][3], double projection[12]);

/// The hourglass vectors γ_α = h_α − Σ_i (h_α · X_i) ∇₀N̄_i at [α × 8 + a], from
/// hex8_hourglass_projections() and hex8_mean_gradients(); blind to every linear field.
void hex8_hourglass_vectors(const double* projection, const double* gradient, double gamma[32]);

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
