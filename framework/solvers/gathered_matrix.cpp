#include "framework/solvers/gathered_matrix.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/assembly/tpetra_compat.hpp"
#include "framework/base/error.hpp"

namespace railfe {

GatheredMatrix::GatheredMatrix(const TpetraMatrix& A) {
  const auto comm = A.getComm();
  on_root_ = comm->getRank() == 0;
  const auto row_map = A.getRowMap();
  const auto owned = row_map->getNodeElementList();
  // Rank 0 asks for every row; the order of rows on rank 0 is the ranks' order.
  const int n_ranks = comm->getSize();
  int count = static_cast<int>(owned.size());
  std::vector<int> counts(n_ranks), offsets(n_ranks, 0);
  Teuchos::gatherAll(*comm, 1, &count, n_ranks, counts.data());
  long total = 0;
  for (int r = 0; r < n_ranks; ++r) {
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  std::vector<GlobalIndex> all(on_root_ ? total : 0);
  std::vector<GlobalIndex> mine(owned.begin(), owned.end());
  if (n_ranks == 1) {
    all = mine;
  } else {
    // Teuchos has no gatherv; the MPI communicator underneath is used directly.
    const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(comm.get());
    MPI_Gatherv(mine.data(), count, MPI_LONG_LONG, all.data(), counts.data(), offsets.data(),
                MPI_LONG_LONG, 0, *mpi->getRawMpiComm());
  }
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

std::vector<double> GatheredMatrix::gather(const TpetraVector& b) const {
  TpetraVector root(root_map_);
  root.doImport(b, *importer_, Tpetra::INSERT);
  if (!on_root_)
    return {};
  const auto data = root.getData();
  return std::vector<double>(data.begin(), data.end());
}

void GatheredMatrix::scatter(const std::vector<double>& root_values, TpetraVector& x) const {
  TpetraVector root(root_map_);
  if (on_root_) {
    auto data = root.getDataNonConst();
    std::copy(root_values.begin(), root_values.end(), data.begin());
  }
  x.doExport(root, *importer_, Tpetra::INSERT);
}

void share_root_verdict(const TpetraMatrix& A, const std::string& root_problem) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(A.getComm().get());
  std::string message = root_problem;
  unsigned long long length = message.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, *mpi->getRawMpiComm());
  message.resize(length);
  if (length > 0)
    MPI_Bcast(message.data(), static_cast<int>(length), MPI_CHAR, 0, *mpi->getRawMpiComm());
  if (length > 0)
    throw RunError(message);
}

std::string describe_dof(GlobalIndex dof, int dofs_per_node) {
  static const char* kAxes = "xyz";
  const int component = static_cast<int>(dof % dofs_per_node);
  const std::string name =
      dofs_per_node == 3 ? std::string(1, kAxes[component]) : std::to_string(component + 1);
  return "node " + std::to_string(dof / dofs_per_node + 1) + " component " + name;
}

}  // namespace railfe
