#pragma once
/// \file
/// Simply supported beam bridges built in C++ for the direct method's verification and
/// benchmarks (the deck-driven structure is the implicit module's): a grillage of
/// longitudinal beams joined by transverse beams at every station, one line being a single
/// beam. Sparse M and K over the free DOFs, and the first line as the path vehicles travel.

#include <Eigen/Sparse>

#include <vector>

#include "physics/implicit/moving_contact.hpp"

namespace railfe {

/// The assembled bridge.
struct BridgeModel {
  Eigen::SparseMatrix<double> mass;       ///< M over the free DOFs
  Eigen::SparseMatrix<double> stiffness;  ///< K over the free DOFs
  std::vector<PathElement> path;          ///< the elements of line 0, from x = 0 to the span
  long midspan_vertical = -1;             ///< unknown of u_z at midspan of line 0
  std::size_t n_unknowns = 0;             ///< number of free DOFs
};

/// \p n_lines longitudinal lines \p spacing apart (along y) of \p n_elements beams over
/// \p span (along x, \p n_elements even), joined at every station by transverse beams of the
/// same section when n_lines > 1. Every line rests on pins at x = 0 (u_x, u_y, u_z, θ_x fixed)
/// and rollers at x = span (u_y, u_z, θ_x fixed).
BridgeModel simply_supported_bridge(double span, int n_elements, int n_lines, double spacing,
                                    const BeamMaterial& material, const BeamSection& section,
                                    BeamMass mass_kind);

}  // namespace railfe
