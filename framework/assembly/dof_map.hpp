#pragma once
/// \file
/// Degrees of freedom over a mesh partition, in one of two layouts:
/// - uniform: a fixed number per node, global DOF = dofs_per_node × global node + component, so
///   MueLu sees node blocks (solids with 3, beam models with 6);
/// - mixed: 3 translations at solid nodes, 6 (u_x, u_y, u_z, θ_x, θ_y, θ_z) at beam and body
///   nodes (DofMap::for_mesh()); global DOFs numbered node after node in global node order.
/// In both the owned map is a prefix of the overlapping one and the components of a node are
/// consecutive (local_dof(node, c) = local_dof(node, 0) + c).

#include <string>
#include <vector>

#include "framework/assembly/tpetra_types.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

/// Owned and overlapping (owned + ghost) DOF maps and the plan to move data between them.
class DofMap {
 public:
  /// Uniform layout: \p dofs_per_node DOFs at every node of \p partition (collective).
  /// \p partition must outlive the map.
  DofMap(const MeshPartition& partition, int dofs_per_node);
  /// Per-node layout: \p node_dofs[n] DOFs at global mesh node n (size Mesh::n_nodes(), the same
  /// on every rank; entries for nodes no element uses are ignored), collective. Falls back to the
  /// uniform layout when every used node has the same count. \p partition must outlive the map.
  DofMap(const MeshPartition& partition, const std::vector<int>& node_dofs);
  /// The layout a mesh asks for (collective): 6 DOFs at nodes of beam2, spring2, point_mass and
  /// rigid_link elements that no hex8 element uses, 3 at all others (solid nodes keep 3: springs,
  /// masses and rigid links acting on them act on their translations). Uniform (3 or 6) when every
  /// node has the same count. Throws InputError naming the node when a beam2 element shares a node
  /// with a hex8 element (a beam's rotations would have no unknowns there: tie the beam end to
  /// the solid face instead, see physics/common/solid_beam_ties.hpp).
  static DofMap for_mesh(const MeshPartition& partition);
  /// The per-node counts for_mesh() uses, for every global mesh node (0 for unused nodes).
  static std::vector<int> mesh_node_dofs(const Mesh& mesh);

  /// The mesh partition.
  const MeshPartition& partition() const { return *partition_; }
  /// Whether every node has the same number of DOFs.
  bool is_uniform() const { return dofs_per_node_ > 0; }
  /// DOFs per node of a uniform layout; throws std::logic_error for a mixed one (code that
  /// indexes dofs_per_node × node must not run on it: use local_dof() and dofs_of_node()).
  int dofs_per_node() const {
    if (dofs_per_node_ == 0)
      throw_mixed_layout("dofs_per_node()");
    return dofs_per_node_;
  }
  /// Throws std::logic_error naming \p who unless the layout is uniform with \p dofs_per_node.
  void require_uniform(int dofs_per_node, const std::string& who) const;
  /// Number of DOFs of local node \p node (3 or 6 in a mixed layout).
  int dofs_of_node(LocalIndex node) const {
    return dofs_per_node_ > 0 ? dofs_per_node_ : node_offsets_[node + 1] - node_offsets_[node];
  }
  /// Number of DOFs of global mesh node \p node (0 for a node no element uses in a mixed layout).
  int dofs_of_global_node(GlobalIndex node) const {
    return dofs_per_node_ > 0 ? dofs_per_node_
                              : static_cast<int>(global_offsets_[node + 1] - global_offsets_[node]);
  }
  /// The largest number of DOFs of a node (the count of a uniform layout).
  int max_dofs_per_node() const { return max_dofs_per_node_; }
  /// DOFs per node to give MueLu ("number of equations"): the count of a uniform layout, 1 for a
  /// mixed one (MueLu's node blocks must be of one size; it then aggregates scalar DOFs, which
  /// converges more slowly: prefer a direct solver for mixed models).
  int solver_dofs_per_node() const { return dofs_per_node_ > 0 ? dofs_per_node_ : 1; }
  /// DOFs owned by this rank (one-to-one over ranks).
  Teuchos::RCP<const TpetraMap> owned_map() const { return owned_map_; }
  /// DOFs of all local nodes, owned first (overlapping).
  Teuchos::RCP<const TpetraMap> overlap_map() const { return overlap_map_; }
  /// Plan from owned to overlapping vectors (use it reversed for overlap → owned sums).
  Teuchos::RCP<const TpetraImport> importer() const { return importer_; }
  /// Number of owned DOFs.
  LocalIndex n_owned_dofs() const {
    return dofs_per_node_ > 0 ? dofs_per_node_ * partition_->n_owned_nodes()
                              : node_offsets_[partition_->n_owned_nodes()];
  }
  /// Number of overlapping DOFs.
  LocalIndex n_overlap_dofs() const {
    return dofs_per_node_ > 0 ? dofs_per_node_ * partition_->n_local_nodes() : node_offsets_.back();
  }
  /// Total number of DOFs in the model.
  GlobalIndex n_global_dofs() const { return n_global_dofs_; }
  /// Local (owned or overlap) index of \p component of local node \p node (component <
  /// dofs_of_node(node), unchecked).
  LocalIndex local_dof(LocalIndex node, int component) const {
    return dofs_per_node_ > 0 ? dofs_per_node_ * node + component : node_offsets_[node] + component;
  }
  /// Global index of \p component of global mesh node \p node (component <
  /// dofs_of_global_node(node), unchecked): what constraints and messages name.
  GlobalIndex global_dof(GlobalIndex node, int component) const {
    return dofs_per_node_ > 0 ? dofs_per_node_ * node + component
                              : global_offsets_[node] + component;
  }
  /// "node N component c" for global DOF \p dof (see describe_dof()), in either layout.
  std::string describe(GlobalIndex dof) const;

  /// Copies owned values into \p overlap (ghost entries filled from their owners).
  void owned_to_overlap(const TpetraVector& owned, TpetraVector& overlap) const;
  /// Adds overlapping contributions into \p owned (which is overwritten).
  void overlap_to_owned_sum(const TpetraVector& overlap, TpetraVector& owned) const;

 private:
  void build_maps(const std::vector<GlobalIndex>& dofs, std::size_t n_owned);
  [[noreturn]] static void throw_mixed_layout(const std::string& who);

  const MeshPartition* partition_;
  int dofs_per_node_ = 0;  // 0 for a mixed layout
  int max_dofs_per_node_ = 0;
  GlobalIndex n_global_dofs_ = 0;
  std::vector<LocalIndex> node_offsets_;     // mixed: first local DOF of each local node, + end
  std::vector<GlobalIndex> global_offsets_;  // mixed: first global DOF of each mesh node, + end
  Teuchos::RCP<const TpetraMap> owned_map_;
  Teuchos::RCP<const TpetraMap> overlap_map_;
  Teuchos::RCP<const TpetraImport> importer_;
};

/// "node N component c" for global DOF \p dof with \p dofs_per_node unknowns per node (node
/// 1-based, as ParaView shows it; components x, y, z, then θx, θy, θz for rotations when there
/// are three or six, else numbered from 1), for messages.
std::string describe_dof(GlobalIndex dof, int dofs_per_node);

/// "node N component c" for component \p component (0-based; 3..5 are θx, θy, θz) of global
/// node \p node (0-based; shown 1-based).
std::string describe_node_component(GlobalIndex node, int component);

}  // namespace railfe
