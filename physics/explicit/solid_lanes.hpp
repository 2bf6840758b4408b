#pragma once
/// \file
/// SIMD lanes for the batched solid kernel: kLanes doubles as one GCC/Clang vector-extension
/// value, whose arithmetic is lane by lane with the rounding of scalar code (the compiler maps it
/// to one AVX-512 register, two AVX2 ones or four SSE2 ones). The helpers below (select, any,
/// maximum, root) have a double overload too, so the element arithmetic is written once as a
/// template and serves one element (double) or kLanes elements (Lanes).

#include <cmath>
#include <cstddef>
#include <cstring>

// Lanes cross no call (everything here is always inlined), so GCC's note that 64-byte vectors
// are passed differently with and without AVX-512 does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace railfe {

/// Inlined always, so that the batched kernel, compiled for AVX-512 by a target attribute,
/// compiles the element arithmetic for that instruction set whatever the build's -march.
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

/// Four doubles: one row of transpose_rows().
using Quad = double __attribute__((vector_size(4 * sizeof(double))));

/// Reads 4 doubles at base + offsets[l × stride] for each lane l (any alignment) into \p columns:
/// value c of row l goes to lane l of columns[c]. Eight row loads and eight permutations, where
/// filling lanes one value at a time takes 32 loads and 32 stores (and stalls on the stores).
RAILFE_LANE_INLINE void transpose_rows(const double* base, const std::size_t* offsets, int stride,
                                       Lanes columns[4]) {
  static_assert(kLanes == 8, "the permutations below are those of 8 lanes");
  Quad quads[kLanes];
  for (int l = 0; l < kLanes; ++l)
    std::memcpy(&quads[l], base + offsets[l * stride], sizeof(Quad));
  Lanes pairs[4];  // rows 2k and 2k + 1
  for (int k = 0; k < 4; ++k)
    pairs[k] = __builtin_shufflevector(quads[2 * k], quads[2 * k + 1], 0, 1, 2, 3, 4, 5, 6, 7);
  // Values 0, 1 (first half) and 2, 3 (second half) of rows 0-3, then of rows 4-7.
  const Lanes low[2] = {__builtin_shufflevector(pairs[0], pairs[1], 0, 4, 8, 12, 1, 5, 9, 13),
                        __builtin_shufflevector(pairs[2], pairs[3], 0, 4, 8, 12, 1, 5, 9, 13)};
  const Lanes high[2] = {__builtin_shufflevector(pairs[0], pairs[1], 2, 6, 10, 14, 3, 7, 11, 15),
                         __builtin_shufflevector(pairs[2], pairs[3], 2, 6, 10, 14, 3, 7, 11, 15)};
  columns[0] = __builtin_shufflevector(low[0], low[1], 0, 1, 2, 3, 8, 9, 10, 11);
  columns[1] = __builtin_shufflevector(low[0], low[1], 4, 5, 6, 7, 12, 13, 14, 15);
  columns[2] = __builtin_shufflevector(high[0], high[1], 0, 1, 2, 3, 8, 9, 10, 11);
  columns[3] = __builtin_shufflevector(high[0], high[1], 4, 5, 6, 7, 12, 13, 14, 15);
}

/// The inverse of transpose_rows() for three columns: row l of \p rows is (x, y, z, 0) of lane l
/// of \p columns. Eight permutations.
RAILFE_LANE_INLINE void transpose_columns(const Lanes columns[3], Quad rows[kLanes]) {
  const Lanes zero{};
  // x and y of lanes 0-3, then 4-7; z and 0 likewise.
  const Lanes low[2] = {
      __builtin_shufflevector(columns[0], columns[1], 0, 1, 2, 3, 8, 9, 10, 11),
      __builtin_shufflevector(columns[0], columns[1], 4, 5, 6, 7, 12, 13, 14, 15)};
  const Lanes high[2] = {__builtin_shufflevector(columns[2], zero, 0, 1, 2, 3, 8, 9, 10, 11),
                         __builtin_shufflevector(columns[2], zero, 4, 5, 6, 7, 12, 13, 14, 15)};
  for (int k = 0; k < 2; ++k) {
    const Lanes first = __builtin_shufflevector(low[k], high[k], 0, 4, 8, 12, 1, 5, 9, 13);
    const Lanes second = __builtin_shufflevector(low[k], high[k], 2, 6, 10, 14, 3, 7, 11, 15);
    rows[4 * k] = __builtin_shufflevector(first, first, 0, 1, 2, 3);
    rows[4 * k + 1] = __builtin_shufflevector(first, first, 4, 5, 6, 7);
    rows[4 * k + 2] = __builtin_shufflevector(second, second, 0, 1, 2, 3);
    rows[4 * k + 3] = __builtin_shufflevector(second, second, 4, 5, 6, 7);
  }
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

#pragma GCC diagnostic pop
