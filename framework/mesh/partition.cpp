#include "framework/mesh/partition.hpp"

#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

#include <algorithm>

namespace railfe {

namespace {

using ZoltanTypes = Zoltan2::BasicUserTypes<double, int, long long>;
using CentroidAdapter = Zoltan2::BasicVectorAdapter<ZoltanTypes>;

// Centroid of a global element (any element type: the mean of its nodes).
void centroid(const Mesh& mesh, const ElementBlock& block, GlobalIndex e, double* c) {
  const int count = block.n_element_nodes(e);
  const GlobalIndex* nodes = block.element_nodes(e);
  c[0] = c[1] = c[2] = 0;
  for (int a = 0; a < count; ++a) {
    for (int d = 0; d < 3; ++d)
      c[d] += mesh.coordinates[3 * nodes[a] + d];
  }
  for (int d = 0; d < 3; ++d)
    c[d] /= count;
}

}  // namespace

MeshPartition::MeshPartition(const Mesh& mesh, const Communicator& comm, PartitionMethod method)
    : mesh_(&mesh), comm_(comm) {
  assign_elements(method);
  build_local_numbering();
}

void MeshPartition::assign_elements(PartitionMethod method) {
  const GlobalIndex n_elements = mesh_->n_elements();
  const int n_ranks = comm_.n_ranks();
  element_ranks_.assign(n_elements, 0);
  method_name_ = n_ranks == 1                       ? "none (one rank)"
                 : method == PartitionMethod::block ? "block"
                 : method == PartitionMethod::rcb   ? "Zoltan2 rcb"
                                                    : "Zoltan2 multijagged";
  if (n_ranks == 1)
    return;

  // Each rank hands the partitioner an equal slice of the elements; the answer is gathered so
  // every rank knows every element's rank.
  const GlobalIndex begin = n_elements * comm_.rank() / n_ranks;
  const GlobalIndex end = n_elements * (comm_.rank() + 1) / n_ranks;
  std::vector<long long> slice_ranks(end - begin);
  if (method == PartitionMethod::block) {
    for (GlobalIndex e = begin; e < end; ++e)
      slice_ranks[e - begin] = comm_.rank();
  } else {
    const int count = static_cast<int>(end - begin);
    std::vector<long long> ids(count);
    std::vector<double> x(count), y(count), z(count);
    for (GlobalIndex e = begin; e < end; ++e) {
      const auto& block = mesh_->blocks[mesh_->block_of(e)];
      double c[3];
      centroid(*mesh_, block, e - block.first_element, c);
      ids[e - begin] = e;
      x[e - begin] = c[0];
      y[e - begin] = c[1];
      z[e - begin] = c[2];
    }
    CentroidAdapter adapter(count, ids.data(), x.data(), y.data(), z.data());
    Teuchos::ParameterList parameters("zoltan2");
    parameters.set("algorithm", method == PartitionMethod::rcb ? "rcb" : "multijagged");
    parameters.set("num_global_parts", static_cast<int>(n_ranks));
    parameters.set("imbalance_tolerance", 1.02);
    Zoltan2::PartitioningProblem<CentroidAdapter> problem(&adapter, &parameters, comm_.teuchos());
    problem.solve();
    const auto* parts = problem.getSolution().getPartListView();
    for (int i = 0; i < count; ++i)
      slice_ranks[i] = parts[i];
  }
  const auto all = comm_.all_gather(slice_ranks);
  for (GlobalIndex e = 0; e < n_elements; ++e)
    element_ranks_[e] = static_cast<int>(all[e]);
}

void MeshPartition::build_local_numbering() {
  const GlobalIndex n_nodes = mesh_->n_nodes();
  const int rank = comm_.rank();
  node_ranks_.assign(n_nodes, -1);
  std::vector<char> touched(n_nodes, 0);
  for (const auto& block : mesh_->blocks) {
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const int owner = element_ranks_[block.first_element + e];
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < block.n_element_nodes(e); ++a) {
        int& node_rank = node_ranks_[nodes[a]];
        if (node_rank < 0 || owner < node_rank)
          node_rank = owner;
        if (owner == rank)
          touched[nodes[a]] = 1;
      }
    }
  }
  n_active_nodes_ =
      std::count_if(node_ranks_.begin(), node_ranks_.end(), [](int r) { return r >= 0; });

  // Owned nodes first, then ghosts, each in ascending global order (keeps generator locality).
  global_nodes_.clear();
  for (GlobalIndex n = 0; n < n_nodes; ++n) {
    if (touched[n] && node_ranks_[n] == rank)
      global_nodes_.push_back(n);
  }
  n_owned_nodes_ = static_cast<LocalIndex>(global_nodes_.size());
  for (GlobalIndex n = 0; n < n_nodes; ++n) {
    if (touched[n] && node_ranks_[n] != rank)
      global_nodes_.push_back(n);
  }
  local_of_global_.assign(n_nodes, -1);
  local_coordinates_.resize(3 * global_nodes_.size());
  for (std::size_t i = 0; i < global_nodes_.size(); ++i) {
    local_of_global_[global_nodes_[i]] = static_cast<LocalIndex>(i);
    for (int d = 0; d < 3; ++d)
      local_coordinates_[3 * i + d] = mesh_->coordinates[3 * global_nodes_[i] + d];
  }

  blocks_.clear();
  for (std::size_t b = 0; b < mesh_->blocks.size(); ++b) {
    const auto& block = mesh_->blocks[b];
    LocalBlock local;
    local.block = static_cast<int>(b);
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      if (element_ranks_[block.first_element + e] != rank)
        continue;
      local.elements.push_back(e);
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < block.n_element_nodes(e); ++a) {
        local.connectivity.push_back(local_of_global_[nodes[a]]);
      }
      local.offsets.push_back(static_cast<LocalIndex>(local.connectivity.size()));
    }
    if (!local.elements.empty())
      blocks_.push_back(std::move(local));
  }
  first_local_elements_.assign(1, 0);
  for (const auto& block : blocks_) {
    first_local_elements_.push_back(first_local_elements_.back() + block.n_elements());
  }
}

LocalIndex MeshPartition::n_local_elements() const {
  LocalIndex total = 0;
  for (const auto& block : blocks_)
    total += block.n_elements();
  return total;
}

std::vector<LocalIndex> owned_set_nodes(const MeshPartition& partition, const std::string& set) {
  std::vector<LocalIndex> nodes;
  if (set.empty()) {
    for (LocalIndex node = 0; node < partition.n_owned_nodes(); ++node)
      nodes.push_back(node);
    return nodes;
  }
  for (GlobalIndex node : partition.mesh().node_set(set, "", "").nodes) {
    const LocalIndex local = partition.local_node(node);
    if (local >= 0 && local < partition.n_owned_nodes())
      nodes.push_back(local);
  }
  return nodes;
}

}  // namespace railfe
