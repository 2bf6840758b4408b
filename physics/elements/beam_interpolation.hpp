#pragma once
/// \file
/// Displacement of a point inside a beam element from its 12 nodal DOFs, on the element's own
/// interpolation (beam_element.hpp): linear for the axial displacement, and for the transverse
/// ones the exact Timoshenko functions of timoshenko_bending.hpp with the element's shear
/// parameters, which use the nodal rotations and reduce to Hermite cubics for an Euler–Bernoulli
/// beam. Used by moving constraints (the direct method) and moving loads: the load vector
/// Nᵀ P is then work-consistent with the element's mass and stiffness.

#include <Eigen/Dense>

#include "physics/elements/beam_element.hpp"

namespace railfe {

/// The 3 × 12 matrix N with u(ξ) = N u_e: global translations at ξ = x / L ∈ [0, 1] from the
/// element's global DOFs (node a: u_x, u_y, u_z, θ_x, θ_y, θ_z, then node b).
Eigen::Matrix<double, 3, 12> beam_translation_interpolation(const BeamElement& beam, double xi);

}  // namespace railfe
