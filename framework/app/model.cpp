#include "framework/app/model.hpp"

#include <stdexcept>

#include <Tpetra_Vector.hpp>

namespace railfe {

Model::Model(Deck deck, Mesh mesh, const Communicator& comm, PartitionMethod method)
    : deck_(std::move(deck)), mesh_(std::make_unique<Mesh>(std::move(mesh))), method_(method) {
  partition_ = std::make_unique<MeshPartition>(*mesh_, comm, method);
}

const Teuchos::ParameterList& Model::section(const std::string& name) const {
  if (!deck_.parameters->isSublist(name)) {
    throw std::logic_error("railfe: deck has no section '" + name + "'");
  }
  return deck_.parameters->sublist(name);
}

bool Model::has_section(const std::string& name) const {
  return deck_.parameters->isSublist(name);
}

const DofMap& Model::dofs(int dofs_per_node) {
  auto& map = dof_maps_[dofs_per_node];
  if (!map)
    map = std::make_unique<DofMap>(*partition_, dofs_per_node);
  return *map;
}

const DofMap& Model::mesh_dofs() {
  if (!mesh_dofs_)
    mesh_dofs_ = std::make_unique<DofMap>(DofMap::for_mesh(*partition_));
  return *mesh_dofs_;
}

void Model::set_field(const std::string& name, Teuchos::RCP<TpetraVector> field) {
  fields_[name] = std::move(field);
}

Teuchos::RCP<TpetraVector> Model::field(const std::string& name) const {
  auto it = fields_.find(name);
  return it == fields_.end() ? Teuchos::null : it->second;
}

}  // namespace railfe
