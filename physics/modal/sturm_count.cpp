#include "physics/modal/sturm_count.hpp"

#include <cholmod.h>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <cstring>
#include <string>

#include "framework/base/error.hpp"
#include "framework/solvers/gathered_matrix.hpp"

namespace railfe {

namespace {

// Negative pivots of a simplicial LDLᵀ of the gathered symmetric matrix, or −1 on breakdown.
long long negative_pivots(const GatheredMatrix& matrix, std::string& problem) {
  cholmod_common common;
  cholmod_l_start(&common);
  common.supernodal = CHOLMOD_SIMPLICIAL;
  common.final_ll = 0;  // keep LDLᵀ: D carries the inertia
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_METIS;
  common.print = 0;
  common.quick_return_if_not_posdef = 0;
  const long n = matrix.n_rows();
  const long nnz = matrix.row_offsets()[n];
  cholmod_sparse* A = cholmod_l_allocate_sparse(n, n, nnz, 0, 1, -1, CHOLMOD_REAL, &common);
  std::memcpy(A->p, matrix.row_offsets().data(), sizeof(long) * (n + 1));
  std::memcpy(A->i, matrix.columns().data(), sizeof(long) * nnz);
  std::memcpy(A->x, matrix.values().data(), sizeof(double) * nnz);
  cholmod_factor* L = cholmod_l_analyze(A, &common);
  long long count = -1;
  if (L != nullptr && cholmod_l_factorize(A, L, &common) && L->minor == static_cast<size_t>(n)) {
    // Simplicial LDLᵀ stores D on the diagonal of L, the first entry of each column.
    const auto* p = static_cast<const long*>(L->p);
    const auto* x = static_cast<const double*>(L->x);
    count = 0;
    for (long j = 0; j < n; ++j)
      count += x[p[j]] < 0 ? 1 : 0;
  } else {
    problem = "the LDL^T factorization of K - sigma M broke down (status " +
              std::to_string(common.status) +
              "): sigma lies on an eigenvalue or the matrix needs pivoting";
  }
  cholmod_l_free_factor(&L, &common);
  cholmod_l_free_sparse(&A, &common);
  cholmod_l_finish(&common);
  return count;
}

}  // namespace

long long count_eigenvalues_below(const TpetraMatrix& K, const TpetraMatrix& M, double sigma) {
  const auto shifted = Tpetra::MatrixMatrix::add(1.0, false, K, -sigma, false, M);
  const GatheredMatrix gathered(*shifted);
  std::string problem;
  double count = 0;
  if (gathered.on_root())
    count = static_cast<double>(negative_pivots(gathered, problem));
  share_root_verdict(*shifted, problem);
  std::vector<double> shared{count};
  communicator_of(*K.getComm()).broadcast(shared);
  return static_cast<long long>(shared[0]);
}

}  // namespace railfe
