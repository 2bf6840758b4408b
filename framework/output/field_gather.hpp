#pragma once
/// \file
/// Collecting distributed nodal and element values on rank 0 in global mesh order, for files.

#include <vector>

#include "framework/mesh/partition.hpp"

namespace railfe {

/// Gathers \p owned_values (n_owned_nodes × \p components, node-major) into one array per
/// component over all mesh nodes, on rank 0 (empty elsewhere). Nodes no element uses get 0.
std::vector<std::vector<double>> gather_node_field(const MeshPartition& partition,
                                                   const std::vector<double>& owned_values,
                                                   int components);

/// Gathers \p local_values (one per local element, in partition block order, × \p components)
/// into one array per component over all mesh elements in global order, on rank 0.
std::vector<std::vector<double>> gather_element_field(const MeshPartition& partition,
                                                      const std::vector<double>& local_values,
                                                      int components);

}  // namespace railfe
