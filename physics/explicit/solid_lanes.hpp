#pragma once
/// \file
/// SIMD lanes for the batched solid kernel: W doubles as one GCC/Clang vector-extension value,
/// whose arithmetic is lane by lane with the rounding of scalar code (W = 8: one AVX-512
/// register; W = 4: one AVX2 register). The helpers below (select, any, maximum, root) serve a
/// double too, so the element arithmetic is written once as a template and serves one element
/// (double) or W elements (Lanes<W>).

#include <cmath>
#include <cstddef>

// Lanes cross no call (everything here is always inlined), so GCC's note that 64-byte vectors
// are passed differently with and without AVX-512 does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace railfe {

/// Inlined always, so that the batched kernel, compiled for AVX-512 or AVX2 by a target
/// attribute, compiles the element arithmetic for that instruction set whatever the build's
/// -march.
#define RAILFE_LANE_INLINE inline __attribute__((always_inline))

/// Elements per batch where the CPU has AVX-512: one 512-bit register of doubles.
inline constexpr int kWideLanes = 8;
/// Elements per batch where it has AVX2 and FMA only: one 256-bit register.
inline constexpr int kNarrowLanes = 4;

/// W doubles as one vector-extension value, one element's value in each lane.
template <int W>
struct LaneVector {
  typedef double type __attribute__((vector_size(W * sizeof(double))));  ///< the vector type
  /// The same at any double's address (aligned to 8 bytes, aliasing double).
  typedef double unaligned
      __attribute__((vector_size(W * sizeof(double)), aligned(sizeof(double)), may_alias));
};
/// W doubles, one element's value in each lane (W = kWideLanes or kNarrowLanes).
template <int W>
using Lanes = typename LaneVector<W>::type;
/// The result of comparing two Lanes<W>: all bits set in a lane where the comparison holds.
template <int W>
using LaneMask = decltype(Lanes<W>{} < Lanes<W>{});

/// The W doubles from \p values on (any alignment), as one vector load. (std::memcpy into a
/// vector is copied in 16-byte pieces under some tunings, e.g. znver3, and the whole vector read
/// back from the stack then waits for both stores: that stall was a quarter of the 4-lane pass.)
template <int W>
RAILFE_LANE_INLINE Lanes<W> load(const double* values) {
  return *reinterpret_cast<const typename LaneVector<W>::unaligned*>(values);
}

/// Writes \p lanes to the W doubles from \p values on (any alignment), as one vector store.
template <int W>
RAILFE_LANE_INLINE void store(Lanes<W> lanes, double* values) {
  *reinterpret_cast<typename LaneVector<W>::unaligned*>(values) = lanes;
}

/// a where \p mask holds, else b: lane by lane for Lanes (\p mask a LaneMask), or for one double
/// (\p mask a bool).
template <class T>
RAILFE_LANE_INLINE T select(decltype(T{} < T{}) mask, T a, T b) {
  return mask ? a : b;
}

/// Whether \p mask holds.
RAILFE_LANE_INLINE bool any(bool mask) {
  return mask;
}
/// Whether \p mask (a LaneMask) holds in at least one lane.
template <class Mask>
RAILFE_LANE_INLINE bool any(Mask mask) {
  auto bits = mask[0];
  for (std::size_t l = 1; l < sizeof(Mask) / sizeof(bits); ++l)
    bits |= mask[l];
  return bits != 0;
}

/// The larger of \p a and \p b (b where a < b), as std::max.
template <class T>
RAILFE_LANE_INLINE T maximum(T a, T b) {
  return select(a < b, b, a);
}

/// Four doubles: one row of transpose_rows().
using Quad = Lanes<4>;

/// Reads 4 doubles at base + offsets[l × stride] for each lane l (any alignment) into \p columns:
/// value c of row l goes to lane l of columns[c]. W row loads and 2W permutations, where filling
/// lanes one value at a time takes 4W loads and 4W stores (and stalls on the stores).
template <int W>
RAILFE_LANE_INLINE void transpose_rows(const double* base, const std::size_t* offsets, int stride,
                                       Lanes<W> columns[4]) {
  static_assert(W == kWideLanes || W == kNarrowLanes, "the permutations are those of 8 or 4 lanes");
  Quad quads[W];
  for (int l = 0; l < W; ++l)
    quads[l] = load<4>(base + offsets[l * stride]);
  if constexpr (W == kNarrowLanes) {
    // Values 0 and 2 of rows 0, 1 (then 2, 3) interleaved; values 1 and 3 likewise.
    const Quad even[2] = {__builtin_shufflevector(quads[0], quads[1], 0, 4, 2, 6),
                          __builtin_shufflevector(quads[2], quads[3], 0, 4, 2, 6)};
    const Quad odd[2] = {__builtin_shufflevector(quads[0], quads[1], 1, 5, 3, 7),
                         __builtin_shufflevector(quads[2], quads[3], 1, 5, 3, 7)};
    columns[0] = __builtin_shufflevector(even[0], even[1], 0, 1, 4, 5);
    columns[1] = __builtin_shufflevector(odd[0], odd[1], 0, 1, 4, 5);
    columns[2] = __builtin_shufflevector(even[0], even[1], 2, 3, 6, 7);
    columns[3] = __builtin_shufflevector(odd[0], odd[1], 2, 3, 6, 7);
  } else {
    Lanes<W> pairs[4];  // rows 2k and 2k + 1
    for (int k = 0; k < 4; ++k)
      pairs[k] = __builtin_shufflevector(quads[2 * k], quads[2 * k + 1], 0, 1, 2, 3, 4, 5, 6, 7);
    // Values 0, 1 (first half) and 2, 3 (second half) of rows 0-3, then of rows 4-7.
    const Lanes<W> low[2] = {__builtin_shufflevector(pairs[0], pairs[1], 0, 4, 8, 12, 1, 5, 9, 13),
                             __builtin_shufflevector(pairs[2], pairs[3], 0, 4, 8, 12, 1, 5, 9, 13)};
    const Lanes<W> high[2] = {
        __builtin_shufflevector(pairs[0], pairs[1], 2, 6, 10, 14, 3, 7, 11, 15),
        __builtin_shufflevector(pairs[2], pairs[3], 2, 6, 10, 14, 3, 7, 11, 15)};
    columns[0] = __builtin_shufflevector(low[0], low[1], 0, 1, 2, 3, 8, 9, 10, 11);
    columns[1] = __builtin_shufflevector(low[0], low[1], 4, 5, 6, 7, 12, 13, 14, 15);
    columns[2] = __builtin_shufflevector(high[0], high[1], 0, 1, 2, 3, 8, 9, 10, 11);
    columns[3] = __builtin_shufflevector(high[0], high[1], 4, 5, 6, 7, 12, 13, 14, 15);
  }
}

/// The inverse of transpose_rows() for three columns: row l of \p rows is (x, y, z, 0) of lane l
/// of \p columns. 2W permutations.
template <int W>
RAILFE_LANE_INLINE void transpose_columns(const Lanes<W> columns[3], Quad rows[W]) {
  const Lanes<W> zero{};
  if constexpr (W == kNarrowLanes) {
    // x, y of lanes 0, 1 (then 2, 3) interleaved; z, 0 likewise.
    const Quad xy[2] = {__builtin_shufflevector(columns[0], columns[1], 0, 4, 1, 5),
                        __builtin_shufflevector(columns[0], columns[1], 2, 6, 3, 7)};
    const Quad z0[2] = {__builtin_shufflevector(columns[2], zero, 0, 4, 1, 5),
                        __builtin_shufflevector(columns[2], zero, 2, 6, 3, 7)};
    for (int k = 0; k < 2; ++k) {
      rows[2 * k] = __builtin_shufflevector(xy[k], z0[k], 0, 1, 4, 5);
      rows[2 * k + 1] = __builtin_shufflevector(xy[k], z0[k], 2, 3, 6, 7);
    }
  } else {
    // x and y of lanes 0-3, then 4-7; z and 0 likewise.
    const Lanes<W> low[2] = {
        __builtin_shufflevector(columns[0], columns[1], 0, 1, 2, 3, 8, 9, 10, 11),
        __builtin_shufflevector(columns[0], columns[1], 4, 5, 6, 7, 12, 13, 14, 15)};
    const Lanes<W> high[2] = {
        __builtin_shufflevector(columns[2], zero, 0, 1, 2, 3, 8, 9, 10, 11),
        __builtin_shufflevector(columns[2], zero, 4, 5, 6, 7, 12, 13, 14, 15)};
    for (int k = 0; k < 2; ++k) {
      const Lanes<W> first = __builtin_shufflevector(low[k], high[k], 0, 4, 8, 12, 1, 5, 9, 13);
      const Lanes<W> second = __builtin_shufflevector(low[k], high[k], 2, 6, 10, 14, 3, 7, 11, 15);
      rows[4 * k] = __builtin_shufflevector(first, first, 0, 1, 2, 3);
      rows[4 * k + 1] = __builtin_shufflevector(first, first, 4, 5, 6, 7);
      rows[4 * k + 2] = __builtin_shufflevector(second, second, 0, 1, 2, 3);
      rows[4 * k + 3] = __builtin_shufflevector(second, second, 4, 5, 6, 7);
    }
  }
}

/// √x.
RAILFE_LANE_INLINE double root(double x) {
  return std::sqrt(x);
}
/// √x in every lane of \p x (a Lanes; one vector instruction where errno is not kept:
/// -fno-math-errno).
template <class V>
RAILFE_LANE_INLINE V root(V x) {
  V r;
  for (std::size_t l = 0; l < sizeof(V) / sizeof(double); ++l)
    r[l] = std::sqrt(x[l]);
  return r;
}

}  // namespace railfe

#pragma GCC diagnostic pop
