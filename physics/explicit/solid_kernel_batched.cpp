// The batched one-point hex8 kernel: kLanes elements at a time, one per SIMD lane. Each batch
// gathers its elements' nodes and constants into lanes (structure of arrays), runs the scalar
// kernel's arithmetic (solid_element_forces.hpp) on whole lanes, and scatters the forces one
// element after the other, so elements that share nodes add in the scalar kernel's order.
//
// The pass is compiled for AVX-512 (target attribute) and runs only where the CPU has it
// (checked at run time), whatever the build's -march: with AVX2 alone its 8-lane vectors take
// two registers each and it ran 11 % slower than the scalar kernel (SSE2: 1.7 times slower), so
// there add_internal_forces() keeps the scalar kernel. This file is compiled with
// -fno-math-errno so that √ is one vector instruction.
#include <algorithm>
#include <cstring>

#include "physics/elements/hex8_one_point.hpp"
#include "physics/explicit/solid_element_forces.hpp"
#include "physics/explicit/solid_kernel.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#define RAILFE_SIMD_TARGET __attribute__((target("avx512f")))
#define RAILFE_HAS_SIMD_TARGET 1
#else
#define RAILFE_SIMD_TARGET
#define RAILFE_HAS_SIMD_TARGET 0
#endif

namespace railfe {

namespace {

// What the kernel reads of one batch, lane l holding element element[l].
struct Batch {
  std::size_t offsets[kLanes][8];   // 3 × node of lane l's node a
  Lanes u[8][3], v[8][3], x[8][3];  // displacement, velocity, current position
  Lanes gradient[24];               // mean gradients [i × 8 + a]
  Lanes projection[12];             // hourglass projections [α × 3 + i]
};

// The lanes of a per-element field: contiguous for a full batch.
RAILFE_LANE_INLINE Lanes lanes_of(const std::vector<double>& field, LocalIndex first,
                                  const LocalIndex element[kLanes], bool full) {
  Lanes values;
  if (full) {
    std::memcpy(&values, &field[first], sizeof(values));
  } else {
    for (int l = 0; l < kLanes; ++l)
      values[l] = field[element[l]];
  }
  return values;
}

// Gathers the nodal values and stored element data of the batch's elements into \p batch, four
// values of an element at a time (transpose_rows()). A node's x, y, z are read with the next
// node's x, which the last local node has not: a batch that holds it is gathered value by value.
RAILFE_LANE_INLINE void gather(const SolidElements& elements, const LocalIndex element[kLanes],
                               bool hourglass, const double* coordinates, const double* u,
                               const double* v, Batch& batch) {
  const double* nodal[3] = {u, v, coordinates};
  Lanes(*fields[3])[3] = {batch.u, batch.v, batch.x};
  // Lanes 0 to count - 1 hold elements element[0] onwards; the others copy the last of them.
  const int count = static_cast<int>(element[kLanes - 1] - element[0]) + 1;
  const LocalIndex* nodes = &elements.nodes[8 * static_cast<std::size_t>(element[0])];
  std::size_t* offsets = &batch.offsets[0][0];
  LocalIndex highest = 0;
  for (int k = 0; k < 8 * count; ++k) {
    highest = std::max(highest, nodes[k]);
    offsets[k] = 3 * static_cast<std::size_t>(nodes[k]);
  }
  for (int l = count; l < kLanes; ++l)
    std::copy_n(batch.offsets[count - 1], 8, batch.offsets[l]);
  if (highest + 1 < elements.n_nodes) {
    for (int a = 0; a < 8; ++a)
      for (int f = 0; f < 3; ++f) {
        Lanes columns[4];
        transpose_rows(nodal[f], &batch.offsets[0][a], 8, columns);
        for (int i = 0; i < 3; ++i)
          fields[f][a][i] = columns[i];
      }
  } else {
    for (int a = 0; a < 8; ++a)
      for (int f = 0; f < 3; ++f)
        for (int i = 0; i < 3; ++i)
          for (int l = 0; l < kLanes; ++l)
            fields[f][a][i][l] = nodal[f][batch.offsets[l][a] + i];
  }
  std::size_t element_offsets[kLanes];
  for (int l = 0; l < kLanes; ++l)
    element_offsets[l] = 24 * static_cast<std::size_t>(element[l]);
  for (int k = 0; k < 24; k += 4)
    transpose_rows(elements.gradients.data() + k, element_offsets, 1, batch.gradient + k);
  if (hourglass) {
    // h_α · X_i from the reference coordinates, as build_solid_elements() stored them (same
    // sums in the same order, products by ±1 exact): computing them reads 96 bytes less per
    // element.
    for (int alpha = 0; alpha < 4; ++alpha)
      for (int i = 0; i < 3; ++i) {
        Lanes sum{};
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
RAILFE_LANE_INLINE void scatter(const Lanes fe[8][3], const std::size_t offsets[kLanes][8],
                                LocalIndex count, double* forces) {
  using Pair = double __attribute__((vector_size(2 * sizeof(double))));
  Quad rows[8][kLanes];
  for (int a = 0; a < 8; ++a)
    transpose_columns(fe[a], rows[a]);
  for (int l = 0; l < count; ++l)
    for (int a = 0; a < 8; ++a) {
      double* node = forces + offsets[l][a];
      const Quad row = rows[a][l];
      Pair xy;
      std::memcpy(&xy, node, sizeof(Pair));
      xy += __builtin_shufflevector(row, row, 0, 1);
      std::memcpy(node, &xy, sizeof(Pair));
      node[2] += row[2];
    }
}

// Elements ahead of the batch whose stored data is fetched into the caches while it computes:
// the next batch (1e5 elements: 2 and 4 batches ahead measured 4-6 % slower).
constexpr LocalIndex kPrefetchDistance = kLanes;

// Asks for the stored data of the batch starting at element \p first: ten sequential streams,
// more than the hardware prefetchers follow (at 1e5 elements this took the step from 0.148 to
// 0.118 µs CPU per element-step; prefetching nodal rows as well made it slower).
RAILFE_LANE_INLINE void prefetch(const SolidElements& elements, LocalIndex first) {
  if (first + kLanes > elements.n_elements)
    return;
  const std::size_t e = static_cast<std::size_t>(first);
  for (int line = 0; line < 24 * kLanes; line += 8)
    __builtin_prefetch(&elements.gradients[24 * e + line]);
  for (int line = 0; line < 8 * kLanes; line += 16)
    __builtin_prefetch(&elements.nodes[8 * e + line]);
  for (const auto* field :
       {&elements.lambda, &elements.mu, &elements.density, &elements.wave_speed, &elements.length,
        &elements.volume, &elements.hourglass_scale, &elements.stable_step})
    __builtin_prefetch(field->data() + e);
}

RAILFE_SIMD_TARGET SolidForceTotals batched_pass(const SolidElements& elements,
                                                 const SolidKernelSettings& settings,
                                                 const double* coordinates, const double* u,
                                                 const double* v, double* forces) {
  SolidForceTotals totals;
  const bool stiffness_form = settings.hourglass == HourglassForm::stiffness;
  const bool hourglass = settings.hourglass != HourglassForm::none;
  Lanes lane_index;
  for (int l = 0; l < kLanes; ++l)
    lane_index[l] = l;
  Lanes strain{}, hourglass_energy{}, hourglass_power{}, viscous_power{};
  Batch batch;
  const LocalIndex n = elements.n_elements;
  for (LocalIndex first = 0; first < n; first += kLanes) {
    const LocalIndex count = std::min<LocalIndex>(kLanes, n - first);
    const bool full = count == kLanes;
    LocalIndex element[kLanes];
    for (int l = 0; l < kLanes; ++l)
      element[l] = first + std::min<LocalIndex>(l, count - 1);
    prefetch(elements, first + kPrefetchDistance);
    gather(elements, element, hourglass, coordinates, u, v, batch);

    const SolidElementConstants<Lanes> constants{
        lanes_of(elements.lambda, first, element, full),
        lanes_of(elements.mu, first, element, full),
        lanes_of(elements.density, first, element, full),
        lanes_of(elements.wave_speed, first, element, full),
        lanes_of(elements.length, first, element, full)};
    const Lanes volume = lanes_of(elements.volume, first, element, full);
    Lanes fe[8][3] = {};
    Lanes jacobian, div, viscous{}, energy{}, power{};
    const Lanes point_strain = add_point_forces(batch.gradient, volume, batch.u, batch.v, constants,
                                                settings, fe, viscous, jacobian, div);
    const Lanes length = jacobian * volume / largest_face_area(batch.x);
    if (hourglass) {
      Lanes gamma[32];
      hex8_hourglass_vectors(batch.projection, batch.gradient, gamma);
      add_hourglass_forces(gamma, lanes_of(elements.hourglass_scale, first, element, full),
                           stiffness_form ? batch.u : batch.v, stiffness_form, fe, energy, power);
    }
    const LaneMask valid = lane_index < static_cast<double>(count);
    strain += select(valid, point_strain, Lanes{});
    viscous_power += select(valid, viscous, Lanes{});
    hourglass_energy += select(valid, energy, Lanes{});
    hourglass_power += select(valid, power, Lanes{});

    scatter(fe, batch.offsets, count, forces);
    const Lanes step = current_stable_step(
        lanes_of(elements.stable_step, first, element, full), constants.length, length,
        select(div < 0.0, div, Lanes{}), constants.wave_speed, settings);
    for (int l = 0; l < count; ++l)
      if (step[l] < totals.stable_step) {
        totals.stable_step = step[l];
        totals.critical_element = first + l;
      }
  }
  for (int l = 0; l < kLanes; ++l) {
    totals.strain_energy += strain[l];
    totals.hourglass_energy += hourglass_energy[l];
    totals.hourglass_power += hourglass_power[l];
    totals.viscous_power += viscous_power[l];
  }
  return totals;
}

}  // namespace

bool batched_kernel_available() {
#if RAILFE_HAS_SIMD_TARGET
  static const bool available = __builtin_cpu_supports("avx512f");
  return available;
#else
  return false;
#endif
}

SolidForceTotals add_internal_forces_batched(const SolidElements& elements,
                                             const SolidKernelSettings& settings,
                                             const double* coordinates, const double* u,
                                             const double* v, double* forces) {
  return batched_pass(elements, settings, coordinates, u, v, forces);
}

}  // namespace railfe
