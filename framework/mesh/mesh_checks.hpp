#pragma once
/// \file
/// Checks that a mesh can be computed on: node indices in range, finite coordinates, sets that
/// point at existing entities, and no inverted or degenerate solid elements.

#include <string>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// Throws InputError naming the mesh source and the first bad entity (1-based element and node
/// ids, as ParaView shows them). A hex8 element is inverted when the Jacobian determinant is
/// negative at one of its 2×2×2 integration points and degenerate when it is nearly zero there
/// (quality below 1e-8): both make its stiffness meaningless. Negative Jacobians at corners only
/// are accepted, as in MacNeal and Harder's standard patch, whose element 2 has one.
void check_mesh(const Mesh& mesh);

/// Volume of the hex8 elements of \p block (m³), by 2×2×2 Gauss quadrature: exact for
/// trilinear hexahedra. For tests and summaries; other element types count nothing.
double block_volume(const Mesh& mesh, const ElementBlock& block);

/// Smallest Jacobian determinant of a hex8 element at its 2×2×2 integration points, divided by
/// (longest edge / 2)³: 1 for a cube, <= 0 for an inverted element.
double hex8_jacobian_quality(const double x[8][3]);

}  // namespace railfe
