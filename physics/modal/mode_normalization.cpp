#include "physics/modal/mode_normalization.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace railfe {

namespace {

// Values within this relative distance of the largest count as ties for the pivot; round-off
// between runs is far smaller, real differences between DOFs far larger.
constexpr double kTieTolerance = 1e-6;

// The pivot (lowest global index within the tie tolerance of the largest) of the per-DOF
// magnitudes \p magnitude over the owned DOFs of \p modes (collective).
GlobalIndex pivot_of(const TpetraMultiVector& modes, const std::vector<double>& magnitude) {
  const auto& comm = *modes.getMap()->getComm();
  double local_max = 0;
  for (double value : magnitude)
    local_max = std::max(local_max, value);
  double global_max = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local_max, Teuchos::outArg(global_max));
  GlobalIndex local_first = std::numeric_limits<GlobalIndex>::max();
  for (std::size_t i = 0; i < magnitude.size(); ++i) {
    if (magnitude[i] >= (1 - kTieTolerance) * global_max) {
      local_first = std::min(local_first, modes.getMap()->getGlobalElement(i));
    }
  }
  GlobalIndex first = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, local_first, Teuchos::outArg(first));
  return first;
}

// Column \p j's value at global DOF \p dof (collective).
double value_at(const TpetraMultiVector& modes, std::size_t j, GlobalIndex dof) {
  const auto local = modes.getMap()->getLocalElement(dof);
  double mine = 0;
  if (local != Teuchos::OrdinalTraits<LocalIndex>::invalid())
    mine = modes.getData(j)[local];
  double value = 0;
  Teuchos::reduceAll(*modes.getMap()->getComm(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(value));
  return value;
}

void make_pivot_positive(TpetraMultiVector& modes, std::size_t j) {
  const auto data = modes.getData(j);
  std::vector<double> magnitude(data.size());
  for (std::size_t i = 0; i < magnitude.size(); ++i)
    magnitude[i] = std::abs(data[i]);
  if (value_at(modes, j, pivot_of(modes, magnitude)) < 0)
    modes.getVectorNonConst(j)->scale(-1.0);
}

void rotate_doublet(TpetraMultiVector& modes, std::size_t i) {
  std::vector<double> energy;
  {
    const auto a = modes.getData(i), b = modes.getData(i + 1);
    energy.resize(a.size());
    for (std::size_t k = 0; k < energy.size(); ++k)
      energy[k] = a[k] * a[k] + b[k] * b[k];
  }
  const GlobalIndex pivot = pivot_of(modes, energy);
  const double a = value_at(modes, i, pivot), b = value_at(modes, i + 1, pivot);
  const double radius = std::hypot(a, b);
  if (radius > 0) {
    const double c = a / radius, s = b / radius;
    auto first = modes.getDataNonConst(i);
    auto second = modes.getDataNonConst(i + 1);
    for (decltype(first.size()) k = 0; k < first.size(); ++k) {
      const double u = first[k], v = second[k];
      first[k] = c * u + s * v;
      second[k] = -s * u + c * v;
    }
  }
  make_pivot_positive(modes, i + 1);
}

// Replaces columns 0..k-1 of \p modes (a k-dimensional rigid-body eigenspace) by the
// M-orthonormalized projections of the rigid motions onto it; false (nothing changed) if fewer
// than k independent projections exist.
bool canonical_rigid_modes(TpetraMultiVector& modes, std::size_t k, const TpetraMatrix& K,
                           const TpetraMatrix& M, const TpetraMultiVector& rigid_basis,
                           std::vector<double>& eigenvalues) {
  const auto comm = modes.getMap()->getComm();
  const std::size_t n_rigid = rigid_basis.getNumVectors();
  const auto span = modes.subCopy(Teuchos::Range1D(0, k - 1));
  TpetraMultiVector mass_rigid(M.getRangeMap(), n_rigid);
  M.apply(rigid_basis, mass_rigid);
  const auto replicated = Teuchos::rcp(new TpetraMap(k, 0, comm, Tpetra::LocallyReplicated));
  TpetraMultiVector coefficients(replicated, n_rigid);
  coefficients.multiply(Teuchos::TRANS, Teuchos::NO_TRANS, 1.0, *span, mass_rigid, 0.0);
  TpetraMultiVector projected(modes.getMap(), n_rigid);
  projected.multiply(Teuchos::NO_TRANS, Teuchos::NO_TRANS, 1.0, *span, coefficients, 0.0);

  std::vector<Teuchos::RCP<TpetraVector>> accepted;
  TpetraVector mass_times(M.getRangeMap());
  for (std::size_t j = 0; j < n_rigid && accepted.size() < k; ++j) {
    auto candidate = Teuchos::rcp(new TpetraVector(*projected.getVector(j), Teuchos::Copy));
    M.apply(*rigid_basis.getVector(j), mass_times);
    const double reference = std::sqrt(std::abs(rigid_basis.getVector(j)->dot(mass_times)));
    for (int pass = 0; pass < 2; ++pass) {  // twice is enough (Kahan-Parlett)
      for (const auto& q : accepted) {
        M.apply(*q, mass_times);
        candidate->update(-candidate->dot(mass_times), *q, 1.0);
      }
    }
    M.apply(*candidate, mass_times);
    const double norm = std::sqrt(std::abs(candidate->dot(mass_times)));
    if (norm > 1e-6 * reference) {
      candidate->scale(1.0 / norm);
      accepted.push_back(candidate);
    }
  }
  if (accepted.size() < k)
    return false;
  TpetraVector stiffness_times(K.getRangeMap());
  for (std::size_t j = 0; j < k; ++j) {
    modes.getVectorNonConst(j)->update(1.0, *accepted[j], 0.0);
    K.apply(*accepted[j], stiffness_times);
    eigenvalues[j] = accepted[j]->dot(stiffness_times);
  }
  return true;
}

}  // namespace

void canonicalize_modes(std::vector<double>& eigenvalues, TpetraMultiVector& modes,
                        const TpetraMatrix& K, const TpetraMatrix& M,
                        const TpetraMultiVector& rigid_basis, double rigid_limit,
                        double doublet_tolerance) {
  const std::size_t n = eigenvalues.size();
  std::size_t n_rigid = 0;
  while (n_rigid < n && std::abs(eigenvalues[n_rigid]) < rigid_limit)
    ++n_rigid;
  if (n_rigid > 0 && canonical_rigid_modes(modes, n_rigid, K, M, rigid_basis, eigenvalues)) {
    // done: the rigid-body block no longer depends on round-off
  } else {
    n_rigid = 0;
  }
  // Only a degenerate pair may be rotated: the modes of a pair split by more than round-off (a
  // wheel refined over an arc, paired for naming by a loose Doublet tolerance) are unique up to
  // sign, and mixing them breaks K phi = lambda M phi by about the split (the squeal demo wheel's
  // 0.7 % gave backward errors of 3e-8 against the check's 1e-8).
  const double degenerate = std::min(doublet_tolerance, kDegenerateTolerance);
  auto close = [&](std::size_t a, std::size_t b) {
    const double scale = std::max(std::abs(eigenvalues[a]), std::abs(eigenvalues[b]));
    return std::abs(eigenvalues[a] - eigenvalues[b]) <= degenerate * scale;
  };
  std::size_t i = n_rigid;
  while (i < n) {
    std::size_t end = i + 1;
    while (end < n && close(end - 1, end))
      ++end;
    if (end - i == 2) {
      rotate_doublet(modes, i);
    } else {
      for (std::size_t j = i; j < end; ++j)
        make_pivot_positive(modes, j);
    }
    i = end;
  }
}

}  // namespace railfe
