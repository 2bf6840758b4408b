#pragma once
/// \file
/// Stresses at the corners of a hex8, for stresses at points of the boundary (where benchmarks ask
/// for them): the 2×2×2 Gauss-point stresses extrapolated trilinearly to the nodes, as commercial
/// codes report nodal stresses before averaging between elements.

#include "physics/elements/hex8.hpp"

namespace railfe {

/// How an element's strain is formed (the stiffness it was assembled with).
enum class Hex8Strain {
  full,             ///< compatible strain B u at each Gauss point
  enhanced_strain,  ///< B u plus the condensed enhanced strains (hex8_enhanced_strain.hpp)
  centre            ///< the centre strain everywhere (the one-point hex8)
};

/// Stress (Pa, order xx, yy, zz, xy, yz, zx) at each of the eight nodes of the element with node
/// coordinates \p x and nodal displacements \p u (24): Gauss-point stresses of the formulation
/// \p strain, extrapolated to the corners with the trilinear field through the eight points. Exact
/// for a linear displacement field in every formulation (the patch test).
void hex8_corner_stresses(const double x[8][3], const double* u, const LameConstants& material,
                          Hex8Strain strain, double stress[8][6]);

}  // namespace railfe
