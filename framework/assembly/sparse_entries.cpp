#include "framework/assembly/sparse_entries.hpp"

#include <Tpetra_CrsMatrix.hpp>

#include <algorithm>

namespace railfe {

Teuchos::RCP<TpetraMatrix> matrix_from_entries(const Teuchos::RCP<const TpetraMap>& map,
                                               std::vector<MatrixEntry> entries) {
  std::sort(entries.begin(), entries.end(), [](const MatrixEntry& p, const MatrixEntry& q) {
    return std::tie(std::get<0>(p), std::get<1>(p)) < std::tie(std::get<0>(q), std::get<1>(q));
  });
  std::vector<MatrixEntry> merged;
  for (const MatrixEntry& entry : entries) {
    if (!merged.empty() && std::get<0>(merged.back()) == std::get<0>(entry) &&
        std::get<1>(merged.back()) == std::get<1>(entry))
      std::get<2>(merged.back()) += std::get<2>(entry);
    else
      merged.push_back(entry);
  }
  Teuchos::Array<std::size_t> row_lengths(map->getNodeNumElements(), 0);
  for (const MatrixEntry& entry : merged)
    ++row_lengths[map->getLocalElement(std::get<0>(entry))];
  auto matrix = Teuchos::rcp(new TpetraMatrix(map, row_lengths()));
  std::vector<GlobalIndex> columns;
  std::vector<double> values;
  for (std::size_t begin = 0; begin < merged.size();) {
    std::size_t end = begin;
    columns.clear();
    values.clear();
    while (end < merged.size() && std::get<0>(merged[end]) == std::get<0>(merged[begin])) {
      columns.push_back(std::get<1>(merged[end]));
      values.push_back(std::get<2>(merged[end]));
      ++end;
    }
    matrix->insertGlobalValues(
        std::get<0>(merged[begin]),
        Teuchos::ArrayView<const GlobalIndex>(columns.data(), static_cast<int>(columns.size())),
        Teuchos::ArrayView<const double>(values.data(), static_cast<int>(values.size())));
    begin = end;
  }
  matrix->fillComplete(map, map);
  return matrix;
}

}  // namespace railfe
