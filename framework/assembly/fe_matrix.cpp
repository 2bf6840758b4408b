#include "framework/assembly/fe_matrix.hpp"

#include <Tpetra_Assembly_Helpers.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>

#include <algorithm>
#include <stdexcept>

#include "framework/assembly/tpetra_compat.hpp"

namespace railfe {

struct FeMatrix::Storage {
  Teuchos::RCP<Tpetra::FECrsGraph<>> graph;
  Teuchos::RCP<Tpetra::FECrsMatrix<double>> matrix;
};

FeMatrix::FeMatrix(const DofMap& dofs) : dofs_(&dofs), storage_(std::make_unique<Storage>()) {
  build_node_adjacency();
  const int dpn = dofs.dofs_per_node();
  const MeshPartition& partition = dofs.partition();
  const LocalIndex n_nodes = partition.n_local_nodes();

  Kokkos::DualView<std::size_t*, Tpetra::FECrsGraph<>::device_type> counts("row counts",
                                                                         dpn * n_nodes);
  auto host_counts = counts.h_view;
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    const std::size_t degree = adjacency_offsets_[node + 1] - adjacency_offsets_[node];
    for (int c = 0; c < dpn; ++c) host_counts(dpn * node + c) = dpn * degree;
  }
  counts.modify_host();
  counts.sync_device();
  Kokkos::DualView<const std::size_t*, Tpetra::FECrsGraph<>::device_type> const_counts = counts;

  // Tpetra chooses the column map: rows of nodes on a partition boundary also receive couplings
  // from the neighbouring rank's elements, which no locally built column map could list.
  storage_->graph = Teuchos::rcp(new Tpetra::FECrsGraph<>(dofs.owned_map(), dofs.overlap_map(),
                                                          const_counts, dofs.importer()));
  Tpetra::beginAssembly(*storage_->graph);
  std::vector<GlobalIndex> columns;
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    columns.clear();
    for (LocalIndex k = adjacency_offsets_[node]; k < adjacency_offsets_[node + 1]; ++k) {
      const GlobalIndex neighbour = partition.global_node(adjacency_[k]);
      for (int c = 0; c < dpn; ++c) columns.push_back(dpn * neighbour + c);
    }
    for (int c = 0; c < dpn; ++c) {
      storage_->graph->insertGlobalIndices(
          dpn * partition.global_node(node) + c,
          Teuchos::ArrayView<const GlobalIndex>(columns.data(), columns.size()));
    }
  }
  Tpetra::endAssembly(*storage_->graph);
  storage_->matrix = Teuchos::rcp(new Tpetra::FECrsMatrix<double>(storage_->graph));
}

FeMatrix::~FeMatrix() = default;

void FeMatrix::build_node_adjacency() {
  const MeshPartition& partition = dofs_->partition();
  const LocalIndex n_nodes = partition.n_local_nodes();
  // Node -> elements (as (block, element) pairs flattened to offsets into connectivity).
  std::vector<LocalIndex> element_count(n_nodes + 1, 0);
  for (const auto& block : partition.blocks()) {
    for (LocalIndex node : block.connectivity) ++element_count[node + 1];
  }
  for (LocalIndex n = 0; n < n_nodes; ++n) element_count[n + 1] += element_count[n];
  struct ElementRef {
    const LocalBlock* block;
    LocalIndex element;
  };
  std::vector<ElementRef> node_elements(element_count[n_nodes]);
  std::vector<LocalIndex> fill(element_count.begin(), element_count.end() - 1);
  for (const auto& block : partition.blocks()) {
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      for (LocalIndex k = block.offsets[e]; k < block.offsets[e + 1]; ++k) {
        node_elements[fill[block.connectivity[k]]++] = {&block, e};
      }
    }
  }
  adjacency_offsets_.assign(n_nodes + 1, 0);
  adjacency_.clear();
  std::vector<LocalIndex> neighbours;
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    neighbours.clear();
    for (LocalIndex k = element_count[node]; k < element_count[node + 1]; ++k) {
      const auto& ref = node_elements[k];
      const auto& conn = ref.block->connectivity;
      neighbours.insert(neighbours.end(), conn.begin() + ref.block->offsets[ref.element],
                        conn.begin() + ref.block->offsets[ref.element + 1]);
    }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    adjacency_.insert(adjacency_.end(), neighbours.begin(), neighbours.end());
    adjacency_offsets_[node + 1] = static_cast<LocalIndex>(adjacency_.size());
  }
}

void FeMatrix::begin_assembly() {
  storage_->matrix->beginAssembly();
  storage_->matrix->setAllToScalar(0.0);
  auto local = storage_->matrix->getLocalMatrixHost();
  values_ = local.values.data();
  row_offsets_ = local.graph.row_map.data();
  columns_ = local.graph.entries.data();
  if (node_columns_.empty()) map_node_columns();
}

void FeMatrix::map_node_columns() {
  // add_element() finds a node's columns by searching for the column of its first component and
  // takes the others as the next ones; and it reuses one search for all rows of a node. Both
  // hold for Tpetra's column maps (a node's DOFs share an owner and sort together); checked here
  // once rather than trusted.
  const int dpn = dofs_->dofs_per_node();
  const MeshPartition& partition = dofs_->partition();
  const auto& column_map = *storage_->matrix->getColMap();
  const LocalIndex n_nodes = partition.n_local_nodes();
  node_columns_.resize(n_nodes);
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    const GlobalIndex first = dpn * partition.global_node(node);
    node_columns_[node] = column_map.getLocalElement(first);
    for (int c = 0; c < dpn; ++c) {
      if (column_map.getLocalElement(first + c) != node_columns_[node] + c) {
        throw std::logic_error("railfe: FeMatrix: a node's DOFs are not adjacent columns");
      }
    }
    const std::size_t begin = row_offsets_[dpn * node];
    const std::size_t length = row_offsets_[dpn * node + 1] - begin;
    for (int c = 1; c < dpn; ++c) {
      const std::size_t other = row_offsets_[dpn * node + c];
      if (row_offsets_[dpn * node + c + 1] - other != length ||
          !std::equal(columns_ + begin, columns_ + begin + length, columns_ + other)) {
        throw std::logic_error("railfe: FeMatrix: rows of one node differ in sparsity");
      }
    }
  }
}

void FeMatrix::add_element(const LocalIndex* nodes, int n_nodes, const double* element_matrix) {
  const int dpn = dofs_->dofs_per_node();
  const int n_columns = dpn * n_nodes;
  constexpr int kMaxNodes = 64;
  if (n_nodes > kMaxNodes) {
    throw std::logic_error("railfe: FeMatrix::add_element supports at most 64 nodes per element");
  }
  std::size_t position[kMaxNodes];
  for (int a = 0; a < n_nodes; ++a) {
    const LocalIndex first_row = dpn * nodes[a];
    const LocalIndex* row_begin = columns_ + row_offsets_[first_row];
    const LocalIndex* row_end = columns_ + row_offsets_[first_row + 1];
    for (int b = 0; b < n_nodes; ++b) {
      position[b] = std::lower_bound(row_begin, row_end, node_columns_[nodes[b]]) - row_begin;
    }
    for (int i = 0; i < dpn; ++i) {
      double* row = values_ + row_offsets_[first_row + i];
      const double* element_row = element_matrix + static_cast<std::size_t>(dpn * a + i) * n_columns;
      for (int b = 0; b < n_nodes; ++b) {
        for (int j = 0; j < dpn; ++j) row[position[b] + j] += element_row[dpn * b + j];
      }
    }
  }
}

void FeMatrix::end_assembly() {
  values_ = nullptr;
  row_offsets_ = nullptr;
  columns_ = nullptr;
  storage_->matrix->endAssembly();
}

Teuchos::RCP<TpetraMatrix> FeMatrix::matrix() const {
  return Teuchos::rcp_implicit_cast<TpetraMatrix>(storage_->matrix);
}

GlobalIndex FeMatrix::n_global_entries() const {
  return static_cast<GlobalIndex>(storage_->matrix->getGlobalNumEntries());
}

}  // namespace railfe
