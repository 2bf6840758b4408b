#include "framework/output/field_gather.hpp"

namespace railfe {

namespace {

std::vector<std::vector<double>> scatter_on_root(const Communicator& comm,
                                                 const std::vector<long long>& local_ids,
                                                 const std::vector<double>& local_values,
                                                 int components, GlobalIndex total) {
  const auto ids = comm.gather_to_root(local_ids);
  const auto values = comm.gather_to_root(local_values);
  std::vector<std::vector<double>> result;
  if (!comm.is_root())
    return result;
  result.assign(components, std::vector<double>(total, 0.0));
  for (std::size_t k = 0; k < ids.size(); ++k) {
    for (int c = 0; c < components; ++c)
      result[c][ids[k]] = values[components * k + c];
  }
  return result;
}

}  // namespace

std::vector<std::vector<double>> gather_node_field(const MeshPartition& partition,
                                                   const std::vector<double>& owned_values,
                                                   int components) {
  std::vector<long long> ids(partition.global_nodes().begin(),
                             partition.global_nodes().begin() + partition.n_owned_nodes());
  return scatter_on_root(partition.comm(), ids, owned_values, components,
                         partition.mesh().n_nodes());
}

std::vector<std::vector<double>> gather_element_field(const MeshPartition& partition,
                                                      const std::vector<double>& local_values,
                                                      int components) {
  std::vector<long long> ids;
  for (const auto& block : partition.blocks()) {
    const GlobalIndex first = partition.mesh().blocks[block.block].first_element;
    for (GlobalIndex e : block.elements)
      ids.push_back(first + e);
  }
  return scatter_on_root(partition.comm(), ids, local_values, components,
                         partition.mesh().n_elements());
}

}  // namespace railfe
