#pragma once
/// \file
/// A sparse matrix from a list of (row, column, value) entries, for couplings that no element
/// graph holds (a penalty contact, springs between node sets): the rows are owned by the rank
/// that lists them, duplicates are summed, and each row gets exactly its length.

#include <tuple>
#include <vector>

#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

/// One matrix entry: global row, global column, value.
using MatrixEntry = std::tuple<GlobalIndex, GlobalIndex, double>;

/// The fill-complete matrix over \p map (domain and range) with \p entries summed; every row
/// must be owned by this rank in \p map.
Teuchos::RCP<TpetraMatrix> matrix_from_entries(const Teuchos::RCP<const TpetraMap>& map,
                                               std::vector<MatrixEntry> entries);

}  // namespace railfe
