#pragma once
/// \file
/// Eigenpairs of K φ = λ M φ (λ = ω²) nearest a shift σ, by Anasazi's block Krylov–Schur method
/// on the shift-inverted operator (K − σM)⁻¹M, which is self-adjoint in the M inner product.
/// Eigenvalues near σ become the largest of the inverted operator, so a few dozen Krylov vectors
/// find hundreds of well-separated modes; the price is one factorization of K − σM.

#include <string>
#include <vector>

#include "framework/assembly/tpetra_types.hpp"
#include "framework/output/progress.hpp"
#include "framework/solvers/linear_solver.hpp"

namespace railfe {

/// How the eigensolver runs.
struct ShiftInvertSettings {
  int n_modes = 10;       ///< eigenpairs wanted (those nearest the shift)
  int block_size = 0;     ///< vectors per Krylov block; 0 = automatic (krylov_plan.hpp)
  int krylov_blocks = 0;  ///< blocks in the Krylov space; 0 = automatic (about 3 × n_modes)
  /// Vectors the automatic Krylov space holds at least: a band's batches are sized for the
  /// whole band (krylov_plan.hpp).
  int minimum_space = 0;
  long long free_dofs = 0;     ///< DOFs not fixed (bounds the space); 0 = every row of K
  int maximum_restarts = 100;  ///< restarts before giving up
  double tolerance = 1e-10;    ///< Ritz residual of the inverted problem, relative to its value
  unsigned seed = 12345;       ///< seed of the random start block (reproducible runs)
  /// Solve a small model densely (kDenseEigenLimit in krylov_plan.hpp): for the default inner
  /// solver, whose factorization already shows K − σM positive definite.
  bool allow_dense = false;
};

/// What the eigensolver found.
struct ShiftInvertResult {
  std::vector<double> eigenvalues;          ///< λ = ω² (rad²/s²), ascending
  Teuchos::RCP<TpetraMultiVector> vectors;  ///< one column per eigenvalue, φᵀMφ = 1
  int n_requested = 0;                      ///< n_modes asked for
  int krylov_dimension = 0;                 ///< block_size × krylov_blocks used
  int block_size = 0;                       ///< vectors per block used
  int restarts = 0;                         ///< restarts Anasazi needed
  long long operator_applies = 0;           ///< columns passed through (K − σM)⁻¹M
  double factor_seconds = 0;                ///< time to factorize K − σM
  double iteration_seconds = 0;             ///< time in Anasazi
  std::string inner_method;                 ///< the inner solver, for the summary
  bool converged = false;                   ///< Anasazi reported all n_modes converged
  /// Every mode of the model was computed (the dense solve of a small model): no later batch
  /// can add one.
  bool complete = false;
};

/// K φ = λ M φ with K − σM factorized once, for one or more eigensolves.
class ShiftInvertEigensolver {
 public:
  /// Sets \p inner up for K − σM with \p traits (collective). K and M share the row map; M may
  /// be singular (prescribed DOFs with zero mass rows give no eigenvalue). \p inner must outlive
  /// this object. Throws RunError if the factorization fails (e.g. K − σM not positive definite
  /// for a Cholesky inner solver).
  ShiftInvertEigensolver(Teuchos::RCP<const TpetraMatrix> K, Teuchos::RCP<const TpetraMatrix> M,
                         LinearSolver& inner, const ProblemTraits& traits, double shift);

  /// The settings.n_modes eigenpairs nearest the shift (collective), reporting operator
  /// applications to \p progress if given. With \p found (M-orthonormal modes of an earlier
  /// solve), the search runs M-orthogonal to them: the next n_modes beyond those, without
  /// recomputing them (spectrum continuation for frequency bands).
  ShiftInvertResult solve(const ShiftInvertSettings& settings, Progress* progress = nullptr,
                          Teuchos::RCP<const TpetraMultiVector> found = Teuchos::null) const;

  /// Every finite mode of a small model by a dense generalized eigensolve on rank 0 of
  /// M φ = μ (K − σM) φ, λ = σ + 1/μ (collective); what solve() does for a dense plan.
  ShiftInvertResult solve_dense(const ShiftInvertSettings& settings) const;

  /// Seconds the factorization took.
  double factor_seconds() const { return factor_seconds_; }

 private:
  Teuchos::RCP<const TpetraMatrix> K_, M_;
  LinearSolver& inner_;
  double shift_;
  Teuchos::RCP<const TpetraMatrix> shifted_;  // K − σM, which inner_ refers to
  double factor_seconds_ = 0;
};

}  // namespace railfe
