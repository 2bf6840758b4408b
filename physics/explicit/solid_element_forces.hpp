#pragma once
/// \file
/// The arithmetic of the explicit hex8 kernel, written once for one element (T = double, the
/// scalar kernel) and for W elements at once (T = Lanes<W>, the batched kernel): the forces of
/// one integration point (St. Venant–Kirchhoff, bulk viscosity), the Flanagan–Belytschko
/// hourglass forces, and the current stable step. Internal to the explicit module.

#include "framework/mesh/hex8_topology.hpp"
#include "physics/explicit/solid_kernel.hpp"
#include "physics/explicit/solid_lanes.hpp"

namespace railfe {

/// Largest face area of an element with corners \p x (Exodus face order).
template <class T>
RAILFE_LANE_INLINE T largest_face_area(const T x[8][3]) {
  T largest{};
  for (const auto& face : kHex8FaceNodes) {
    const T* p0 = x[face[0]];
    const T* p1 = x[face[1]];
    const T* p2 = x[face[2]];
    const T* p3 = x[face[3]];
    const T d1[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const T d2[3] = {p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
    const T c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                    d1[0] * d2[1] - d1[1] * d2[0]};
    largest = maximum(largest, c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }
  return 0.5 * root(largest);
}

/// Material and size of the elements a kernel pass works on (one element or one per lane).
template <class T>
struct SolidElementConstants {
  T lambda;      ///< Lamé λ (Pa)
  T mu;          ///< shear modulus μ (Pa)
  T density;     ///< reference density (kg/m³)
  T wave_speed;  ///< dilatational wave speed (m/s)
  T length;      ///< reference characteristic length (m), the bulk viscosity's length
};

/// Adds the forces of one integration point with gradients \p g (g[i*8+a]) and weight \p w
/// (reference volume) into \p fe and returns its strain energy; accumulates bulk-viscous power,
/// and returns the Jacobian and the rate of volume change tr(Ḟ F⁻¹) through \p jacobian, \p div.
template <class T>
RAILFE_LANE_INLINE T add_point_forces(const T* g, T w, const T ue[8][3], const T ve[8][3],
                                      const SolidElementConstants<T>& k,
                                      const SolidKernelSettings& s, T fe[8][3], T& viscous_power,
                                      T& jacobian, T& div) {
  T H[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T sum = ue[0][i] * g[j * 8];
      for (int a = 1; a < 8; ++a)
        sum += ue[a][i] * g[j * 8 + a];
      H[i][j] = sum;
    }
  T E[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      E[i][j] =
          0.5 * (H[i][j] + H[j][i] + H[0][i] * H[0][j] + H[1][i] * H[1][j] + H[2][i] * H[2][j]);
  const T trace = E[0][0] + E[1][1] + E[2][2];
  T S[3][3];
  T contraction{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      S[i][j] = 2.0 * k.mu * E[i][j];
      contraction += E[i][j] * E[i][j];
    }
  T F[3][3];
  for (int i = 0; i < 3; ++i) {
    S[i][i] += k.lambda * trace;
    for (int j = 0; j < 3; ++j)
      F[i][j] = H[i][j];
    F[i][i] += 1.0;
  }
  T P[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      P[i][j] = F[i][0] * S[0][j] + F[i][1] * S[1][j] + F[i][2] * S[2][j];

  // Cofactor J F⁻ᵀ: gives J, the rate of volume change and the bulk-viscous PK1 stress −q J F⁻ᵀ.
  const T C[3][3] = {{F[1][1] * F[2][2] - F[1][2] * F[2][1], F[1][2] * F[2][0] - F[1][0] * F[2][2],
                      F[1][0] * F[2][1] - F[1][1] * F[2][0]},
                     {F[0][2] * F[2][1] - F[0][1] * F[2][2], F[0][0] * F[2][2] - F[0][2] * F[2][0],
                      F[0][1] * F[2][0] - F[0][0] * F[2][1]},
                     {F[0][1] * F[1][2] - F[0][2] * F[1][1], F[0][2] * F[1][0] - F[0][0] * F[1][2],
                      F[0][0] * F[1][1] - F[0][1] * F[1][0]}};
  jacobian = F[0][0] * C[0][0] + F[0][1] * C[0][1] + F[0][2] * C[0][2];
  div = T{};
  if (s.bulk_linear > 0 || s.bulk_quadratic > 0) {
    T rate{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T Fdot = ve[0][i] * g[j * 8];
        for (int a = 1; a < 8; ++a)
          Fdot += ve[a][i] * g[j * 8 + a];
        rate += Fdot * C[i][j];
      }
    div = rate / jacobian;
    const auto compressing = div < 0.0;
    if (any(compressing)) {
      // Zero where the volume grows, so such lanes keep their stress and power exactly.
      const T q = select(compressing,
                         k.density / jacobian * k.length *
                             (s.bulk_quadratic * s.bulk_quadratic * k.length * div * div -
                              s.bulk_linear * k.wave_speed * div),
                         T{});
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          P[i][j] -= q * C[i][j];
      viscous_power += q * (-div) * jacobian * w;
    }
  }
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      fe[a][i] += w * (P[i][0] * g[a] + P[i][1] * g[8 + a] + P[i][2] * g[16 + a]);
  return w * (0.5 * k.lambda * trace * trace + k.mu * contraction);
}

/// Adds the hourglass forces C γ_α (γ_αᵀ field) of a one-point element with hourglass vectors
/// \p gamma ([α × 8 + a]) and scale \p scale into \p fe; \p field is the displacement (stiffness
/// form: adds the stored energy to \p energy) or the velocity (viscous form: adds the dissipated
/// power to \p power).
template <class T>
RAILFE_LANE_INLINE void add_hourglass_forces(const T gamma[32], T scale, const T field[8][3],
                                             bool stiffness_form, T fe[8][3], T& energy, T& power) {
  for (int alpha = 0; alpha < 4; ++alpha) {
    const T* g = gamma + 8 * alpha;
    T q[3] = {g[0] * field[0][0], g[0] * field[0][1], g[0] * field[0][2]};
    for (int a = 1; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        q[i] += g[a] * field[a][i];
    const T qq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    if (stiffness_form)
      energy += 0.5 * scale * qq;
    else
      power += scale * qq;
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        fe[a][i] += scale * g[a] * q[i];
  }
}

/// The current stable step of an element whose reference step \p reference_step belongs to the
/// reference length \p reference_length, at current characteristic length \p length and
/// smallest rate of volume change \p compression (≤ 0), bulk viscosity included.
template <class T>
RAILFE_LANE_INLINE T current_stable_step(T reference_step, T reference_length, T length,
                                         T compression, T wave_speed,
                                         const SolidKernelSettings& s) {
  T step = reference_step * length / reference_length;
  if (s.bulk_linear > 0 || s.bulk_quadratic > 0) {
    // The linear term always counts, so the step does not jump when round-off flips the sign
    // of a vanishing volume rate; the quadratic one grows continuously from zero.
    const T xi =
        s.bulk_linear + s.bulk_quadratic * s.bulk_quadratic * length * (-compression) / wave_speed;
    step /= xi + root(1.0 + xi * xi);
  }
  return step;
}

}  // namespace railfe
