#include "framework/assembly/dof_map.hpp"

#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <stdexcept>

#include "framework/base/error.hpp"

namespace railfe {

DofMap::DofMap(const MeshPartition& partition, int dofs_per_node)
    : partition_(&partition), dofs_per_node_(dofs_per_node), max_dofs_per_node_(dofs_per_node) {
  if (dofs_per_node <= 0)
    throw std::logic_error("railfe: DofMap: dofs_per_node must be positive");
  std::vector<GlobalIndex> dofs;
  dofs.reserve(static_cast<std::size_t>(dofs_per_node) * partition.n_local_nodes());
  for (LocalIndex node = 0; node < partition.n_local_nodes(); ++node) {
    for (int c = 0; c < dofs_per_node; ++c) {
      dofs.push_back(dofs_per_node * partition.global_node(node) + c);
    }
  }
  n_global_dofs_ = dofs_per_node * partition.n_active_nodes();
  build_maps(dofs, static_cast<std::size_t>(dofs_per_node) * partition.n_owned_nodes());
}

DofMap::DofMap(const MeshPartition& partition, const std::vector<int>& node_dofs)
    : partition_(&partition) {
  const Mesh& mesh = partition.mesh();
  if (node_dofs.size() != static_cast<std::size_t>(mesh.n_nodes()))
    throw std::logic_error("railfe: DofMap: one DOF count per mesh node expected");
  // Global numbering from the replicated mesh: every rank computes the same offsets. Nodes no
  // element uses (no owner) carry no DOFs.
  const std::vector<int>& owners = partition.node_ranks();
  global_offsets_.assign(node_dofs.size() + 1, 0);
  int smallest = 0;
  for (std::size_t n = 0; n < node_dofs.size(); ++n) {
    const int count = owners[n] < 0 ? 0 : node_dofs[n];
    if (owners[n] >= 0 && count <= 0)
      throw std::logic_error("railfe: DofMap: a used node needs at least one DOF");
    if (count > 0) {
      smallest = smallest == 0 ? count : std::min(smallest, count);
      max_dofs_per_node_ = std::max(max_dofs_per_node_, count);
    }
    global_offsets_[n + 1] = global_offsets_[n] + count;
  }
  if (smallest == max_dofs_per_node_) {  // one count everywhere: the uniform layout
    *this = DofMap(partition, std::max(smallest, 1));
    return;
  }
  n_global_dofs_ = global_offsets_.back();
  node_offsets_.assign(partition.n_local_nodes() + 1, 0);
  std::vector<GlobalIndex> dofs;
  for (LocalIndex node = 0; node < partition.n_local_nodes(); ++node) {
    const GlobalIndex global = partition.global_node(node);
    const int count = static_cast<int>(global_offsets_[global + 1] - global_offsets_[global]);
    node_offsets_[node + 1] = node_offsets_[node] + count;
    for (int c = 0; c < count; ++c)
      dofs.push_back(global_offsets_[global] + c);
  }
  build_maps(dofs, static_cast<std::size_t>(node_offsets_[partition.n_owned_nodes()]));
}

void DofMap::build_maps(const std::vector<GlobalIndex>& dofs, std::size_t n_owned) {
  const auto comm = partition_->comm().teuchos();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  owned_map_ = Teuchos::rcp(
      new TpetraMap(invalid, Teuchos::ArrayView<const GlobalIndex>(dofs.data(), n_owned), 0, comm));
  overlap_map_ = Teuchos::rcp(new TpetraMap(
      invalid, Teuchos::ArrayView<const GlobalIndex>(dofs.data(), dofs.size()), 0, comm));
  importer_ = Teuchos::rcp(new TpetraImport(owned_map_, overlap_map_));
}

std::vector<int> DofMap::mesh_node_dofs(const Mesh& mesh) {
  std::vector<int> counts(mesh.n_nodes(), 0);
  std::vector<char> in_beam(mesh.n_nodes(), 0);
  for (const auto& block : mesh.blocks) {
    if (block.type == ElementType::hex8)
      continue;
    for (GlobalIndex node : block.connectivity) {
      counts[node] = 6;
      if (block.type == ElementType::beam2)
        in_beam[node] = 1;
    }
  }
  for (const auto& block : mesh.blocks) {
    if (block.type != ElementType::hex8)
      continue;
    for (GlobalIndex node : block.connectivity) {
      if (in_beam[node]) {
        throw_input_error(mesh.source, "Mesh",
                          "node " + std::to_string(node + 1) +
                              " belongs to a beam2 and a hex8 "
                              "element (block '" +
                              block.name +
                              "'): a solid node has no rotation "
                              "unknowns for the beam",
                          "beam nodes apart from solid nodes, joined by a solid-beam tie");
      }
      counts[node] = 3;
    }
  }
  return counts;
}

DofMap DofMap::for_mesh(const MeshPartition& partition) {
  return DofMap(partition, mesh_node_dofs(partition.mesh()));
}

void DofMap::require_uniform(int dofs_per_node, const std::string& who) const {
  if (dofs_per_node_ != dofs_per_node) {
    throw std::logic_error(
        "railfe: " + who + " needs a DOF map with " + std::to_string(dofs_per_node) +
        " DOFs at every node, not " +
        (dofs_per_node_ > 0 ? std::to_string(dofs_per_node_) : std::string("a mixed 3/6 layout")));
  }
}

void DofMap::throw_mixed_layout(const std::string& who) {
  throw std::logic_error("railfe: DofMap::" + who +
                         " on a mixed 3/6 DOF layout: use local_dof() and dofs_of_node()");
}

std::string DofMap::describe(GlobalIndex dof) const {
  if (dofs_per_node_ > 0)
    return describe_dof(dof, dofs_per_node_);
  const auto next = std::upper_bound(global_offsets_.begin(), global_offsets_.end(), dof);
  const GlobalIndex node = (next - global_offsets_.begin()) - 1;
  return describe_node_component(node, static_cast<int>(dof - global_offsets_[node]));
}

void DofMap::owned_to_overlap(const TpetraVector& owned, TpetraVector& overlap) const {
  overlap.doImport(owned, *importer_, Tpetra::INSERT);
}

void DofMap::overlap_to_owned_sum(const TpetraVector& overlap, TpetraVector& owned) const {
  owned.putScalar(0.0);
  owned.doExport(overlap, *importer_, Tpetra::ADD);
}

std::string describe_node_component(GlobalIndex node, int component) {
  static const char* kNames[] = {"x", "y", "z", "θx", "θy", "θz"};
  const std::string name =
      component >= 0 && component < 6 ? kNames[component] : std::to_string(component + 1);
  return "node " + std::to_string(node + 1) + " component " + name;
}

std::string describe_dof(GlobalIndex dof, int dofs_per_node) {
  const int component = static_cast<int>(dof % dofs_per_node);
  const GlobalIndex node = dof / dofs_per_node;
  if (dofs_per_node == 3 || dofs_per_node == 6)
    return describe_node_component(node, component);
  return "node " + std::to_string(node + 1) + " component " + std::to_string(component + 1);
}

}  // namespace railfe
