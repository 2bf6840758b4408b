#pragma once
/// \file
/// Sizes of the eigensolver's Krylov spaces, decided before they are built. A Krylov space can
/// hold no more vectors than the problem has free degrees of freedom (fixed DOFs carry no mass,
/// so (K − σM)⁻¹M maps everything into the free ones), less the modes of earlier batches it is
/// kept M-orthogonal to; one that large or larger cannot be extended, and Krylov–Schur restarts
/// forever on a space it cannot grow. Every space stays at least one vector below that bound. The
/// same rules run at check time (input errors naming the parameter at fault) and before every
/// batch, so neither can ask for a space the model cannot hold.
///
/// The batch sizes of a frequency band come from the band and the model: a small first batch
/// that shows how fast the mode count grows with frequency, then the whole band as extrapolated
/// from it, solved again from scratch in one batch (the estimate errs high: running short costs
/// another batch, M-orthogonal to the modes found). Cost is operator applications, and a batch
/// that converges in one filling of its Krylov space costs that space: a batch of the whole
/// band costs what a deck told the count would, and the first batch only its own small space.
/// Measured on the wheel, 128 modes below 10 kHz: 16 modes in 64 vectors, then 134 in 408,
/// take 66 + 416 operator applications; a single batch of 140 (the count known) 432; the
/// earlier defaults, 32 in 96 then 108 beyond them in 328, 164 + 552. A later batch's space
/// is sized for every mode of the band, not for the batch alone (a space for the batch alone
/// restarts).

#include <string>
#include <vector>

namespace railfe {

/// The Krylov space of one eigensolver batch, or why it cannot be built.
struct KrylovPlan {
  /// The model is small enough to solve densely (kDenseEigenLimit): every free mode at once, no
  /// Krylov space (block_size and blocks are 0).
  bool dense = false;
  int block_size = 0;     ///< vectors per block
  int blocks = 0;         ///< blocks in the space
  std::string problem;    ///< why the request cannot be met ("" when it can)
  std::string parameter;  ///< the deck parameter most likely at fault ("Modes", "Krylov blocks")
  std::string allowed;    ///< what that parameter may be, for the message
  /// Vectors in the space.
  int dimension() const { return block_size * blocks; }
};

/// Models with at most this many free DOFs are solved densely, all their modes at once: a
/// Krylov space must stay below the free DOFs, so a vehicle of 18 free DOFs could give 16 of
/// its 18 modes, and a dense solve of a few hundred rows takes milliseconds.
constexpr long long kDenseEigenLimit = 400;

/// The block size for a batch of \p n_modes when the deck leaves it automatic (0): wide blocks
/// pass more right-hand sides through the factor at once and find doublets together, but a
/// block much wider than a sixteenth of the batch makes the space grow in coarse steps (measured
/// on the wheel: block 8 best for 140 modes, 16 slower).
int automatic_block_size(int n_modes);

/// The Krylov space for \p n_modes eigenpairs in blocks of \p block_size (0 = automatic) with
/// \p krylov_blocks blocks (0 = about three times the modes, and at least \p minimum_space
/// vectors), in a model with \p free_dofs free DOFs of which \p deflated are spanned by modes
/// found earlier. Sets problem and parameter when no space fits. With \p allow_dense, a first
/// batch (no \p deflated) of a model within kDenseEigenLimit with automatic blocks is planned
/// dense.
KrylovPlan plan_krylov_space(int n_modes, int block_size, int krylov_blocks, long long free_dofs,
                             long long deflated = 0, int minimum_space = 0,
                             bool allow_dense = false);

/// The smallest automatic Krylov space (vectors) for a batch of a frequency band that holds
/// \p band_modes modes, found and wanted: three times them, and at least 48 more than them (a
/// small first batch restarts in less).
int band_space(int band_modes);

/// The most modes a single batch can ask for in a model with \p free_dofs free DOFs (blocks of
/// \p block_size, 0 = automatic), for messages.
int largest_batch(int block_size, long long free_dofs);

/// The first batch of a frequency band when the deck leaves Modes automatic (0).
int automatic_first_batch(long long free_dofs);

/// Modes to ask for in the next batch of a band whose upper end is \p band_high (Hz), given the
/// frequencies found so far (ascending, rigid-body modes as 0) and \p minimum, the smallest
/// batch worth running. The count is extrapolated as N(f) ∝ f^α with α fitted to the upper half
/// of the modes found (clamped to [0.5, 3]: beams to 3-D solids), plus a margin.
int next_band_batch(const std::vector<double>& frequencies, double band_high, int minimum);

/// Batches a frequency band may take before the run stops with an error naming the band: a
/// bound on the search loop (the free DOFs bound it too, as every batch adds modes); the
/// estimate normally needs two.
constexpr int kMaximumBandBatches = 40;

}  // namespace railfe
