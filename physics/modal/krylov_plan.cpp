#include "physics/modal/krylov_plan.hpp"

#include <algorithm>
#include <cmath>

namespace railfe {

namespace {

int ceil_div(long long a, long long b) {
  return static_cast<int>((a + b - 1) / b);
}

// Krylov-Schur keeps the wanted Ritz vectors plus at least one block to extend them.
int minimum_blocks(int n_modes, int block_size) {
  return ceil_div(n_modes, block_size) + 1;
}

}  // namespace

int automatic_block_size(int n_modes) {
  if (n_modes >= 96)
    return 8;
  if (n_modes >= 32)
    return 4;
  return 2;
}

KrylovPlan plan_krylov_space(int n_modes, int block_size, int krylov_blocks, long long free_dofs,
                             long long deflated, int minimum_space, bool allow_dense) {
  KrylovPlan plan;
  const long long available = free_dofs - deflated;
  if (allow_dense && deflated == 0 && free_dofs <= kDenseEigenLimit && block_size == 0 &&
      krylov_blocks == 0) {
    plan.dense = true;
    if (n_modes > free_dofs) {
      plan.parameter = "Modes";
      plan.problem = std::to_string(n_modes) + " modes, but the model has only " +
                     std::to_string(free_dofs) + " free DOFs";
      plan.allowed = "at most " + std::to_string(free_dofs) + " modes for this model";
    }
    return plan;
  }
  plan.block_size = block_size > 0 ? block_size : automatic_block_size(n_modes);
  // An automatic block narrows when the wide one leaves no room for a block to extend the space.
  while (block_size == 0 && plan.block_size > 1 &&
         minimum_blocks(n_modes, plan.block_size) > (available - 1) / plan.block_size)
    plan.block_size /= 2;
  // A space as large as the free DOFs is invariant: Krylov-Schur cannot extend it and never
  // stops (measured: 120 vectors on 120 free DOFs hangs, 119 converges), so one vector less.
  const long long fitting_blocks = std::max(0LL, (available - 1) / plan.block_size);
  const int needed = minimum_blocks(n_modes, plan.block_size);
  const std::string dofs = std::to_string(free_dofs) + " free DOFs";
  if (needed > fitting_blocks) {
    // No space the model can hold is large enough: too many modes for the model.
    plan.parameter = "Modes";
    plan.problem = std::to_string(n_modes) + " modes" +
                   (deflated > 0 ? " beyond the " + std::to_string(deflated) + " found" : "") +
                   " need a Krylov space of at least " + std::to_string(needed * plan.block_size) +
                   " vectors (" + std::to_string(needed) + " blocks of " +
                   std::to_string(plan.block_size) + "), but the model has only " + dofs +
                   (deflated > 0 ? " (" + std::to_string(available) + " left)" : "");
    plan.allowed = "at most " + std::to_string(largest_batch(block_size, available)) +
                   " modes for this model, or a finer mesh";
    return plan;
  }
  if (krylov_blocks == 0) {
    // Three times the wanted modes: with two, Krylov-Schur restarts so often that it needs
    // twice the operator applications (measured on the wheel, 140 modes: 832 against 432).
    const int wanted = std::max({3 * n_modes, n_modes + 20, minimum_space});
    plan.blocks =
        static_cast<int>(std::min<long long>(ceil_div(wanted, plan.block_size), fitting_blocks));
    return plan;
  }
  plan.blocks = krylov_blocks;
  if (plan.blocks < needed) {
    plan.parameter = "Krylov blocks";
    plan.problem = std::to_string(plan.blocks) + " blocks of " + std::to_string(plan.block_size) +
                   " vectors cannot hold " + std::to_string(n_modes) +
                   " modes and a block to extend them";
    plan.allowed = "at least " + std::to_string(needed) + " blocks, or 0 (automatic)";
  } else if (plan.blocks > fitting_blocks) {
    plan.parameter = "Krylov blocks";
    plan.problem = std::to_string(plan.blocks) + " blocks of " + std::to_string(plan.block_size) +
                   " vectors (" + std::to_string(plan.dimension()) +
                   ") do not fit below the model's " + dofs +
                   (deflated > 0 ? " less the " + std::to_string(deflated) + " modes found" : "");
    plan.allowed = "at most " + std::to_string(fitting_blocks) + " blocks, or 0 (automatic)";
  }
  return plan;
}

int band_space(int band_modes) {
  // On the wheel 16 modes took 82 operator applications in 48 vectors (restarting) and 58 or
  // 66 in 56 or 64 (one filling); 10 modes without a band take 52 in 30 but 60 in 58, so the
  // wider space is kept to bands.
  return std::max(3 * band_modes, band_modes + 48);
}

int largest_batch(int block_size, long long free_dofs) {
  // An automatic block narrows down to single vectors when the model is small.
  const long long size = block_size > 0 ? block_size : 1;
  return static_cast<int>(std::max(0LL, ((free_dofs - 1) / size - 1) * size));
}

int automatic_first_batch(long long free_dofs) {
  // Enough modes to see how the count grows (measured on the wheel: 16 estimate 134 modes for
  // its 128, as 32 do, but 8 or 12 only 46 or 42), and no more than an eighth of what the model
  // can resolve so that the rest of the band still fits. Every mode more here costs more than
  // it saves: the continuation's space is sized for the whole band in any case.
  return static_cast<int>(std::max(1LL, std::min<long long>(16, free_dofs / 8)));
}

int next_band_batch(const std::vector<double>& frequencies, double band_high, int minimum) {
  const int n = static_cast<int>(frequencies.size());
  int estimate = 2 * n;  // without a usable fit, double the modes found
  const int half = n / 2;
  if (n >= 4 && frequencies[half - 1] > 0 && frequencies[n - 1] > frequencies[half - 1]) {
    const double alpha = std::clamp(std::log(static_cast<double>(n) / half) /
                                        std::log(frequencies[n - 1] / frequencies[half - 1]),
                                    0.5, 3.0);
    const double total = n * std::pow(band_high / frequencies[n - 1], alpha);
    // A margin of 15 %: running short costs another batch deep in the spectrum, where small
    // batches converge slowly; running over costs a few Ritz vectors.
    estimate = static_cast<int>(std::ceil(1.15 * total));
  }
  return std::max(minimum, estimate - n);
}

}  // namespace railfe
