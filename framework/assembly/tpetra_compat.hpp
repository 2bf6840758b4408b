#pragma once
/// \file
/// The Tpetra names that changed between releases, in one place. Trilinos 13.2 (Debian 12) says
/// getNodeNumElements/getNodeNumRows where later releases say getLocalNumElements/
/// getLocalNumRows; calling these wrappers keeps the rest of railfe version-neutral.

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

namespace railfe {

/// Number of indices of \p map on this rank.
inline std::size_t local_size(const Tpetra::Map<>& map) {
  return map.getNodeNumElements();
}

/// Number of rows of \p matrix on this rank.
inline std::size_t local_rows(const Tpetra::CrsMatrix<double>& matrix) {
  return matrix.getNodeNumRows();
}

/// Length of \p vector on this rank.
inline std::size_t local_length(const Tpetra::MultiVector<double>& vector) {
  return vector.getLocalLength();
}

}  // namespace railfe
