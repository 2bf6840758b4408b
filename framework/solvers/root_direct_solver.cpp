#include "framework/solvers/root_direct_solver.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/base/blas_threads.hpp"
#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/solution_check.hpp"

namespace railfe {

namespace {

// Y = alpha A⁻¹ X + beta Y with the solver's current factorization of A.
class FactorOperator : public TpetraOperator {
 public:
  FactorOperator(RootDirectSolver& solver, Teuchos::RCP<const TpetraMap> map)
      : solver_(solver), map_(std::move(map)) {}

  Teuchos::RCP<const TpetraMap> getDomainMap() const override { return map_; }
  Teuchos::RCP<const TpetraMap> getRangeMap() const override { return map_; }

  void apply(const TpetraMultiVector& X, TpetraMultiVector& Y, Teuchos::ETransp /*mode*/,
             double alpha, double beta) const override {
    // A is symmetric wherever this serves as a preconditioner (CG), so the transpose is A⁻¹ too.
    TpetraMultiVector solution(map_, X.getNumVectors());
    // The preconditioned iteration checks its own residual; a backward-error check here would
    // cost a product with the old matrix every iteration.
    const bool checked = solver_.checks_solutions();
    solver_.check_solutions(false);
    solver_.solve_block(X, solution);
    solver_.check_solutions(checked);
    Y.update(alpha, solution, beta);
  }

 private:
  RootDirectSolver& solver_;
  Teuchos::RCP<const TpetraMap> map_;
};

// Rank 0 works alone while the other ranks sleep in quiet_barrier(): it may use their cores for
// BLAS threads. Below this size a factorization takes well under a second and threads cost
// more than they give.
constexpr long kThreadedRows = 50000;

int lent_threads(const GatheredMatrix& matrix, const Communicator& comm) {
  return matrix.n_rows() >= kThreadedRows ? comm.n_ranks() : 1;
}

}  // namespace

RootDirectSolver::RootDirectSolver(std::string method, double backward_error_limit)
    : method_(std::move(method)), limit_(backward_error_limit) {}

void RootDirectSolver::setup(const Teuchos::RCP<const TpetraMatrix>& A,
                             const ProblemTraits& traits) {
  Stopwatch clock;
  matrix_ = A;
  gathered_.emplace(*A);
  const Communicator comm = communicator_of(*A->getComm());
  std::string problem;
  if (gathered_->on_root()) {
    const BorrowedBlasThreads threads(lent_threads(*gathered_, comm));
    try {
      problem = factorize(*gathered_, traits);
    } catch (const std::exception& error) {
      problem = method_ + " factorization failed: " + essential_line(error.what());
    }
  }
  comm.quiet_barrier();
  share_root_verdict(*A, problem);
  setup_seconds_ = clock.seconds();
}

Teuchos::RCP<TpetraOperator> RootDirectSolver::factor_operator() {
  if (matrix_.is_null())
    return Teuchos::null;
  return Teuchos::rcp(new FactorOperator(*this, matrix_->getRangeMap()));
}

SolveReport RootDirectSolver::solve(const TpetraVector& b, TpetraVector& x) {
  return solve_block(b, x);
}

SolveReport RootDirectSolver::solve_block(const TpetraMultiVector& B, TpetraMultiVector& X) {
  Stopwatch clock;
  const int n_columns = static_cast<int>(B.getNumVectors());
  const std::vector<double> rhs = gathered_->gather(B);
  std::vector<double> solution;
  std::string problem;
  const Communicator comm = communicator_of(*matrix_->getComm());
  if (gathered_->on_root()) {
    const BorrowedBlasThreads threads(lent_threads(*gathered_, comm));
    try {
      solution = solve_on_root(rhs, n_columns);
    } catch (const std::exception& error) {
      problem = method_ + " solve failed: " + essential_line(error.what());
    }
  }
  comm.quiet_barrier();
  share_root_verdict(*matrix_, problem);
  gathered_->scatter(solution, X);
  SolveReport report;
  report.method = method_ + " (on rank 0)";
  for (int j = 0; check_solutions_ && j < n_columns; ++j) {
    const ResidualNorms norms = residual_norms(*matrix_, *X.getVector(j), *B.getVector(j));
    if (j == 0 || norms.backward_error > report.backward_error) {
      report.relative_residual = norms.relative_residual;
      report.backward_error = norms.backward_error;
    }
    require_backward_error(norms, limit_, method_);
  }
  report.setup_seconds = setup_seconds_;
  report.solve_seconds = clock.seconds();
  return report;
}

}  // namespace railfe
