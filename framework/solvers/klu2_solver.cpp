#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/root_direct_solver.hpp"

namespace railfe {

namespace {

// Amesos2's KLU2 gives wrong answers on any communicator of more than one rank in Trilinos 13.2,
// so it only ever sees a copy of the matrix on a one-rank communicator on rank 0.
class Klu2Solver : public RootDirectSolver {
 public:
  explicit Klu2Solver(double limit) : RootDirectSolver("Amesos2 KLU2 sparse LU", limit) {}

 protected:
  std::string factorize(const GatheredMatrix& matrix, const ProblemTraits&) override {
    const long n = matrix.n_rows();
    auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    map_ = Teuchos::rcp(new TpetraMap(n, 0, self));
    const auto& offsets = matrix.row_offsets();
    Teuchos::Array<std::size_t> counts(n);
    for (long row = 0; row < n; ++row)
      counts[row] = offsets[row + 1] - offsets[row];
    auto local = Teuchos::rcp(new TpetraMatrix(map_, counts()));
    std::vector<GlobalIndex> columns;
    for (long row = 0; row < n; ++row) {
      columns.assign(matrix.columns().begin() + offsets[row],
                     matrix.columns().begin() + offsets[row + 1]);
      local->insertGlobalValues(
          row, Teuchos::ArrayView<const GlobalIndex>(columns.data(), columns.size()),
          Teuchos::ArrayView<const double>(matrix.values().data() + offsets[row], columns.size()));
    }
    local->fillComplete();
    local_matrix_ = local;
    solver_ = Amesos2::create<TpetraMatrix, TpetraMultiVector>("KLU2", local_matrix_);
    solver_->symbolicFactorization().numericFactorization();
    return "";
  }

  std::vector<double> solve_on_root(const std::vector<double>& rhs, int n_columns) override {
    const std::size_t n = rhs.size() / n_columns;
    auto B = Teuchos::rcp(new TpetraMultiVector(map_, n_columns));
    auto X = Teuchos::rcp(new TpetraMultiVector(map_, n_columns));
    for (int j = 0; j < n_columns; ++j) {
      auto column = B->getDataNonConst(j);
      std::copy(rhs.begin() + j * n, rhs.begin() + (j + 1) * n, column.begin());
    }
    solver_->solve(X.ptr(), B.ptr());
    std::vector<double> solution(rhs.size());
    X->get1dCopy(Teuchos::ArrayView<double>(solution.data(), solution.size()), n);
    return solution;
  }

 private:
  Teuchos::RCP<const TpetraMap> map_;
  Teuchos::RCP<const TpetraMatrix> local_matrix_;
  Teuchos::RCP<Amesos2::Solver<TpetraMatrix, TpetraMultiVector>> solver_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_klu2_solver(double backward_error_limit) {
  return std::make_unique<Klu2Solver>(backward_error_limit);
}

}  // namespace railfe
