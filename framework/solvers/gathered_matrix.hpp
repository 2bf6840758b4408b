#pragma once
/// \file
/// A distributed matrix collected on rank 0 as compressed rows, for direct solvers that run on
/// one process (CHOLMOD; Amesos2 KLU2, which returns wrong answers when distributed in
/// Trilinos 13.2).

#include <string>
#include <vector>

#include "framework/assembly/tpetra_types.hpp"
#include "framework/base/parallel.hpp"

namespace railfe {

/// Rows of a distributed matrix on rank 0, renumbered 0..n-1; vectors move to and from rank 0
/// with the same numbering.
class GatheredMatrix {
 public:
  /// Collects \p A on rank 0 (collective).
  explicit GatheredMatrix(const TpetraMatrix& A);

  /// Whether this rank holds the rows (rank 0).
  bool on_root() const { return on_root_; }
  /// Number of rows (on rank 0; 0 elsewhere).
  long n_rows() const { return static_cast<long>(global_indices_.size()); }
  /// Row i's entries are columns[row_offsets[i] .. row_offsets[i+1]) (rank 0).
  const std::vector<long>& row_offsets() const { return row_offsets_; }
  /// Column of each entry, in the 0..n-1 numbering (rank 0).
  const std::vector<long>& columns() const { return columns_; }
  /// Value of each entry (rank 0).
  const std::vector<double>& values() const { return values_; }
  /// The global DOF behind gathered row \p row (rank 0).
  GlobalIndex global_index(long row) const { return global_indices_[row]; }

  /// The columns of \p b one after another, each in gathered order, on rank 0; empty elsewhere
  /// (collective).
  std::vector<double> gather(const TpetraMultiVector& b) const;
  /// Writes \p root_values (columns one after another, meaningful on rank 0) into the
  /// distributed \p x (collective).
  void scatter(const std::vector<double>& root_values, TpetraMultiVector& x) const;

 private:
  bool on_root_ = false;
  Teuchos::RCP<const TpetraMap> root_map_;
  Teuchos::RCP<const TpetraImport> importer_;
  std::vector<GlobalIndex> global_indices_;
  std::vector<long> row_offsets_;
  std::vector<long> columns_;
  std::vector<double> values_;
};

/// The railfe Communicator over the same ranks as a Teuchos (MPI) communicator.
Communicator communicator_of(const Teuchos::Comm<int>& comm);

/// Rank 0 ran a solver step alone and found \p root_problem ("" if none): every rank throws
/// RunError with that message, or returns (collective over \p A's communicator).
void share_root_verdict(const TpetraMatrix& A, const std::string& root_problem);

}  // namespace railfe
