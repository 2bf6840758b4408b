#include "framework/assembly/dof_map.hpp"

#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace railfe {

DofMap::DofMap(const MeshPartition& partition, int dofs_per_node)
    : partition_(&partition), dofs_per_node_(dofs_per_node) {
  std::vector<GlobalIndex> dofs;
  dofs.reserve(static_cast<std::size_t>(dofs_per_node) * partition.n_local_nodes());
  for (LocalIndex node = 0; node < partition.n_local_nodes(); ++node) {
    for (int c = 0; c < dofs_per_node; ++c) {
      dofs.push_back(dofs_per_node * partition.global_node(node) + c);
    }
  }
  const auto comm = partition.comm().teuchos();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const std::size_t n_owned = static_cast<std::size_t>(dofs_per_node) * partition.n_owned_nodes();
  owned_map_ = Teuchos::rcp(
      new TpetraMap(invalid, Teuchos::ArrayView<const GlobalIndex>(dofs.data(), n_owned), 0, comm));
  overlap_map_ = Teuchos::rcp(new TpetraMap(
      invalid, Teuchos::ArrayView<const GlobalIndex>(dofs.data(), dofs.size()), 0, comm));
  importer_ = Teuchos::rcp(new TpetraImport(owned_map_, overlap_map_));
}

void DofMap::owned_to_overlap(const TpetraVector& owned, TpetraVector& overlap) const {
  overlap.doImport(owned, *importer_, Tpetra::INSERT);
}

void DofMap::overlap_to_owned_sum(const TpetraVector& overlap, TpetraVector& owned) const {
  owned.putScalar(0.0);
  owned.doExport(overlap, *importer_, Tpetra::ADD);
}

std::string describe_dof(GlobalIndex dof, int dofs_per_node) {
  static const char* kAxes = "xyz";
  const int component = static_cast<int>(dof % dofs_per_node);
  const std::string name =
      dofs_per_node == 3 ? std::string(1, kAxes[component]) : std::to_string(component + 1);
  return "node " + std::to_string(dof / dofs_per_node + 1) + " component " + name;
}

}  // namespace railfe
