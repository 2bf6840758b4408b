#pragma once
/// \file
/// Element-by-element assembly of a global matrix on Tpetra's FECrsMatrix: each rank adds its
/// elements into owned and shared rows; end_assembly() sums shared rows into their owners.

#include <memory>
#include <vector>

#include "framework/assembly/dof_map.hpp"

namespace railfe {

/// A matrix over a DofMap whose sparsity couples every pair of nodes sharing an element.
///
/// Assembly adds a dense element matrix straight into the CRS values: the columns of a node
/// pair are found once per pair (binary search in the row) rather than once per entry, which
/// keeps assembly cheap next to computing the element matrix.
class FeMatrix {
 public:
  /// Builds the sparsity from every local element of every block (collective).
  /// \p dofs must outlive the matrix.
  explicit FeMatrix(const DofMap& dofs);
  ~FeMatrix();
  FeMatrix(const FeMatrix&) = delete;
  FeMatrix& operator=(const FeMatrix&) = delete;

  /// Opens the matrix for assembly and sets every entry to zero.
  void begin_assembly();
  /// Adds the dense, row-major element matrix of \p n_nodes local nodes \p nodes (size
  /// (n_nodes·dofs_per_node)², DOFs node-major) to the owned+shared rows.
  void add_element(const LocalIndex* nodes, int n_nodes, const double* element_matrix);
  /// Sums shared rows into their owners and completes the matrix (collective).
  void end_assembly();

  /// The assembled matrix over the owned DOF map (valid after end_assembly()).
  Teuchos::RCP<TpetraMatrix> matrix() const;
  /// The DOF map it is built on.
  const DofMap& dofs() const { return *dofs_; }
  /// Stored entries over all ranks (a measure of memory).
  GlobalIndex n_global_entries() const;

 private:
  void build_node_adjacency();
  void map_node_columns();

  const DofMap* dofs_;
  std::vector<LocalIndex> adjacency_offsets_;  // CSR over local nodes: neighbours via elements
  std::vector<LocalIndex> adjacency_;
  // Tpetra's FE graph and matrix; kept out of this header (their 13.2 forward declarations
  // clash with the definitions).
  struct Storage;
  std::unique_ptr<Storage> storage_;
  std::vector<LocalIndex> node_columns_;  // column index of each local node's first DOF
  // CRS arrays of the owned+shared rows while assembling.
  double* values_ = nullptr;
  const std::size_t* row_offsets_ = nullptr;
  const LocalIndex* columns_ = nullptr;
};

}  // namespace railfe
