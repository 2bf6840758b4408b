#include "framework/solvers/solution_check.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "framework/assembly/tpetra_compat.hpp"
#include "framework/base/error.hpp"

namespace railfe {

ResidualNorms residual_norms(const TpetraMatrix& A, const TpetraVector& x, const TpetraVector& b) {
  TpetraVector residual(b.getMap());
  A.apply(x, residual);
  residual.update(1.0, b, -1.0);
  ResidualNorms norms;
  const double b_norm = b.norm2();
  const double r_norm = residual.norm2();
  norms.relative_residual = b_norm > 0 ? r_norm / b_norm : r_norm;
  // ||A||∞: the largest absolute row sum.
  auto local = A.getLocalMatrixHost();
  double row_max = 0;
  for (std::size_t row = 0; row < local_rows(A); ++row) {
    double sum = 0;
    for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k) {
      sum += std::abs(local.values(k));
    }
    row_max = std::max(row_max, sum);
  }
  double a_norm = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MAX, row_max, Teuchos::outArg(a_norm));
  const double denominator = a_norm * x.normInf() + b.normInf();
  norms.backward_error = denominator > 0 ? residual.normInf() / denominator : 0.0;
  // The infinity norms take maxima, which pass over NaN entries; the 1-norms add them up, so a
  // single NaN or inf anywhere makes them non-finite and the solution is refused.
  if (!std::isfinite(x.norm1()) || !std::isfinite(residual.norm1()) || !std::isfinite(a_norm))
    norms.backward_error = norms.relative_residual = std::numeric_limits<double>::quiet_NaN();
  return norms;
}

void require_backward_error(const ResidualNorms& norms, double limit, const std::string& method) {
  if (std::isfinite(norms.backward_error) && norms.backward_error <= limit)
    return;
  std::ostringstream message;
  if (!std::isfinite(norms.backward_error)) {
    message << method
            << " returned a solution that is not finite (NaN or inf): the system is singular "
               "or its entries under- or overflow (check the material constants, densities and "
               "loads for extreme values). The result was discarded.";
    throw RunError(message.str());
  }
  message << method << " returned a wrong solution: backward error " << norms.backward_error
          << " (relative residual " << norms.relative_residual << ") exceeds the limit " << limit
          << ". The result was discarded.";
  throw RunError(message.str());
}

}  // namespace railfe
