#pragma once
/// \file
/// Stresses at named points of a solid mesh (the statics probes): nodal stresses recovered from
/// the elements around each node, for benchmarks that ask for a stress at a boundary point.

#include <vector>

#include "framework/mesh/partition.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

/// Stress (Pa, 6 per set: xx, yy, zz, xy, yz, zx) of each node set in \p node_sets (global node
/// numbers), from displacements \p u_overlap over the overlapping DOFs (collective). At each node:
/// the mean over the hex8 elements around it of their corner stress (hex8_corner_stresses(): the
/// Gauss-point stresses extrapolated to the node, in the formulation of the element's material, or
/// the centre stress when \p one_point); then the mean over the set's nodes. Nodes that no hex8
/// touches are left out; a set without any such node gets zeros.
std::vector<double> node_set_stresses(const MeshPartition& partition,
                                      const MaterialTable& materials, const double* u_overlap,
                                      const std::vector<std::vector<GlobalIndex>>& node_sets,
                                      bool one_point);

}  // namespace railfe
