// The batched one-point hex8 kernel: W elements at a time, one per SIMD lane. Each batch
// gathers its elements' nodes and constants into lanes (structure of arrays), runs the scalar
// kernel's arithmetic (solid_element_forces.hpp) on whole lanes, and scatters the forces one
// element after the other, so elements that share nodes add in the scalar kernel's order.
//
// The pass is compiled twice, by target attributes whatever the build's -march: 8 lanes for
// AVX-512 and 4 lanes for AVX2 with FMA, and the CPU's widest runs (checked at run time). 8 lanes
// on AVX2 take two registers each and ran 11 % slower than the scalar kernel (SSE2: 1.7 times
// slower), so there is no 8-lane AVX2 pass; without AVX2, add_internal_forces() keeps the scalar
// kernel. This file is compiled with -fno-math-errno so that √ is one vector instruction.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "physics/elements/hex8_one_point.hpp"
#include "physics/explicit/solid_element_forces.hpp"
#include "physics/explicit/solid_kernel.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#define RAILFE_WIDE_TARGET __attribute__((target("avx512f")))
#define RAILFE_NARROW_TARGET __attribute__((target("avx2,fma")))
#define RAILFE_HAS_SIMD_TARGET 1
#else
#define RAILFE_WIDE_TARGET
#define RAILFE_NARROW_TARGET
#define RAILFE_HAS_SIMD_TARGET 0
#endif

namespace railfe {

namespace {

// What the kernel reads of one batch of W elements, lane l holding element element[l].
template <int W>
struct Batch {
  std::size_t offsets[W][8];           // 3 × node of lane l's node a
  Lanes<W> u[8][3], v[8][3], x[8][3];  // displacement, velocity, current position
  Lanes<W> gradient[24];               // mean gradients [i × 8 + a]
  Lanes<W> projection[12];             // hourglass projections [α × 3 + i]
};

// The lanes of a per-element field: contiguous for a full batch.
template <int W>
RAILFE_LANE_INLINE Lanes<W> lanes_of(const std::vector<double>& field, LocalIndex first,
                                     const LocalIndex element[W], bool full) {
  Lanes<W> values;
  if (full) {
    values = load<W>(&field[first]);
  } else {
    for (int l = 0; l < W; ++l)
      values[l] = field[element[l]];
  }
  return values;
}

// Gathers the nodal values and stored element data of the batch's elements into \p batch, four
// values of an element at a time (transpose_rows()). A node's x, y, z are read with the next
// node's x, which the last local node has not: a batch that holds it is gathered value by value.
template <int W>
RAILFE_LANE_INLINE void gather(const SolidElements& elements, const LocalIndex element[W],
                               bool hourglass, const double* coordinates, const double* u,
                               const double* v, Batch<W>& batch) {
  const double* nodal[3] = {u, v, coordinates};
  Lanes<W>(*fields[3])[3] = {batch.u, batch.v, batch.x};
  // Lanes 0 to count - 1 hold elements element[0] onwards; the others copy the last of them.
  const int count = static_cast<int>(element[W - 1] - element[0]) + 1;
  const LocalIndex* nodes = &elements.nodes[8 * static_cast<std::size_t>(element[0])];
  std::size_t* offsets = &batch.offsets[0][0];
  LocalIndex highest = 0;
  for (int k = 0; k < 8 * count; ++k) {
    highest = std::max(highest, nodes[k]);
    offsets[k] = 3 * static_cast<std::size_t>(nodes[k]);
  }
  for (int l = count; l < W; ++l)
    std::copy_n(batch.offsets[count - 1], 8, batch.offsets[l]);
  if (highest + 1 < elements.n_nodes) {
    for (int a = 0; a < 8; ++a)
      for (int f = 0; f < 3; ++f) {
        Lanes<W> columns[4];
        transpose_rows<W>(nodal[f], &batch.offsets[0][a], 8, columns);
        for (int i = 0; i < 3; ++i)
          fields[f][a][i] = columns[i];
      }
  } else {
    for (int a = 0; a < 8; ++a)
      for (int f = 0; f < 3; ++f)
        for (int i = 0; i < 3; ++i)
          for (int l = 0; l < W; ++l)
            fields[f][a][i][l] = nodal[f][batch.offsets[l][a] + i];
  }
  std::size_t element_offsets[W];
  for (int l = 0; l < W; ++l)
    element_offsets[l] = 24 * static_cast<std::size_t>(element[l]);
  for (int k = 0; k < 24; k += 4)
    transpose_rows<W>(elements.gradients.data() + k, element_offsets, 1, batch.gradient + k);
  if (hourglass) {
    // h_α · X_i from the reference coordinates, as build_solid_elements() stored them (same
    // sums in the same order, products by ±1 exact): computing them reads 96 bytes less per
    // element.
    for (int alpha = 0; alpha < 4; ++alpha)
      for (int i = 0; i < 3; ++i) {
        Lanes<W> sum{};
        for (int a = 0; a < 8; ++a)
          sum += kHex8HourglassBase.h[alpha][a] * batch.x[a][i];
        batch.projection[3 * alpha + i] = sum;
      }
  }
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      batch.x[a][i] += batch.u[a][i];
}

// Adds the forces \p fe of the batch's first \p count lanes to \p forces, one element after
// the other (so each nodal sum is made in the scalar kernel's order), x and y of a node as one
// pair.
template <int W>
RAILFE_LANE_INLINE void scatter(const Lanes<W> fe[8][3], const std::size_t offsets[W][8],
                                LocalIndex count, double* forces) {
  Quad rows[8][W];
  for (int a = 0; a < 8; ++a)
    transpose_columns<W>(fe[a], rows[a]);
  for (int l = 0; l < count; ++l)
    for (int a = 0; a < 8; ++a) {
      double* node = forces + offsets[l][a];
      const Quad row = rows[a][l];
      store<2>(load<2>(node) + __builtin_shufflevector(row, row, 0, 1), node);
      node[2] += row[2];
    }
}

// Asks for the stored data of the batch starting at element \p first: ten sequential streams,
// more than the hardware prefetchers follow (at 1e5 elements this took the step from 0.148 to
// 0.118 µs CPU per element-step; prefetching nodal rows as well made it slower). The next batch
// is fetched (1e5 elements, 8 lanes: 2 and 4 batches ahead measured 4-6 % slower).
template <int W>
RAILFE_LANE_INLINE void prefetch(const SolidElements& elements, LocalIndex first) {
  if (first + W > elements.n_elements)
    return;
  const std::size_t e = static_cast<std::size_t>(first);
  for (int line = 0; line < 24 * W; line += 8)
    __builtin_prefetch(&elements.gradients[24 * e + line]);
  for (int line = 0; line < 8 * W; line += 16)
    __builtin_prefetch(&elements.nodes[8 * e + line]);
  for (const auto* field :
       {&elements.lambda, &elements.mu, &elements.density, &elements.wave_speed, &elements.length,
        &elements.volume, &elements.hourglass_scale, &elements.stable_step})
    __builtin_prefetch(field->data() + e);
}

// The pass over every element, W at a time; inlined into the pass of each instruction set.
template <int W>
RAILFE_LANE_INLINE SolidForceTotals batched_pass(const SolidElements& elements,
                                                 const SolidKernelSettings& settings,
                                                 const double* coordinates, const double* u,
                                                 const double* v, double* forces) {
  using Lanes = railfe::Lanes<W>;
  SolidForceTotals totals;
  const bool stiffness_form = settings.hourglass == HourglassForm::stiffness;
  const bool hourglass = settings.hourglass != HourglassForm::none;
  Lanes lane_index;
  for (int l = 0; l < W; ++l)
    lane_index[l] = l;
  Lanes strain{}, hourglass_energy{}, hourglass_power{}, viscous_power{};
  Batch<W> batch;
  const LocalIndex n = elements.n_elements;
  for (LocalIndex first = 0; first < n; first += W) {
    const LocalIndex count = std::min<LocalIndex>(W, n - first);
    const bool full = count == W;
    LocalIndex element[W];
    for (int l = 0; l < W; ++l)
      element[l] = first + std::min<LocalIndex>(l, count - 1);
    prefetch<W>(elements, first + W);
    gather<W>(elements, element, hourglass, coordinates, u, v, batch);

    const SolidElementConstants<Lanes> constants{
        lanes_of<W>(elements.lambda, first, element, full),
        lanes_of<W>(elements.mu, first, element, full),
        lanes_of<W>(elements.density, first, element, full),
        lanes_of<W>(elements.wave_speed, first, element, full),
        lanes_of<W>(elements.length, first, element, full)};
    const Lanes volume = lanes_of<W>(elements.volume, first, element, full);
    Lanes fe[8][3] = {};
    Lanes jacobian, div, viscous{}, energy{}, power{};
    const Lanes point_strain = add_point_forces(batch.gradient, volume, batch.u, batch.v, constants,
                                                settings, fe, viscous, jacobian, div);
    const Lanes length = jacobian * volume / largest_face_area(batch.x);
    if (hourglass) {
      Lanes gamma[32];
      hex8_hourglass_vectors(batch.projection, batch.gradient, gamma);
      add_hourglass_forces(gamma, lanes_of<W>(elements.hourglass_scale, first, element, full),
                           stiffness_form ? batch.u : batch.v, stiffness_form, fe, energy, power);
    }
    const LaneMask<W> valid = lane_index < static_cast<double>(count);
    strain += select(valid, point_strain, Lanes{});
    viscous_power += select(valid, viscous, Lanes{});
    hourglass_energy += select(valid, energy, Lanes{});
    hourglass_power += select(valid, power, Lanes{});

    scatter<W>(fe, batch.offsets, count, forces);
    const Lanes step = current_stable_step(
        lanes_of<W>(elements.stable_step, first, element, full), constants.length, length,
        select(div < 0.0, div, Lanes{}), constants.wave_speed, settings);
    for (int l = 0; l < count; ++l)
      if (step[l] < totals.stable_step) {
        totals.stable_step = step[l];
        totals.critical_element = first + l;
      }
  }
  for (int l = 0; l < W; ++l) {
    totals.strain_energy += strain[l];
    totals.hourglass_energy += hourglass_energy[l];
    totals.hourglass_power += hourglass_power[l];
    totals.viscous_power += viscous_power[l];
  }
  return totals;
}

RAILFE_WIDE_TARGET SolidForceTotals wide_pass(const SolidElements& elements,
                                              const SolidKernelSettings& settings,
                                              const double* coordinates, const double* u,
                                              const double* v, double* forces) {
  return batched_pass<kWideLanes>(elements, settings, coordinates, u, v, forces);
}

RAILFE_NARROW_TARGET SolidForceTotals narrow_pass(const SolidElements& elements,
                                                  const SolidKernelSettings& settings,
                                                  const double* coordinates, const double* u,
                                                  const double* v, double* forces) {
  return batched_pass<kNarrowLanes>(elements, settings, coordinates, u, v, forces);
}

}  // namespace

bool batched_kernel_supports(int lanes) {
#if RAILFE_HAS_SIMD_TARGET
  static const bool wide = __builtin_cpu_supports("avx512f");
  static const bool narrow = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return (lanes == kWideLanes && wide) || (lanes == kNarrowLanes && narrow);
#else
  return false;
#endif
}

int batched_kernel_lanes() {
  for (const int lanes : {kWideLanes, kNarrowLanes})
    if (batched_kernel_supports(lanes))
      return lanes;
  return 0;
}

SolidForceTotals add_internal_forces_batched(const SolidElements& elements,
                                             const SolidKernelSettings& settings,
                                             const double* coordinates, const double* u,
                                             const double* v, double* forces, int lanes) {
  if (lanes == kWideLanes && batched_kernel_supports(lanes))
    return wide_pass(elements, settings, coordinates, u, v, forces);
  if (lanes == kNarrowLanes && batched_kernel_supports(lanes))
    return narrow_pass(elements, settings, coordinates, u, v, forces);
  throw std::invalid_argument("the batched solid kernel has no " + std::to_string(lanes) +
                              "-lane pass for this CPU (batched_kernel_supports)");
}

}  // namespace railfe
