#include "framework/assembly/fe_matrix.hpp"

#include <Tpetra_Assembly_Helpers.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "framework/assembly/tpetra_compat.hpp"

namespace railfe {

struct FeMatrix::Storage {
  Teuchos::RCP<Tpetra::FECrsGraph<>> graph;
  Teuchos::RCP<Tpetra::FECrsMatrix<double>> matrix;
};

FeMatrix::FeMatrix(const DofMap& dofs) : dofs_(&dofs), storage_(std::make_unique<Storage>()) {
  build_sparsity();
  const MeshPartition& partition = dofs.partition();
  const LocalIndex n_nodes = partition.n_local_nodes();

  // Columns: the local nodes (owned, then ghosts), then the column-only nodes that reach owned
  // rows through other ranks' elements, each node's components consecutive. Column index of
  // component c of column node n: column_starts[n] + c (dpn·n + c in a uniform layout).
  std::vector<LocalIndex> column_starts{0};
  std::vector<GlobalIndex> column_dofs;
  column_dofs.reserve(static_cast<std::size_t>(dofs.max_dofs_per_node()) *
                      (n_nodes + column_only_nodes_.size()));
  auto add_column_node = [&](GlobalIndex node) {
    const int count = dofs.dofs_of_global_node(node);
    for (int c = 0; c < count; ++c)
      column_dofs.push_back(dofs.global_dof(node, c));
    column_starts.push_back(static_cast<LocalIndex>(column_dofs.size()));
  };
  for (LocalIndex node = 0; node < n_nodes; ++node)
    add_column_node(partition.global_node(node));
  for (GlobalIndex node : column_only_nodes_)
    add_column_node(node);

  // Where each neighbour's entries start within a row (mixed layouts; dpn·k when uniform).
  if (!dofs.is_uniform()) {
    neighbour_starts_.resize(adjacency_.size());
    for (LocalIndex node = 0; node < n_nodes; ++node) {
      LocalIndex start = 0;
      for (LocalIndex k = adjacency_offsets_[node]; k < adjacency_offsets_[node + 1]; ++k) {
        neighbour_starts_[k] = start;
        start += column_starts[adjacency_[k] + 1] - column_starts[adjacency_[k]];
      }
    }
  }

  const LocalIndex n_rows = dofs.n_overlap_dofs();
  Kokkos::DualView<std::size_t*, Tpetra::FECrsGraph<>::device_type> counts("row counts", n_rows);
  auto host_counts = counts.h_view;
  std::vector<LocalIndex> columns;
  auto node_columns = [&](LocalIndex node) {
    columns.clear();
    for (LocalIndex k = adjacency_offsets_[node]; k < adjacency_offsets_[node + 1]; ++k) {
      for (LocalIndex c = column_starts[adjacency_[k]]; c < column_starts[adjacency_[k] + 1]; ++c)
        columns.push_back(c);
    }
  };
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    const LocalIndex degree = adjacency_offsets_[node + 1] - adjacency_offsets_[node];
    std::size_t row_length = 0;
    if (dofs.is_uniform()) {
      row_length = static_cast<std::size_t>(dofs.dofs_per_node()) * degree;
    } else {
      for (LocalIndex k = adjacency_offsets_[node]; k < adjacency_offsets_[node + 1]; ++k)
        row_length += column_starts[adjacency_[k] + 1] - column_starts[adjacency_[k]];
    }
    for (int c = 0; c < dofs.dofs_of_node(node); ++c)
      host_counts(dofs.local_dof(node, c)) = row_length;
  }
  counts.modify_host();
  counts.sync_device();
  Kokkos::DualView<const std::size_t*, Tpetra::FECrsGraph<>::device_type> const_counts = counts;

  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto column_map = Teuchos::rcp(new TpetraMap(
      invalid, Teuchos::ArrayView<const GlobalIndex>(column_dofs.data(), column_dofs.size()), 0,
      partition.comm().teuchos()));

  storage_->graph = Teuchos::rcp(new Tpetra::FECrsGraph<>(
      dofs.owned_map(), dofs.overlap_map(), column_map, const_counts, dofs.importer()));
  Tpetra::beginAssembly(*storage_->graph);
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    node_columns(node);
    for (int c = 0; c < dofs.dofs_of_node(node); ++c) {
      storage_->graph->insertLocalIndices(
          dofs.local_dof(node, c),
          Teuchos::ArrayView<const LocalIndex>(columns.data(), columns.size()));
    }
  }
  Tpetra::endAssembly(*storage_->graph);
  storage_->matrix = Teuchos::rcp(new Tpetra::FECrsMatrix<double>(storage_->graph));
  column_starts_ = std::move(column_starts);
}

FeMatrix::~FeMatrix() = default;

void FeMatrix::build_sparsity() {
  const MeshPartition& partition = dofs_->partition();
  const Mesh& mesh = partition.mesh();
  const int rank = partition.comm().rank();
  const LocalIndex n_nodes = partition.n_local_nodes();
  const LocalIndex n_owned = partition.n_owned_nodes();

  // Element node lists in column-node numbering: this rank's elements, then other ranks'
  // elements that touch an owned node (their couplings land in owned rows when shared rows are
  // summed, so the owned rows must have room for them).
  std::vector<LocalIndex> element_offsets{0};
  std::vector<LocalIndex> element_nodes;
  std::vector<char> remote;
  element_nodes_.clear();
  element_node_counts_.clear();
  for (const auto& block : partition.blocks()) {
    element_nodes.insert(element_nodes.end(), block.connectivity.begin(), block.connectivity.end());
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      const LocalIndex count = block.offsets[e + 1] - block.offsets[e];
      element_offsets.push_back(element_offsets.back() + count);
      remote.push_back(0);
      element_nodes_.push_back(block.connectivity.data() + block.offsets[e]);
      element_node_counts_.push_back(count);
    }
  }
  column_only_nodes_.clear();
  std::unordered_map<GlobalIndex, LocalIndex> column_only_index;
  if (partition.comm().n_ranks() > 1) {
    for (const auto& block : mesh.blocks) {
      for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
        if (partition.element_ranks()[block.first_element + e] == rank)
          continue;
        const GlobalIndex* nodes = block.element_nodes(e);
        const int count = block.n_element_nodes(e);
        bool touches_owned = false;
        for (int a = 0; a < count && !touches_owned; ++a) {
          touches_owned = partition.node_ranks()[nodes[a]] == rank;
        }
        if (!touches_owned)
          continue;
        for (int a = 0; a < count; ++a) {
          LocalIndex column = partition.local_node(nodes[a]);
          if (column < 0) {
            auto [it, added] = column_only_index.emplace(
                nodes[a], n_nodes + static_cast<LocalIndex>(column_only_nodes_.size()));
            if (added)
              column_only_nodes_.push_back(nodes[a]);
            column = it->second;
          }
          element_nodes.push_back(column);
        }
        element_offsets.push_back(static_cast<LocalIndex>(element_nodes.size()));
        remote.push_back(1);
      }
    }
  }
  const std::size_t n_elements = remote.size();

  // Rows -> elements (CSR), then each row's sorted, unique neighbours. Other ranks' elements only
  // add to owned rows.
  auto has_row = [&](std::size_t e, LocalIndex node) {
    return node < n_nodes && (!remote[e] || node < n_owned);
  };
  std::vector<LocalIndex> row_count(n_nodes + 1, 0);
  for (std::size_t e = 0; e < n_elements; ++e) {
    for (LocalIndex k = element_offsets[e]; k < element_offsets[e + 1]; ++k) {
      if (has_row(e, element_nodes[k]))
        ++row_count[element_nodes[k] + 1];
    }
  }
  for (LocalIndex n = 0; n < n_nodes; ++n)
    row_count[n + 1] += row_count[n];
  std::vector<LocalIndex> row_elements(row_count[n_nodes]);
  std::vector<LocalIndex> fill(row_count.begin(), row_count.end() - 1);
  for (std::size_t e = 0; e < n_elements; ++e) {
    for (LocalIndex k = element_offsets[e]; k < element_offsets[e + 1]; ++k) {
      if (has_row(e, element_nodes[k])) {
        row_elements[fill[element_nodes[k]]++] = static_cast<LocalIndex>(e);
      }
    }
  }
  adjacency_offsets_.assign(n_nodes + 1, 0);
  adjacency_.clear();
  adjacency_.reserve(27 * static_cast<std::size_t>(n_nodes));
  std::vector<LocalIndex> neighbours;
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    neighbours.clear();
    for (LocalIndex k = row_count[node]; k < row_count[node + 1]; ++k) {
      const LocalIndex e = row_elements[k];
      neighbours.insert(neighbours.end(), element_nodes.begin() + element_offsets[e],
                        element_nodes.begin() + element_offsets[e + 1]);
    }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    adjacency_.insert(adjacency_.end(), neighbours.begin(), neighbours.end());
    adjacency_offsets_[node + 1] = static_cast<LocalIndex>(adjacency_.size());
  }

  // Slots of each local element's node pairs: fill a scratch map column node -> slot for one
  // row node at a time, then read it for every element at that node.
  const std::size_t n_local_elements = partition.n_local_elements();
  element_slot_offsets_.assign(n_local_elements + 1, 0);
  for (std::size_t e = 0; e < n_local_elements; ++e) {
    const std::size_t m = element_offsets[e + 1] - element_offsets[e];
    element_slot_offsets_[e + 1] = element_slot_offsets_[e] + m * m;
  }
  element_slots_.assign(element_slot_offsets_[n_local_elements], 0);
  std::vector<int> slot_of(n_nodes + column_only_nodes_.size(), -1);
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    const LocalIndex begin = adjacency_offsets_[node], end = adjacency_offsets_[node + 1];
    if (end - begin > 65535) {
      throw std::logic_error("railfe: FeMatrix: a node has more than 65535 neighbours");
    }
    for (LocalIndex k = begin; k < end; ++k)
      slot_of[adjacency_[k]] = k - begin;
    for (LocalIndex k = row_count[node]; k < row_count[node + 1]; ++k) {
      const LocalIndex e = row_elements[k];
      if (remote[e])
        continue;
      const LocalIndex first = element_offsets[e];
      const LocalIndex m = element_offsets[e + 1] - first;
      for (LocalIndex a = 0; a < m; ++a) {
        if (element_nodes[first + a] != node)
          continue;
        std::uint16_t* slots = element_slots_.data() + element_slot_offsets_[e] + a * m;
        for (LocalIndex b = 0; b < m; ++b) {
          slots[b] = static_cast<std::uint16_t>(slot_of[element_nodes[first + b]]);
        }
      }
    }
    for (LocalIndex k = begin; k < end; ++k)
      slot_of[adjacency_[k]] = -1;
  }
}

void FeMatrix::begin_assembly() {
  storage_->matrix->beginAssembly();
  // A new matrix is zero already; clearing 1 kB per DOF again would cost a fifth of assembly.
  if (assembled_once_)
    storage_->matrix->setAllToScalar(0.0);
  assembled_once_ = true;
  auto local = storage_->matrix->getLocalMatrixHost();
  values_ = local.values.data();
  row_offsets_ = local.graph.row_map.data();
  if (!layout_checked_) {
    check_layout();
    layout_checked_ = true;
  }
}

void FeMatrix::check_layout() const {
  // add_element() writes entry (node n, component i; neighbour slot k, component j) of the
  // owned+shared rows at row_offsets[local_dof(n, i)] + neighbour_start(n, k) + j. That follows
  // from how the graph was built (sorted neighbours, each node's column components consecutive);
  // checked once here.
  auto local = storage_->matrix->getLocalMatrixHost();
  const auto& entries = local.graph.entries;
  const LocalIndex n_nodes = dofs_->partition().n_local_nodes();
  for (LocalIndex node = 0; node < n_nodes; ++node) {
    const LocalIndex begin = adjacency_offsets_[node], end = adjacency_offsets_[node + 1];
    std::size_t row_length = 0;
    for (LocalIndex k = begin; k < end; ++k)
      row_length += column_starts_[adjacency_[k] + 1] - column_starts_[adjacency_[k]];
    for (int i = 0; i < dofs_->dofs_of_node(node); ++i) {
      const LocalIndex row_index = dofs_->local_dof(node, i);
      const std::size_t row = row_offsets_[row_index];
      bool matches = row_offsets_[row_index + 1] - row == row_length;
      for (LocalIndex k = begin; k < end && matches; ++k) {
        const LocalIndex first = column_starts_[adjacency_[k]];
        const LocalIndex count = column_starts_[adjacency_[k] + 1] - first;
        for (LocalIndex j = 0; j < count; ++j) {
          matches = matches && entries(row + neighbour_start(node, k) + j) == first + j;
        }
      }
      if (!matches) {
        throw std::logic_error(
            "railfe: FeMatrix: the matrix layout differs from the sparsity built");
      }
    }
  }
}

LocalIndex FeMatrix::neighbour_start(LocalIndex node, LocalIndex k) const {
  return dofs_->is_uniform() ? dofs_->dofs_per_node() * (k - adjacency_offsets_[node])
                             : neighbour_starts_[k];
}

namespace {

// Adds an element matrix of n_nodes nodes with dpn DOFs each; the fixed-size instance (hex8 with
// three displacements) lets the compiler unroll and vectorize the inner triples.
template <int kDpn, int kNodes>
void scatter(int dpn_runtime, int nodes_runtime, const LocalIndex* nodes,
             const std::uint16_t* slots, const double* element_matrix, double* values,
             const std::size_t* row_offsets) {
  const int dpn = kDpn > 0 ? kDpn : dpn_runtime;
  const int n_nodes = kNodes > 0 ? kNodes : nodes_runtime;
  const int n_columns = dpn * n_nodes;
  for (int a = 0; a < n_nodes; ++a) {
    const std::uint16_t* row_slots = slots + a * n_nodes;
    for (int i = 0; i < dpn; ++i) {
      double* row = values + row_offsets[dpn * nodes[a] + i];
      const double* element_row = element_matrix + (dpn * a + i) * n_columns;
      for (int b = 0; b < n_nodes; ++b) {
        double* target = row + dpn * row_slots[b];
        for (int j = 0; j < dpn; ++j)
          target[j] += element_row[dpn * b + j];
      }
    }
  }
}

}  // namespace

void FeMatrix::add_element(LocalIndex element, const double* element_matrix) {
  const int n_nodes = element_node_counts_[element];
  const std::uint16_t* slots = element_slots_.data() + element_slot_offsets_[element];
  const LocalIndex* nodes = element_nodes_[element];
  if (!dofs_->is_uniform()) {
    add_mixed_element(n_nodes, nodes, slots, element_matrix);
    return;
  }
  const int dpn = dofs_->dofs_per_node();
  if (dpn == 3 && n_nodes == 8) {
    scatter<3, 8>(dpn, n_nodes, nodes, slots, element_matrix, values_, row_offsets_);
  } else {
    scatter<0, 0>(dpn, n_nodes, nodes, slots, element_matrix, values_, row_offsets_);
  }
}

void FeMatrix::add_mixed_element(int n_nodes, const LocalIndex* nodes, const std::uint16_t* slots,
                                 const double* element_matrix) {
  // Element DOFs node-major, each node with its own count.
  int starts[kMaxMixedElementNodes + 1] = {0};
  if (n_nodes > kMaxMixedElementNodes) {
    throw std::logic_error("railfe: FeMatrix: an element of more than " +
                           std::to_string(kMaxMixedElementNodes) + " nodes on a mixed DOF layout");
  }
  for (int a = 0; a < n_nodes; ++a)
    starts[a + 1] = starts[a] + dofs_->dofs_of_node(nodes[a]);
  const int n_columns = starts[n_nodes];
  for (int a = 0; a < n_nodes; ++a) {
    const std::uint16_t* row_slots = slots + a * n_nodes;
    const LocalIndex* neighbour_starts = neighbour_starts_.data() + adjacency_offsets_[nodes[a]];
    for (int i = 0; i < starts[a + 1] - starts[a]; ++i) {
      double* row = values_ + row_offsets_[dofs_->local_dof(nodes[a], i)];
      const double* element_row = element_matrix + (starts[a] + i) * n_columns;
      for (int b = 0; b < n_nodes; ++b) {
        double* target = row + neighbour_starts[row_slots[b]];
        for (int j = 0; j < starts[b + 1] - starts[b]; ++j)
          target[j] += element_row[starts[b] + j];
      }
    }
  }
}

void FeMatrix::end_assembly() {
  values_ = nullptr;
  row_offsets_ = nullptr;
  storage_->matrix->endAssembly();
}

void FeMatrix::add_to_diagonal(const std::vector<double>& values) {
  auto& matrix = *storage_->matrix;
  TpetraVector diagonal(matrix.getRowMap());
  matrix.getLocalDiagCopy(diagonal);
  const auto current = diagonal.getData();
  const auto& rows = *matrix.getRowMap();
  const auto& columns = *matrix.getColMap();
  // An assembled FECrsMatrix accepts new values only while open for modification.
  matrix.beginModify();
  for (std::size_t row = 0; row < values.size(); ++row) {
    if (values[row] == 0)
      continue;
    const LocalIndex column = columns.getLocalElement(rows.getGlobalElement(row));
    matrix.replaceLocalValues(static_cast<LocalIndex>(row), Teuchos::tuple(column),
                              Teuchos::tuple(current[row] + values[row]));
  }
  matrix.endModify();
}

Teuchos::RCP<TpetraMatrix> FeMatrix::matrix() const {
  return Teuchos::rcp_implicit_cast<TpetraMatrix>(storage_->matrix);
}

GlobalIndex FeMatrix::n_global_entries() const {
  return static_cast<GlobalIndex>(storage_->matrix->getGlobalNumEntries());
}

}  // namespace railfe
