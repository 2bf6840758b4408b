#pragma once
/// \file
/// Pairs the nodes of one node set with the nearest nodes of another: how a spring between two
/// node sets (a rail pad between a rail seat and a sleeper's top) joins meshes whose nodes do
/// not match. Each node of the first set gets its own spring to the nearest node of the second,
/// so a seat keeps its spread (and the pad its resistance to rocking) whatever the other mesh.

#include <string>
#include <utility>
#include <vector>

#include "framework/base/types.hpp"

namespace railfe {

class MeshPartition;
class Mesh;

/// Throws InputError naming \p deck and \p path when node sets \p from and \p to share a node
/// (a spring between them would tie a node to itself): a check before anything runs.
void check_disjoint_node_sets(const Mesh& mesh, const std::string& from, const std::string& to,
                              const std::string& deck, const std::string& path);

/// Each node of \p from that an element uses, with the node of \p to nearest to it (global
/// indices, in the order of \p from). The same on every rank. Throws InputError naming \p deck
/// and \p path when either set has no node in an element or the sets share a node.
std::vector<std::pair<GlobalIndex, GlobalIndex>> nearest_node_pairs(const MeshPartition& partition,
                                                                    const std::string& from,
                                                                    const std::string& to,
                                                                    const std::string& deck,
                                                                    const std::string& path);

}  // namespace railfe
