#include <cholmod.h>

#include <cstring>

#include "framework/assembly/dof_map.hpp"
#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/root_direct_solver.hpp"

namespace railfe {

namespace {

class CholmodSolver : public RootDirectSolver {
 public:
  explicit CholmodSolver(double limit)
      : RootDirectSolver("CHOLMOD supernodal Cholesky, METIS ordering", limit) {
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

 protected:
  std::string factorize(const GatheredMatrix& matrix, const ProblemTraits& traits) override {
    release();
    if (!traits.symmetric_positive_definite) {
      return "CHOLMOD needs a symmetric positive definite matrix; use 'klu2' or 'gmres'";
    }
    const long n = matrix.n_rows();
    const long nnz = matrix.row_offsets()[n];
    // Rows of a symmetric matrix are its columns; stype -1 tells CHOLMOD to read only the lower
    // triangle of what it sees as columns.
    cholmod_sparse* A = cholmod_l_allocate_sparse(n, n, nnz, 0, 1, -1, CHOLMOD_REAL, &common_);
    std::memcpy(A->p, matrix.row_offsets().data(), sizeof(long) * (n + 1));
    std::memcpy(A->i, matrix.columns().data(), sizeof(long) * nnz);
    std::memcpy(A->x, matrix.values().data(), sizeof(double) * nnz);
    factor_ = cholmod_l_analyze(A, &common_);
    if (factor_ != nullptr)
      cholmod_l_factorize(A, factor_, &common_);
    cholmod_l_free_sparse(&A, &common_);
    if (factor_ == nullptr || common_.status == CHOLMOD_OUT_OF_MEMORY) {
      return "CHOLMOD ran out of memory factorizing " + std::to_string(n) + " equations";
    }
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      const auto* permutation = static_cast<const long*>(factor_->Perm);
      const GlobalIndex dof = matrix.global_index(permutation[factor_->minor]);
      return "the matrix is not positive definite (CHOLMOD's pivot failed at " +
             (traits.name_dof ? traits.name_dof(dof) : describe_dof(dof, traits.dofs_per_node)) +
             "): the model is probably free to move as a rigid body (check the Dirichlet "
             "conditions) or has parts without stiffness";
    }
    if (common_.status < CHOLMOD_OK) {
      return "CHOLMOD failed with status " + std::to_string(common_.status);
    }
    return "";
  }

  std::vector<double> solve_on_root(const std::vector<double>& rhs, int n_columns) override {
    const long n = static_cast<long>(rhs.size()) / n_columns;
    cholmod_dense* B = cholmod_l_allocate_dense(n, n_columns, n, CHOLMOD_REAL, &common_);
    std::memcpy(B->x, rhs.data(), sizeof(double) * rhs.size());
    cholmod_dense* X = cholmod_l_solve(CHOLMOD_A, factor_, B, &common_);
    std::vector<double> solution(static_cast<double*>(X->x),
                                 static_cast<double*>(X->x) + rhs.size());
    cholmod_l_free_dense(&X, &common_);
    cholmod_l_free_dense(&B, &common_);
    return solution;
  }

 private:
  void release() {
    if (factor_ != nullptr)
      cholmod_l_free_factor(&factor_, &common_);
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(double backward_error_limit) {
  return std::make_unique<CholmodSolver>(backward_error_limit);
}

}  // namespace railfe
