#pragma once
/// \file
/// Bending of a two-node Timoshenko beam in one plane, on the exact interpolation of the
/// homogeneous static equations (Przemieniecki, Theory of Matrix Structural Analysis, 1968,
/// chapters 5 and 11; the same functions in Friedman & Kosmatka, Computers & Structures 47, 1993,
/// 473–481). DOFs (w_a, θ_a, w_b, θ_b): deflection w and section rotation θ, with θ = dw/dx in
/// the absence of shear. φ = 12 E I / (G A_s L²) is the shear deformation parameter; φ = 0 is the
/// Euler–Bernoulli beam (cubic Hermite interpolation).

#include <Eigen/Dense>

namespace railfe {

/// Interpolation of deflection and rotation at one point of the element.
struct TimoshenkoShape {
  Eigen::Vector4d deflection;  ///< N_w: w(ξ) = N_w · (w_a, θ_a, w_b, θ_b)
  Eigen::Vector4d rotation;    ///< N_θ: θ(ξ) = N_θ · (w_a, θ_a, w_b, θ_b)
};

/// Shear deformation parameter φ = 12 \p bending_stiffness / (\p shear_stiffness L²) of an
/// element of \p length (E I in N m², G A_s in N); 0 for an infinite shear stiffness.
double shear_parameter(double bending_stiffness, double shear_stiffness, double length);

/// Shape functions at ξ = x / L ∈ [0, 1] of an element of \p length with parameter \p phi.
/// Exact for an element loaded at its ends only; they reproduce the rigid-body modes.
TimoshenkoShape timoshenko_shape(double xi, double phi, double length);

/// Bending stiffness (4 × 4) for bending stiffness \p bending_stiffness = E I (N m²):
/// E I / ((1+φ) L³) [12, 6L, −12, 6L; 6L, (4+φ)L², −6L, (2−φ)L²; ...].
Eigen::Matrix4d timoshenko_bending_stiffness(double bending_stiffness, double phi, double length);

/// Consistent mass (4 × 4) ∫ (ρA N_wᵀ N_w + ρI N_θᵀ N_θ) dx of the shape functions above, for
/// mass per length \p mass_per_length = ρA (kg/m) and rotary inertia per length
/// \p rotary_per_length = ρI (kg m); Gauss-integrated exactly (the integrand is of degree 6).
Eigen::Matrix4d timoshenko_bending_mass(double mass_per_length, double rotary_per_length,
                                        double phi, double length);

}  // namespace railfe
