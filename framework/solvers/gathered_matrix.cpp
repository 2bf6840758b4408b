#include "framework/solvers/gathered_matrix.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/assembly/tpetra_compat.hpp"
#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"

namespace railfe {

GatheredMatrix::GatheredMatrix(const TpetraMatrix& A) {
  const auto comm = A.getComm();
  on_root_ = comm->getRank() == 0;
  const auto row_map = A.getRowMap();
  const auto owned = row_map->getNodeElementList();
  // Rank 0 asks for every row, in the ranks' order.
  const std::vector<long long> mine(owned.begin(), owned.end());
  const std::vector<GlobalIndex> all = communicator_of(*comm).gather_to_root(mine);
  global_indices_ = all;
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  root_map_ = Teuchos::rcp(new TpetraMap(
      invalid, Teuchos::ArrayView<const GlobalIndex>(all.data(), all.size()), 0, comm));
  importer_ = Teuchos::rcp(new TpetraImport(row_map, root_map_));
  const auto root_matrix = Tpetra::importAndFillCompleteCrsMatrix<TpetraMatrix>(
      Teuchos::rcpFromRef(A), *importer_, root_map_, root_map_);

  if (!on_root_)
    return;
  auto local = root_matrix->getLocalMatrixHost();
  const auto& column_map = *root_matrix->getColMap();
  const long n = static_cast<long>(all.size());
  row_offsets_.assign(n + 1, 0);
  columns_.reserve(local.values.extent(0));
  values_.reserve(local.values.extent(0));
  for (long row = 0; row < n; ++row) {
    for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k) {
      columns_.push_back(
          root_map_->getLocalElement(column_map.getGlobalElement(local.graph.entries(k))));
      values_.push_back(local.values(k));
    }
    row_offsets_[row + 1] = static_cast<long>(columns_.size());
  }
}

std::vector<double> GatheredMatrix::gather(const TpetraMultiVector& b) const {
  const std::size_t n_columns = b.getNumVectors();
  TpetraMultiVector root(root_map_, n_columns);
  root.doImport(b, *importer_, Tpetra::INSERT);
  if (!on_root_)
    return {};
  std::vector<double> values(n_rows() * n_columns);
  root.get1dCopy(Teuchos::ArrayView<double>(values.data(), values.size()), n_rows());
  return values;
}

void GatheredMatrix::scatter(const std::vector<double>& root_values, TpetraMultiVector& x) const {
  const std::size_t n_columns = x.getNumVectors();
  TpetraMultiVector root(root_map_, n_columns);
  if (on_root_) {
    for (std::size_t j = 0; j < n_columns; ++j) {
      auto column = root.getDataNonConst(j);
      std::copy(root_values.begin() + j * n_rows(), root_values.begin() + (j + 1) * n_rows(),
                column.begin());
    }
  }
  x.doExport(root, *importer_, Tpetra::INSERT);
}

Communicator communicator_of(const Teuchos::Comm<int>& comm) {
  return Communicator(*dynamic_cast<const Teuchos::MpiComm<int>&>(comm).getRawMpiComm());
}

void share_root_verdict(const TpetraMatrix& A, const std::string& root_problem) {
  std::string message = root_problem;
  communicator_of(*A.getComm()).broadcast(message);
  if (!message.empty())
    throw RunError(message);
}

}  // namespace railfe
