#include "framework/mesh/nearest_nodes.hpp"

#include <algorithm>
#include <limits>

#include "framework/base/error.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

namespace {

// The set's nodes that carry unknowns (some element uses them).
std::vector<GlobalIndex> active_nodes(const MeshPartition& partition, const std::string& set,
                                      const std::string& deck, const std::string& path) {
  std::vector<GlobalIndex> nodes;
  for (GlobalIndex node : partition.mesh().node_set(set, deck, path).nodes)
    if (partition.node_ranks()[node] >= 0)
      nodes.push_back(node);
  if (nodes.empty())
    throw_input_error(deck, path, "names node set '" + set + "', which has no node in an element",
                      "a node set of nodes that elements use");
  return nodes;
}

}  // namespace

void check_disjoint_node_sets(const Mesh& mesh, const std::string& from, const std::string& to,
                              const std::string& deck, const std::string& path) {
  std::vector<GlobalIndex> targets = mesh.node_set(to, deck, path).nodes;
  std::sort(targets.begin(), targets.end());
  for (GlobalIndex source : mesh.node_set(from, deck, path).nodes)
    if (std::binary_search(targets.begin(), targets.end(), source))
      throw_input_error(deck, path,
                        "joins node sets '" + from + "' and '" + to + "', which share node " +
                            std::to_string(source + 1),
                        "two node sets with no node in common");
}

std::vector<std::pair<GlobalIndex, GlobalIndex>> nearest_node_pairs(const MeshPartition& partition,
                                                                    const std::string& from,
                                                                    const std::string& to,
                                                                    const std::string& deck,
                                                                    const std::string& path) {
  const std::vector<GlobalIndex> sources = active_nodes(partition, from, deck, path);
  const std::vector<GlobalIndex> targets = active_nodes(partition, to, deck, path);
  const std::vector<double>& x = partition.mesh().coordinates;
  std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;
  pairs.reserve(sources.size());
  check_disjoint_node_sets(partition.mesh(), from, to, deck, path);
  for (GlobalIndex source : sources) {
    double nearest = std::numeric_limits<double>::infinity();
    GlobalIndex match = -1;
    // The sets are a seat's or a sleeper's nodes (hundreds): a plain scan is quick enough.
    for (GlobalIndex target : targets) {
      double distance = 0;
      for (int d = 0; d < 3; ++d)
        distance +=
            (x[3 * target + d] - x[3 * source + d]) * (x[3 * target + d] - x[3 * source + d]);
      if (distance < nearest) {
        nearest = distance;
        match = target;
      }
    }
    pairs.emplace_back(source, match);
  }
  return pairs;
}

}  // namespace railfe
