#pragma once
/// \file
/// Degrees of freedom over a mesh partition: a fixed number per node, global DOF =
/// dofs_per_node × global node + component, so MueLu sees node blocks and the owned map is a
/// prefix of the overlapping one.

#include <string>

#include "framework/assembly/tpetra_types.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

/// Owned and overlapping (owned + ghost) DOF maps and the plan to move data between them.
class DofMap {
 public:
  /// DOFs for the nodes of \p partition (collective). \p partition must outlive the map.
  DofMap(const MeshPartition& partition, int dofs_per_node);

  /// The mesh partition.
  const MeshPartition& partition() const { return *partition_; }
  /// DOFs per node.
  int dofs_per_node() const { return dofs_per_node_; }
  /// DOFs owned by this rank (one-to-one over ranks).
  Teuchos::RCP<const TpetraMap> owned_map() const { return owned_map_; }
  /// DOFs of all local nodes, owned first (overlapping).
  Teuchos::RCP<const TpetraMap> overlap_map() const { return overlap_map_; }
  /// Plan from owned to overlapping vectors (use it reversed for overlap → owned sums).
  Teuchos::RCP<const TpetraImport> importer() const { return importer_; }
  /// Number of owned DOFs.
  LocalIndex n_owned_dofs() const { return dofs_per_node_ * partition_->n_owned_nodes(); }
  /// Number of overlapping DOFs.
  LocalIndex n_overlap_dofs() const { return dofs_per_node_ * partition_->n_local_nodes(); }
  /// Total number of DOFs in the model.
  GlobalIndex n_global_dofs() const { return dofs_per_node_ * partition_->n_active_nodes(); }
  /// Local (owned or overlap) index of \p component of local node \p node.
  LocalIndex local_dof(LocalIndex node, int component) const {
    return dofs_per_node_ * node + component;
  }

  /// Copies owned values into \p overlap (ghost entries filled from their owners).
  void owned_to_overlap(const TpetraVector& owned, TpetraVector& overlap) const;
  /// Adds overlapping contributions into \p owned (which is overwritten).
  void overlap_to_owned_sum(const TpetraVector& overlap, TpetraVector& owned) const;

 private:
  const MeshPartition* partition_;
  int dofs_per_node_;
  Teuchos::RCP<const TpetraMap> owned_map_;
  Teuchos::RCP<const TpetraMap> overlap_map_;
  Teuchos::RCP<const TpetraImport> importer_;
};

/// "node N component c" for global DOF \p dof with \p dofs_per_node unknowns per node (node
/// 1-based, as ParaView shows it; components x, y, z when there are three), for messages.
std::string describe_dof(GlobalIndex dof, int dofs_per_node);

}  // namespace railfe
