#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <optional>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/gathered_matrix.hpp"
#include "framework/solvers/solution_check.hpp"

namespace railfe {

namespace {

// Amesos2's KLU2 gives wrong answers on a matrix distributed over several ranks in Trilinos 13.2,
// so it only ever sees a copy of the matrix on a one-rank communicator on rank 0.
class Klu2Solver : public LinearSolver {
 public:
  explicit Klu2Solver(double limit) : limit_(limit) {}

  void setup(const Teuchos::RCP<const TpetraMatrix>& A, const ProblemTraits&) override {
    Stopwatch clock;
    matrix_ = A;
    gathered_.emplace(*A);
    std::string problem;
    if (gathered_->on_root()) {
      try {
        build_local_solver();
      } catch (const std::exception& error) {
        problem = std::string("Amesos2 KLU2 factorization failed: ") + error.what();
      }
    }
    share_root_verdict(*A, problem);
    setup_seconds_ = clock.seconds();
  }

  SolveReport solve(const TpetraVector& b, TpetraVector& x) override {
    Stopwatch clock;
    const std::vector<double> rhs = gathered_->gather(b);
    std::vector<double> solution;
    std::string problem;
    if (gathered_->on_root()) {
      try {
        auto B = Teuchos::rcp(new TpetraMultiVector(local_map_, 1));
        auto X = Teuchos::rcp(new TpetraMultiVector(local_map_, 1));
        auto data = B->getDataNonConst(0);
        std::copy(rhs.begin(), rhs.end(), data.begin());
        solver_->solve(X.ptr(), B.ptr());
        const auto result = X->getData(0);
        solution.assign(result.begin(), result.end());
      } catch (const std::exception& error) {
        problem = std::string("Amesos2 KLU2 solve failed: ") + error.what();
      }
    }
    share_root_verdict(*matrix_, problem);
    gathered_->scatter(solution, x);
    SolveReport report;
    report.method = "Amesos2 KLU2 sparse LU (on rank 0)";
    const ResidualNorms norms = residual_norms(*matrix_, x, b);
    report.relative_residual = norms.relative_residual;
    report.backward_error = norms.backward_error;
    require_backward_error(norms, limit_, "KLU2");
    report.setup_seconds = setup_seconds_;
    report.solve_seconds = clock.seconds();
    return report;
  }

 private:
  void build_local_solver() {
    const long n = gathered_->n_rows();
    auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    local_map_ = Teuchos::rcp(new TpetraMap(n, 0, self));
    const auto& offsets = gathered_->row_offsets();
    Teuchos::Array<std::size_t> counts(n);
    for (long row = 0; row < n; ++row) counts[row] = offsets[row + 1] - offsets[row];
    auto local = Teuchos::rcp(new TpetraMatrix(local_map_, counts()));
    std::vector<GlobalIndex> columns;
    for (long row = 0; row < n; ++row) {
      columns.assign(gathered_->columns().begin() + offsets[row],
                     gathered_->columns().begin() + offsets[row + 1]);
      local->insertGlobalValues(
          row, Teuchos::ArrayView<const GlobalIndex>(columns.data(), columns.size()),
          Teuchos::ArrayView<const double>(gathered_->values().data() + offsets[row],
                                           columns.size()));
    }
    local->fillComplete();
    local_matrix_ = local;
    solver_ = Amesos2::create<TpetraMatrix, TpetraMultiVector>("KLU2", local_matrix_);
    solver_->symbolicFactorization().numericFactorization();
  }

  double limit_;
  std::optional<GatheredMatrix> gathered_;
  Teuchos::RCP<const TpetraMatrix> matrix_;
  Teuchos::RCP<const TpetraMap> local_map_;
  Teuchos::RCP<const TpetraMatrix> local_matrix_;
  Teuchos::RCP<Amesos2::Solver<TpetraMatrix, TpetraMultiVector>> solver_;
  double setup_seconds_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_klu2_solver(double backward_error_limit) {
  return std::make_unique<Klu2Solver>(backward_error_limit);
}

}  // namespace railfe
