#pragma once
/// \file
/// Checks that a mesh can be computed on: node indices in range, finite coordinates, sets that
/// point at existing entities, and no inverted or degenerate solid elements.

#include <string>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// Throws InputError naming the mesh source and the first bad entity (1-based element and node
/// ids, as ParaView shows them). A hex8 element is inverted when the Jacobian determinant at a
/// corner is negative and degenerate when it is below 1e-10 of the element's size cubed.
void check_mesh(const Mesh& mesh);

/// Smallest corner Jacobian determinant of a hex8 element with nodes \p x (8 × xyz), divided by
/// the cube of its longest corner edge: 1 for a cube, <= 0 when inverted or degenerate.
double hex8_scaled_corner_jacobian(const double x[8][3]);

}  // namespace railfe
