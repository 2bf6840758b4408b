#pragma once
/// \file
/// The largest eigenvalue of a symmetric operator distributed over ranks, by Lanczos iteration:
/// the global estimate of a mesh's highest frequency that calibrates the element-by-element
/// stable step (the extreme Ritz value converges in tens of products, far faster than power
/// iteration on the dense top of a mesh's spectrum).

#include <cstddef>
#include <functional>

#include "framework/base/parallel.hpp"
#include "framework/base/types.hpp"

namespace railfe {

/// Estimates the largest eigenvalue of the symmetric operator A from \p add_product (w += A q
/// over this rank's \p n entries; collective), starting from a vector that depends only on
/// \p global_index (the global index of local entry i), so every rank count starts alike. The
/// caller lends two arrays of \p n entries, \p q and \p p, whose contents are overwritten: the
/// two-vector form of the recurrence lets a solver borrow arrays that are idle at that moment
/// instead of allocating. Stops when the largest Ritz value changes by less than \p tolerance
/// (relative) or after \p max_iterations products. The Ritz value is a lower bound that converges
/// from below.
double largest_eigenvalue(const std::function<void(const double*, double*)>& add_product,
                          std::size_t n,
                          const std::function<GlobalIndex(std::size_t)>& global_index, double* q,
                          double* p, const Communicator& comm, double tolerance = 1e-6,
                          int max_iterations = 80);

}  // namespace railfe
