#pragma once
/// \file
/// The model every step of a run works on: the deck, the mesh and its partition, the validated
/// top-level sections (such as Materials), DOF maps and the fields steps hand to each other
/// (a static preload's displacement becomes the start of an explicit run).

#include <map>
#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/deck.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

/// Shared state of one run.
class Model {
 public:
  /// Takes the validated \p deck and the checked \p mesh, and partitions the mesh (collective).
  Model(Deck deck, Mesh mesh, const Communicator& comm, PartitionMethod method);

  /// The deck.
  const Deck& deck() const { return deck_; }
  /// The whole mesh (identical on every rank).
  const Mesh& mesh() const { return *mesh_; }
  /// This rank's part of the mesh.
  const MeshPartition& partition() const { return *partition_; }
  /// The communicator of the run.
  const Communicator& comm() const { return partition_->comm(); }
  /// How the mesh was split over ranks (for a step that partitions a part of it again).
  PartitionMethod partition_method() const { return method_; }
  /// A validated top-level section of the deck (e.g. "Materials"); throws std::logic_error if the
  /// deck has none (owners declare whether their section is required).
  const Teuchos::ParameterList& section(const std::string& name) const;
  /// Whether the deck has the section.
  bool has_section(const std::string& name) const;
  /// The DOF map with \p dofs_per_node unknowns per node, made on first use (collective then).
  const DofMap& dofs(int dofs_per_node);
  /// The DOF map the mesh asks for (DofMap::for_mesh(): 3 at solid nodes, 6 at beam and body
  /// nodes), made on first use (collective then).
  const DofMap& mesh_dofs();
  /// Stores a field under \p name (replacing one of the same name).
  void set_field(const std::string& name, Teuchos::RCP<TpetraVector> field);
  /// The field called \p name, or null.
  Teuchos::RCP<TpetraVector> field(const std::string& name) const;

 private:
  Deck deck_;
  std::unique_ptr<Mesh> mesh_;
  std::unique_ptr<MeshPartition> partition_;
  PartitionMethod method_;
  std::map<int, std::unique_ptr<DofMap>> dof_maps_;  // by DOFs per node
  std::unique_ptr<DofMap> mesh_dofs_;
  std::map<std::string, Teuchos::RCP<TpetraVector>> fields_;
};

}  // namespace railfe
