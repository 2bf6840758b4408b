#pragma once
/// \file
/// The largest eigenvalue of a symmetric operator distributed over ranks, by Lanczos iteration:
/// the global estimate of a mesh's highest frequency that calibrates the element-by-element
/// stable step (the extreme Ritz value converges in tens of products, far faster than power
/// iteration on the dense top of a mesh's spectrum).

#include <cstddef>
#include <functional>
#include <vector>

#include "framework/base/parallel.hpp"
#include "framework/base/types.hpp"

namespace railfe {

/// Estimates the largest eigenvalue of the symmetric operator \p apply (w = A q over this rank's
/// \p n entries; collective) from a start vector that depends only on \p seeds (one global
/// index per entry), so every rank count starts alike. Stops when the largest Ritz value changes
/// by less than \p tolerance (relative) or after \p max_iterations products. The Ritz value is a
/// lower bound that converges from below.
double largest_eigenvalue(const std::function<void(const double*, double*)>& apply,
                          const std::vector<GlobalIndex>& seeds, const Communicator& comm,
                          double tolerance = 1e-6, int max_iterations = 80);

}  // namespace railfe
