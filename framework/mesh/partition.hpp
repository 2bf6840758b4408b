#pragma once
/// \file
/// The part of the mesh one rank computes on: its elements (chosen by a partitioner), the nodes
/// they touch (owned first, then ghosts owned by other ranks) and local connectivity.

#include <memory>
#include <string>
#include <vector>

#include "framework/base/parallel.hpp"
#include "framework/base/types.hpp"
#include "framework/mesh/mesh.hpp"

namespace railfe {

/// How elements are split over ranks.
enum class PartitionMethod {
  multijagged,  ///< Zoltan2 multi-jagged geometric partitioning of element centroids
  rcb,          ///< Zoltan2 recursive coordinate bisection of element centroids
  block         ///< contiguous ranges of global element numbers (for debugging only)
};

/// The elements of one block that this rank computes.
struct LocalBlock {
  int block = 0;                         ///< index into Mesh::blocks
  std::vector<GlobalIndex> elements;     ///< block-local element indices, ascending
  std::vector<LocalIndex> offsets{0};    ///< local element e's nodes: connectivity[offsets[e]..]
  std::vector<LocalIndex> connectivity;  ///< local node indices
  /// Number of local elements.
  LocalIndex n_elements() const { return static_cast<LocalIndex>(elements.size()); }
};

/// A rank's share of a mesh. A node is owned by the lowest rank whose elements touch it; nodes
/// that no element touches belong to no rank.
class MeshPartition {
 public:
  /// Splits \p mesh over the ranks of \p comm (collective). \p mesh must outlive the partition.
  MeshPartition(const Mesh& mesh, const Communicator& comm, PartitionMethod method);

  /// The whole mesh.
  const Mesh& mesh() const { return *mesh_; }
  /// The communicator it was split over.
  const Communicator& comm() const { return comm_; }
  /// Nodes this rank owns (local indices 0 .. n_owned_nodes()-1).
  LocalIndex n_owned_nodes() const { return n_owned_nodes_; }
  /// Owned plus ghost nodes.
  LocalIndex n_local_nodes() const { return static_cast<LocalIndex>(global_nodes_.size()); }
  /// Global index of local node \p node.
  GlobalIndex global_node(LocalIndex node) const { return global_nodes_[node]; }
  /// Global indices of all local nodes (owned first).
  const std::vector<GlobalIndex>& global_nodes() const { return global_nodes_; }
  /// Local index of global node \p node, or -1 if this rank does not hold it.
  LocalIndex local_node(GlobalIndex node) const { return local_of_global_[node]; }
  /// Coordinates of local node \p node (a local copy, for locality in element loops).
  const double* coordinates(LocalIndex node) const { return &local_coordinates_[3 * node]; }
  /// This rank's elements, block by block (blocks with no local element are left out).
  const std::vector<LocalBlock>& blocks() const { return blocks_; }
  /// Rank computing each global element.
  const std::vector<int>& element_ranks() const { return element_ranks_; }
  /// Rank owning each global node (-1 for nodes no element uses).
  const std::vector<int>& node_ranks() const { return node_ranks_; }
  /// Number of local elements over all blocks.
  LocalIndex n_local_elements() const;
  /// Local index of the first element of blocks()[\p local_block] when the local elements of all
  /// blocks are numbered one after another.
  LocalIndex first_local_element(std::size_t local_block) const {
    return first_local_elements_[local_block];
  }
  /// Global number of nodes that some element uses (the nodes that carry unknowns).
  GlobalIndex n_active_nodes() const { return n_active_nodes_; }
  /// Name of the method used.
  const std::string& method_name() const { return method_name_; }

 private:
  void assign_elements(PartitionMethod method);
  void build_local_numbering();

  const Mesh* mesh_;
  Communicator comm_;
  std::string method_name_;
  std::vector<int> element_ranks_;
  std::vector<int> node_ranks_;
  std::vector<GlobalIndex> global_nodes_;
  std::vector<LocalIndex> local_of_global_;
  std::vector<double> local_coordinates_;
  LocalIndex n_owned_nodes_ = 0;
  GlobalIndex n_active_nodes_ = 0;
  std::vector<LocalBlock> blocks_;
  std::vector<LocalIndex> first_local_elements_;
};

/// The owned local nodes of node set \p set of \p partition ("" = every owned node): what a
/// condition on a node set acts on, on this rank.
std::vector<LocalIndex> owned_set_nodes(const MeshPartition& partition, const std::string& set);

}  // namespace railfe
