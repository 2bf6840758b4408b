#pragma once
/// \file
/// The trilinear hexahedron (hex8): stiffness for isotropic linear elasticity with 2×2×2 Gauss
/// integration, consistent body and surface loads, and stress at the centre. Node order and face
/// numbering follow Exodus II (framework/mesh/hex8_topology.hpp). DOFs are node-major:
/// (u_x, u_y, u_z) of node 0, then node 1, ...

namespace railfe {

/// Lamé constants of an isotropic linear elastic solid (Pa).
struct LameConstants {
  double lambda = 0;  ///< first Lamé constant λ
  double mu = 0;      ///< shear modulus μ
};

/// λ and μ from Young's modulus \p young (Pa) and Poisson's ratio \p poisson (< 0.5).
LameConstants lame_constants(double young, double poisson);

/// Stiffness matrix (24 × 24, row-major) of a hex8 with node coordinates \p x, fully integrated.
/// Exact for any parallelepiped; like every fully integrated hex8 it locks in thin bending
/// (several elements through the thickness are needed).
void hex8_stiffness(const double x[8][3], const LameConstants& material, double* stiffness);

/// Consistent nodal forces (24) of a uniform body force density \p b (N/m³): f = ∫ Nᵀ b dV.
void hex8_body_force(const double x[8][3], const double b[3], double* forces);

/// Mass matrix (24 × 24, row-major) of density \p density (kg/m³): consistent,
/// M = ∫ ρ NᵀN dV with 2×2×2 Gauss points (exact for parallelepipeds), or, when \p lumped, its
/// row sums on the diagonal (positive for hex8, and the total mass is kept exactly).
void hex8_mass(const double x[8][3], double density, bool lumped, double* mass);

/// Volume of the element (m³).
double hex8_volume(const double x[8][3]);

/// Stress at the element centre (Pa, order xx, yy, zz, xy, yz, zx: the Exodus/ParaView
/// symmetric-tensor order) from nodal displacements \p u (24). Exact when the displacement field is
/// linear (the patch test).
void hex8_centre_stress(const double x[8][3], const double* u, const LameConstants& material,
                        double stress[6]);

/// Stress like hex8_centre_stress() at the point where the reference shape-function derivatives
/// are \p dN_ref [3][8] (∂N_a/∂ξ_k), e.g. a Gauss point of hex8_gauss_table().
void hex8_point_stress(const double x[8][3], const double* u, const LameConstants& material,
                       const double dN_ref[3][8], double stress[6]);

/// Consistent nodal forces (4 face nodes × 3, in kHex8FaceNodes order) of a uniform traction
/// \p traction (Pa) on face \p face: f = ∫ Nᵀ t dA (2×2 Gauss).
void hex8_face_traction(const double x[8][3], int face, const double traction[3],
                        double forces[12]);

/// Like hex8_face_traction() for a pressure \p pressure (Pa) pushing against the outward normal
/// (t = −p n, with n evaluated at each Gauss point so curved faces are handled).
void hex8_face_pressure(const double x[8][3], int face, double pressure, double forces[12]);

/// Area of face \p face (m²).
double hex8_face_area(const double x[8][3], int face);

}  // namespace railfe
