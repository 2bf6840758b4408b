#include "framework/solvers/root_direct_solver.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/solution_check.hpp"

namespace railfe {

RootDirectSolver::RootDirectSolver(std::string method, double backward_error_limit)
    : method_(std::move(method)), limit_(backward_error_limit) {}

void RootDirectSolver::setup(const Teuchos::RCP<const TpetraMatrix>& A,
                             const ProblemTraits& traits) {
  Stopwatch clock;
  matrix_ = A;
  gathered_.emplace(*A);
  std::string problem;
  if (gathered_->on_root()) {
    try {
      problem = factorize(*gathered_, traits);
    } catch (const std::exception& error) {
      problem = method_ + " factorization failed: " + essential_line(error.what());
    }
  }
  share_root_verdict(*A, problem);
  setup_seconds_ = clock.seconds();
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
  if (gathered_->on_root()) {
    try {
      solution = solve_on_root(rhs, n_columns);
    } catch (const std::exception& error) {
      problem = method_ + " solve failed: " + essential_line(error.what());
    }
  }
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
