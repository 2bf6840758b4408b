#pragma once
/// \file
/// The hex8 force kernel of explicit dynamics: total-Lagrangian St. Venant–Kirchhoff solids,
/// one-point integration with Flanagan–Belytschko hourglass control or 2×2×2 full integration,
/// linear and quadratic bulk viscosity, and each element's stable step. The elements of a rank
/// are stored as structure of arrays, in an order that keeps their nodes close in memory; the
/// hot loop makes no virtual call and no allocation (docs/theory.md#explicit-dynamics).

#include <string>
#include <utility>
#include <vector>

#include "framework/base/types.hpp"

namespace railfe {
class MeshPartition;
class MaterialTable;
}  // namespace railfe

namespace railfe {

/// How hourglass modes of one-point elements are resisted.
enum class HourglassForm {
  none,       ///< not at all (only for tests that show why it is needed)
  viscous,    ///< forces proportional to hourglass velocities (dissipative)
  stiffness,  ///< forces proportional to hourglass displacements (elastic, stored energy)
};

/// Settings of the solid force kernel, from the deck.
struct SolidKernelSettings {
  bool full_integration = false;                       ///< 2×2×2 Gauss points, no hourglass
  HourglassForm hourglass = HourglassForm::stiffness;  ///< one-point hourglass control
  double hourglass_coefficient = 0.03;                 ///< κ of the hourglass form
  double bulk_linear = 0.06;                           ///< linear bulk viscosity coefficient
  double bulk_quadratic = 1.5;                         ///< quadratic bulk viscosity coefficient
  /// One-point elements in SIMD batches (add_internal_forces_batched()) of 8 where the CPU has
  /// AVX-512, of 4 where it has AVX2 (batched_kernel_lanes()); false: one at a time, the scalar
  /// reference. Full integration is always scalar.
  bool batched = true;
};

/// The hex8 elements of one rank, structure of arrays (element e's data at e × stride).
struct SolidElements {
  LocalIndex n_elements = 0;  ///< number of elements
  LocalIndex n_nodes = 0;     ///< local nodes: the nodal arrays the kernel reads hold 3 × n_nodes
  int n_points = 1;           ///< integration points per element (1 or 8)
  std::vector<LocalIndex> nodes;            ///< 8 local node indices per element
  std::vector<LocalIndex> partition_index;  ///< element's index in the partition's block order
  std::vector<GlobalIndex> global_element;  ///< element's global index in the mesh
  std::vector<double> gradients;  ///< per point: ∂N_a/∂X_i at [i × 8 + a] (24 per point)
  /// Full integration only: per point Gauss weight × det J; a one-point element's weight is its
  /// volume, which is not stored twice.
  std::vector<double> weights;
  std::vector<double> volume;  ///< reference volume (m³)
  /// h_α · X_i, [α × 3 + i] (12 per element): the hourglass vectors γ_α = h_α − Σ_i (h_α·X_i)
  /// ∇₀N̄_i are rebuilt from them in the kernel, which costs less than reading 32 numbers.
  std::vector<double> hourglass_projection;
  std::vector<double> lambda;           ///< Lamé λ (Pa)
  std::vector<double> mu;               ///< shear modulus μ (Pa)
  std::vector<double> density;          ///< reference density ρ₀ (kg/m³)
  std::vector<double> wave_speed;       ///< dilatational wave speed √((λ+2μ)/ρ₀) (m/s)
  std::vector<double> hourglass_scale;  ///< C of the hourglass force f = C γ (γᵀ u) or (γᵀ v)
  std::vector<double> stable_step;      ///< critical step in the reference configuration (s)
  std::vector<double> length;           ///< reference characteristic length V / max face area (m)
};

/// What one pass of the kernel sums over its elements.
struct SolidForceTotals {
  double strain_energy = 0;     ///< ∫ W(E) dV (J)
  double hourglass_energy = 0;  ///< energy stored by stiffness hourglass forces (J)
  double hourglass_power = 0;   ///< power dissipated by viscous hourglass forces (W)
  double viscous_power = 0;     ///< power dissipated by bulk viscosity (W)
  double stable_step = 1e300;   ///< smallest current critical step (s), before any safety factor
  LocalIndex critical_element = -1;  ///< which element gave it
};

/// Builds the elements of every hex8 block of \p partition, with their materials from
/// \p materials (every hex8 block must have one). Each element's stable step is L / c_P with
/// L = volume / largest face area: the exact limit of a uniform mesh, whose highest mode is the
/// checkerboard along one axis (the element-by-element eigenvalue bound of Irons would be
/// √((3λ+2μ)/(λ+2μ)) = 1.36 times smaller at ν = 0.3: the Lamé coupling it counts cancels
/// between neighbours). Stiff hourglass control can lower it further: 2/ω of the hourglass
/// stiffness on the lumped masses.
SolidElements build_solid_elements(const MeshPartition& partition, const MaterialTable& materials,
                                   const SolidKernelSettings& settings);

/// Adds every element's internal force (elastic, hourglass, bulk viscous) at displacements \p u
/// and velocities \p v (3 per local node) into \p forces (3 per local node), and returns the
/// sums. \p coordinates are the reference positions (3 per local node).
SolidForceTotals add_internal_forces(const SolidElements& elements,
                                     const SolidKernelSettings& settings, const double* coordinates,
                                     const double* u, const double* v, double* forces);

/// Whether this CPU runs a batched pass of \p lanes elements: 8 (kWideLanes) where it has
/// AVX-512, 4 (kNarrowLanes) where it has AVX2 and FMA.
bool batched_kernel_supports(int lanes);

/// The widest batch this CPU runs (8 or 4), or 0 where it runs none (there the scalar kernel is
/// faster and add_internal_forces() uses it).
int batched_kernel_lanes();

/// Whether this CPU runs the batched kernel at all (batched_kernel_lanes() > 0).
inline bool batched_kernel_available() {
  return batched_kernel_lanes() > 0;
}

/// add_internal_forces() for one-point elements, \p lanes elements at a time in SIMD lanes
/// (solid_kernel_batched.cpp): the same arithmetic as the scalar kernel, so forces, energies and
/// steps equal its own to round-off (fused multiply-adds and the order of the sums differ). The
/// last batch is filled with copies of its last element, whose results are dropped. Only where
/// batched_kernel_supports(\p lanes) (std::invalid_argument otherwise); \p coordinates must be
/// those the elements were built from (the hourglass projections are recomputed from them).
SolidForceTotals add_internal_forces_batched(const SolidElements& elements,
                                             const SolidKernelSettings& settings,
                                             const double* coordinates, const double* u,
                                             const double* v, double* forces, int lanes);

/// Which pass add_internal_forces() runs with \p settings on this CPU, for the run summary:
/// "batched, 8 lanes (AVX-512)", "batched, 4 lanes (AVX2)", "scalar" or "scalar (full
/// integration)".
std::string solid_kernel_name(const SolidKernelSettings& settings);

/// The smallest stable step over every rank's elements and where it is, as "element 12 of block
/// 'rail' at (x, y, z) m" (collective). \p step gives each element's step (e.g. the reference
/// stable_step), \p coordinates the local nodes' positions.
std::pair<double, std::string> smallest_step(const SolidElements& elements,
                                             const MeshPartition& partition,
                                             const std::vector<double>& step,
                                             const double* coordinates);

/// The hourglass vectors γ_α of one-point element \p e, [α × 8 + a].
void hourglass_vectors(const SolidElements& elements, LocalIndex e, double gamma[32]);

/// Cauchy stress at the centre of element \p e (xx, yy, zz, xy, yz, zx, Pa) for displacements
/// \p u: σ = J⁻¹ F S Fᵀ.
void element_cauchy_stress(const SolidElements& elements, LocalIndex e, const double* u,
                           double stress[6]);

}  // namespace railfe
