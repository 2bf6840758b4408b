#include <cholmod.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <cstring>
#include <optional>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/gathered_matrix.hpp"
#include "framework/solvers/solution_check.hpp"

namespace railfe {

namespace {

class CholmodSolver : public LinearSolver {
 public:
  explicit CholmodSolver(double limit) : limit_(limit) {
    cholmod_l_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_METIS;
    common_.print = 0;
  }

  ~CholmodSolver() override {
    release();
    cholmod_l_finish(&common_);
  }

  void setup(const Teuchos::RCP<const TpetraMatrix>& A, const ProblemTraits& traits) override {
    Stopwatch clock;
    release();
    matrix_ = A;
    gathered_.emplace(*A);
    dofs_per_node_ = traits.dofs_per_node;
    std::string problem;
    if (!traits.symmetric_positive_definite) {
      problem = "CHOLMOD needs a symmetric positive definite matrix; use 'klu2' or 'gmres'";
    } else if (gathered_->on_root()) {
      problem = factorize();
    }
    share_root_verdict(*A, problem);
    setup_seconds_ = clock.seconds();
  }

  SolveReport solve(const TpetraVector& b, TpetraVector& x) override {
    Stopwatch clock;
    const std::vector<double> rhs = gathered_->gather(b);
    std::vector<double> solution;
    if (gathered_->on_root()) {
      const long n = gathered_->n_rows();
      cholmod_dense* B = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &common_);
      std::memcpy(B->x, rhs.data(), sizeof(double) * n);
      cholmod_dense* X = cholmod_l_solve(CHOLMOD_A, factor_, B, &common_);
      solution.assign(static_cast<double*>(X->x), static_cast<double*>(X->x) + n);
      cholmod_l_free_dense(&X, &common_);
      cholmod_l_free_dense(&B, &common_);
    }
    gathered_->scatter(solution, x);
    SolveReport report;
    report.method = "CHOLMOD supernodal Cholesky, METIS ordering (on rank 0)";
    const ResidualNorms norms = residual_norms(*matrix_, x, b);
    report.relative_residual = norms.relative_residual;
    report.backward_error = norms.backward_error;
    require_backward_error(norms, limit_, "CHOLMOD");
    report.setup_seconds = setup_seconds_;
    report.solve_seconds = clock.seconds();
    return report;
  }

 private:
  std::string factorize() {
    const long n = gathered_->n_rows();
    const auto& offsets = gathered_->row_offsets();
    const long nnz = offsets[n];
    // Rows of a symmetric matrix are its columns; stype -1 tells CHOLMOD to read only the lower
    // triangle of what it sees as columns.
    cholmod_sparse* A = cholmod_l_allocate_sparse(n, n, nnz, 0, 1, -1, CHOLMOD_REAL, &common_);
    std::memcpy(A->p, offsets.data(), sizeof(long) * (n + 1));
    std::memcpy(A->i, gathered_->columns().data(), sizeof(long) * nnz);
    std::memcpy(A->x, gathered_->values().data(), sizeof(double) * nnz);
    factor_ = cholmod_l_analyze(A, &common_);
    if (factor_ != nullptr) cholmod_l_factorize(A, factor_, &common_);
    cholmod_l_free_sparse(&A, &common_);
    if (factor_ == nullptr || common_.status == CHOLMOD_OUT_OF_MEMORY) {
      return "CHOLMOD ran out of memory factorizing " + std::to_string(n) + " equations";
    }
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      const auto* permutation = static_cast<const long*>(factor_->Perm);
      const long pivot = permutation[factor_->minor];
      const GlobalIndex dof = gathered_->global_index(pivot);
      return "the matrix is not positive definite (CHOLMOD's pivot failed at " +
             describe_dof(dof, dofs_per_node_) +
             "): the model is probably free to move as a rigid body (check the Dirichlet "
             "conditions) or has parts without stiffness";
    }
    if (common_.status < CHOLMOD_OK) {
      return "CHOLMOD failed with status " + std::to_string(common_.status);
    }
    return "";
  }

  void release() {
    if (factor_ != nullptr) cholmod_l_free_factor(&factor_, &common_);
  }

  double limit_;
  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  std::optional<GatheredMatrix> gathered_;
  Teuchos::RCP<const TpetraMatrix> matrix_;
  double setup_seconds_ = 0;
  int dofs_per_node_ = 1;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(double backward_error_limit) {
  return std::make_unique<CholmodSolver>(backward_error_limit);
}

}  // namespace railfe
