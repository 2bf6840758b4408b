#pragma once
/// \file
/// SIMD lanes for the batched solid kernel: kLanes doubles as one GCC/Clang vector-extension
/// value, whose arithmetic is lane by lane with the rounding of scalar code (the compiler maps it
/// to one AVX-512 register, two AVX2 ones or four SSE2 ones). The helpers below (select, any,
/// maximum, root) have a double overload too, so the element arithmetic is written once as a
/// template and serves one element (double) or kLanes elements (Lanes).

#include <cmath>

namespace railfe {

/// Inlined always, so that each SIMD clone of the batched kernel (target_clones) compiles the
/// element arithmetic for its own instruction set.
#define RAILFE_LANE_INLINE inline __attribute__((always_inline))

/// Elements per batch of the batched kernel.
inline constexpr int kLanes = 8;
/// kLanes doubles, one element's value in each lane.
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
/// The result of comparing two Lanes: all bits set in a lane where the comparison holds.
using LaneMask = decltype(Lanes{} < Lanes{});

/// a where \p mask holds, else b.
RAILFE_LANE_INLINE double select(bool mask, double a, double b) {
  return mask ? a : b;
}
/// a in the lanes where \p mask holds, b in the others.
RAILFE_LANE_INLINE Lanes select(LaneMask mask, Lanes a, Lanes b) {
  return mask ? a : b;
}

/// Whether \p mask holds.
RAILFE_LANE_INLINE bool any(bool mask) {
  return mask;
}
/// Whether \p mask holds in at least one lane.
RAILFE_LANE_INLINE bool any(LaneMask mask) {
  auto bits = mask[0];
  for (int l = 1; l < kLanes; ++l)
    bits |= mask[l];
  return bits != 0;
}

/// The larger of \p a and \p b (b where a < b), as std::max.
template <class T>
RAILFE_LANE_INLINE T maximum(T a, T b) {
  return select(a < b, b, a);
}

/// √x.
RAILFE_LANE_INLINE double root(double x) {
  return std::sqrt(x);
}
/// √x in every lane (one vector instruction where errno is not kept: -fno-math-errno).
RAILFE_LANE_INLINE Lanes root(Lanes x) {
  Lanes r;
  for (int l = 0; l < kLanes; ++l)
    r[l] = std::sqrt(x[l]);
  return r;
}

}  // namespace railfe
