#pragma once
/// \file
/// The enhanced-assumed-strain hexahedron (Simo & Rifai 1990, with the nine modes of Andelfinger
/// & Ramm 1993): the trilinear hex8 of hex8.hpp plus nine element-internal strain modes that are
/// linear in the reference coordinates, condensed out at element level. The modes give the
/// element the bending and near-incompressible response that the fully integrated hex8 locks
/// against, while the nodal DOFs, loads and mass stay those of the trilinear element.

#include "physics/elements/hex8.hpp"

namespace railfe {

/// Condensed stiffness matrix (24 × 24, row-major) of the enhanced-strain hex8 with node
/// coordinates \p x: K = K_uu − K_uα K_αα⁻¹ K_αu with 2×2×2 Gauss points. The enhanced strains
/// are mapped with the centre Jacobian and scaled by det J₀ / det J, so they integrate to zero over
/// any element and the element passes the patch test on distorted meshes. They vanish at the
/// element centre, so hex8_centre_stress() gives this element's centre stress as well.
void hex8_enhanced_strain_stiffness(const double x[8][3], const LameConstants& material,
                                    double* stiffness);

/// The enhanced part of the strain (engineering shear, order xx, yy, zz, xy, yz, zx) at the 2×2×2
/// Gauss points (in kHex8NodeReference order) for nodal displacements \p u (24): G α with the
/// internal parameters α recovered from u as the condensation eliminated them. Add it to the
/// compatible strain B u for this element's strain.
void hex8_enhanced_strains(const double x[8][3], const double* u, const LameConstants& material,
                           double strain[8][6]);

}  // namespace railfe
