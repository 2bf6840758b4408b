#pragma once
/// \file
/// The Sturm sequence check: by Sylvester's law of inertia, the number of negative pivots of an
/// LDLᵀ factorization of K − σM equals the number of eigenvalues of K φ = λ M φ below σ. It
/// counts modes without computing them, so it proves that an eigensolver missed none below σ
/// (a lost doublet partner, a mode skipped by a poor shift), as production Lanczos codes do.

#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

/// Number of eigenvalues of K φ = λ M φ below \p sigma (collective; factorizes on rank 0 with
/// CHOLMOD's simplicial LDLᵀ, which accepts indefinite matrices but costs several times a
/// supernodal Cholesky). DOFs whose rows of M are zero carry no eigenvalue and must have a
/// positive diagonal in K. Throws RunError when the factorization breaks down (σ exactly at an
/// eigenvalue, or a zero pivot).
long long count_eigenvalues_below(const TpetraMatrix& K, const TpetraMatrix& M, double sigma);

}  // namespace railfe
