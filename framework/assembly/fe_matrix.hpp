#pragma once
/// \file
/// Element-by-element assembly of a global matrix on Tpetra's FECrsMatrix: each rank adds its
/// elements into owned and shared rows; end_assembly() sums shared rows into their owners.

#include <cstdint>
#include <memory>
#include <vector>

#include "framework/assembly/dof_map.hpp"

namespace railfe {

/// A matrix over a DofMap whose sparsity couples every pair of nodes sharing an element.
///
/// Where each element entry lands in the compressed rows is worked out once, when the sparsity is
/// built (16-bit offsets, n_nodes² per element); add_element() is then a plain scatter, so
/// assembly costs little more than computing the element matrices, and reassembling (Newton
/// iterations, time steps) costs no searching at all.
class FeMatrix {
 public:
  /// Builds the sparsity from every local element of every block (collective).
  /// \p dofs must outlive the matrix.
  explicit FeMatrix(const DofMap& dofs);
  ~FeMatrix();
  FeMatrix(const FeMatrix&) = delete;
  FeMatrix& operator=(const FeMatrix&) = delete;

  /// Opens the matrix for assembly with every entry zero.
  void begin_assembly();
  /// Adds the dense, row-major matrix of local element \p element (numbered as
  /// MeshPartition::first_local_element() does) to the owned+shared rows. Its size is
  /// (Σ dofs_of_node)² over the element's n nodes, DOFs node-major: (n·dofs_per_node)² in a
  /// uniform layout; in a mixed one a hex8 on solid nodes is 24 × 24, a beam2 12 × 12, a spring2
  /// from a solid node to a body node 9 × 9 (at most 64 nodes per element there).
  void add_element(LocalIndex element, const double* element_matrix);
  /// Sums shared rows into their owners and completes the matrix (collective).
  void end_assembly();

  /// Adds \p values (one per owned DOF, in the owned map's order) to the diagonal of the
  /// assembled matrix (after end_assembly(): supports, springs to the ground).
  void add_to_diagonal(const std::vector<double>& values);
  /// The assembled matrix over the owned DOF map (valid after end_assembly()).
  Teuchos::RCP<TpetraMatrix> matrix() const;
  /// The DOF map it is built on.
  const DofMap& dofs() const { return *dofs_; }
  /// Stored entries over all ranks (a measure of memory).
  GlobalIndex n_global_entries() const;

 private:
  void build_sparsity();
  void check_layout() const;
  // Offset of neighbour k (an index into adjacency_) of local node node within node's rows.
  LocalIndex neighbour_start(LocalIndex node, LocalIndex k) const;
  void add_mixed_element(int n_nodes, const LocalIndex* nodes, const std::uint16_t* slots,
                         const double* element_matrix);
  static constexpr int kMaxMixedElementNodes = 64;

  const DofMap* dofs_;
  // CSR over local nodes: their neighbours through elements, in column-node numbering (local
  // nodes first, then column-only nodes: columns of owned rows that are not local nodes).
  std::vector<LocalIndex> adjacency_offsets_;
  std::vector<LocalIndex> adjacency_;
  std::vector<GlobalIndex> column_only_nodes_;
  // First column index of each column node (local nodes, then column-only nodes), + end.
  std::vector<LocalIndex> column_starts_;
  // Mixed layouts: for each adjacency_ entry, where its columns start within the row.
  std::vector<LocalIndex> neighbour_starts_;
  // For local element e with nodes n_0..n_{m-1}: slot of n_b among n_a's neighbours, for every
  // (a, b), at element_slots_[element_slot_offsets_[e] + a·m + b].
  std::vector<std::size_t> element_slot_offsets_;
  std::vector<std::uint16_t> element_slots_;
  std::vector<const LocalIndex*> element_nodes_;  // into the partition's connectivity
  std::vector<int> element_node_counts_;
  // Tpetra's FE graph and matrix; kept out of this header (their 13.2 forward declarations
  // clash with the definitions).
  struct Storage;
  std::unique_ptr<Storage> storage_;
  // CRS arrays of the owned+shared rows while assembling.
  double* values_ = nullptr;
  const std::size_t* row_offsets_ = nullptr;
  bool layout_checked_ = false;
  bool assembled_once_ = false;
};

}  // namespace railfe
