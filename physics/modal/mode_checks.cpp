#include "physics/modal/mode_checks.hpp"

#include <Teuchos_SerialDenseMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>

#include "framework/assembly/tpetra_compat.hpp"

namespace railfe {

namespace {

// ||A||∞, the largest absolute row sum (collective).
double infinity_norm(const TpetraMatrix& A) {
  auto local = A.getLocalMatrixHost();
  double row_max = 0;
  for (std::size_t row = 0; row < local_rows(A); ++row) {
    double sum = 0;
    for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k)
      sum += std::abs(local.values(k));
    row_max = std::max(row_max, sum);
  }
  double global = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MAX, row_max, Teuchos::outArg(global));
  return global;
}

}  // namespace

std::vector<ModeCheck> check_modes(const TpetraMatrix& K, const TpetraMatrix& M,
                                   const std::vector<double>& eigenvalues,
                                   const TpetraMultiVector& modes,
                                   const TpetraMultiVector& translations,
                                   double doublet_tolerance) {
  const int n = static_cast<int>(eigenvalues.size());
  std::vector<ModeCheck> checks(n);
  if (n == 0)
    return checks;
  const double k_norm = infinity_norm(K);
  const double m_norm = infinity_norm(M);

  TpetraMultiVector stiffness_times(K.getRangeMap(), n), mass_times(M.getRangeMap(), n);
  K.apply(modes, stiffness_times);
  M.apply(modes, mass_times);

  // Gram matrix ΦᵀMΦ in one reduction.
  Teuchos::SerialDenseMatrix<int, double> gram(n, n);
  TpetraMultiVector gram_vectors(
      Teuchos::rcp(new TpetraMap(n, 0, K.getComm(), Tpetra::LocallyReplicated)), n);
  gram_vectors.multiply(Teuchos::TRANS, Teuchos::NO_TRANS, 1.0, modes, mass_times, 0.0);

  TpetraMultiVector participation(
      Teuchos::rcp(new TpetraMap(n, 0, K.getComm(), Tpetra::LocallyReplicated)), 3);
  participation.multiply(Teuchos::TRANS, Teuchos::NO_TRANS, 1.0, mass_times, translations, 0.0);

  for (int i = 0; i < n; ++i) {
    ModeCheck& check = checks[i];
    const double lambda = eigenvalues[i];
    auto residual = stiffness_times.getVectorNonConst(i);
    residual->update(-lambda, *mass_times.getVector(i), 1.0);
    const double phi_norm = modes.getVector(i)->normInf();
    const double denominator = (k_norm + std::abs(lambda) * m_norm) * phi_norm;
    check.backward_error = denominator > 0 ? residual->normInf() / denominator : 0.0;
    const auto gram_column = gram_vectors.getData(i);
    for (int j = 0; j < n; ++j) {
      if (j == i)
        check.normalization_error = std::abs(gram_column[j] - 1.0);
      else
        check.orthogonality = std::max(check.orthogonality, std::abs(gram_column[j]));
    }
    check.modal_mass = phi_norm > 0 ? 1.0 / (phi_norm * phi_norm) : 0.0;
    for (int d = 0; d < 3; ++d) {
      const double gamma = participation.getData(d)[i];
      check.effective_mass[d] = gamma * gamma;
    }
    for (int j = 0; j < n; ++j) {
      if (j == i)
        continue;
      const double scale = std::max(std::abs(eigenvalues[i]), std::abs(eigenvalues[j]));
      const bool close = std::abs(eigenvalues[i] - eigenvalues[j]) <= doublet_tolerance * scale;
      const bool nearer = check.partner < 0 || std::abs(eigenvalues[j] - lambda) <
                                                   std::abs(eigenvalues[check.partner] - lambda);
      if (close && nearer)
        check.partner = j;
    }
  }
  return checks;
}

TpetraMultiVector rigid_translations(const DofMap& dofs) {
  TpetraMultiVector translations(dofs.owned_map(), 3);
  for (int d = 0; d < 3; ++d) {
    auto column = translations.getDataNonConst(d);
    for (LocalIndex node = 0; node < dofs.partition().n_owned_nodes(); ++node)
      column[dofs.local_dof(node, d)] = 1.0;
  }
  return translations;
}

}  // namespace railfe
