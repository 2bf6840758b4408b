#include "physics/elements/hex8.hpp"

#include <cmath>

#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

LameConstants lame_constants(double young, double poisson) {
  return {young * poisson / ((1 + poisson) * (1 - 2 * poisson)), young / (2 * (1 + poisson))};
}

namespace {

// Eight doubles: one value per hex8 node, or per Gauss point. GCC and Clang map it to one AVX-512
// register, or two AVX2 registers, or four SSE registers.
typedef double Lanes __attribute__((vector_size(64), aligned(64)));

inline Lanes load_lanes(const double* values) {
  Lanes lanes;
  __builtin_memcpy(&lanes, values, sizeof lanes);
  return lanes;
}

}  // namespace

void hex8_stiffness(const double x[8][3], const LameConstants& material, double* stiffness) {
  // K_ab,ij = λ H_ij(a,b) + μ H_ji(a,b) + δ_ij μ Σ_k H_kk(a,b), H_ij(a,b) = Σ_q w_q g_i^a g_j^b,
  // with g the physical gradients at Gauss point q. The Jacobians of all eight points are
  // computed at once (lanes = points); then each H row (lanes = b) is accumulated over the points
  // in registers. All nine H blocks are formed so no pass reads a column.
  const Hex8GaussTable& table = hex8_gauss_table();
  Lanes J[3][3];  // J[d][k], lanes = points: ∂x_d/∂ξ_k
  for (int d = 0; d < 3; ++d) {
    for (int k = 0; k < 3; ++k)
      J[d][k] = Lanes{};
  }
  for (int a = 0; a < 8; ++a) {
    for (int k = 0; k < 3; ++k) {
      const Lanes dN = load_lanes(table.dN_by_point[k][a]);
      for (int d = 0; d < 3; ++d)
        J[d][k] += x[a][d] * dN;
    }
  }
  const Lanes c00 = J[1][1] * J[2][2] - J[1][2] * J[2][1];
  const Lanes c01 = J[1][2] * J[2][0] - J[1][0] * J[2][2];
  const Lanes c02 = J[1][0] * J[2][1] - J[1][1] * J[2][0];
  const Lanes det = J[0][0] * c00 + J[0][1] * c01 + J[0][2] * c02;
  const Lanes r = 1.0 / det;
  alignas(64) double inverse[3][3][8];  // inverse[k][i][q] = ∂ξ_k/∂x_i at point q
  alignas(64) double weight[8];
  const Lanes inverse_lanes[3][3] = {{c00 * r, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * r,
                                      (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * r},
                                     {c01 * r, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * r,
                                      (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * r},
                                     {c02 * r, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * r,
                                      (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * r}};
  __builtin_memcpy(inverse, inverse_lanes, sizeof inverse);
  __builtin_memcpy(weight, &det, sizeof weight);

  alignas(64) double gradient[8][3][8];  // gradient[q][i][a] = ∂N_a/∂x_i at point q
  for (int q = 0; q < 8; ++q) {
    const Lanes dN0 = load_lanes(table.dN[q][0]);
    const Lanes dN1 = load_lanes(table.dN[q][1]);
    const Lanes dN2 = load_lanes(table.dN[q][2]);
    for (int i = 0; i < 3; ++i) {
      const Lanes g = dN0 * inverse[0][i][q] + dN1 * inverse[1][i][q] + dN2 * inverse[2][i][q];
      __builtin_memcpy(gradient[q][i], &g, sizeof g);
    }
  }
  Lanes H[3][3][8];  // H[i][j][a], lanes = b
  for (int i = 0; i < 3; ++i) {
    for (int a = 0; a < 8; ++a) {
      Lanes h0{}, h1{}, h2{};
      for (int q = 0; q < 8; ++q) {
        const double wa = weight[q] * gradient[q][i][a];
        h0 += wa * load_lanes(gradient[q][0]);
        h1 += wa * load_lanes(gradient[q][1]);
        h2 += wa * load_lanes(gradient[q][2]);
      }
      H[i][0][a] = h0;
      H[i][1][a] = h1;
      H[i][2][a] = h2;
    }
  }
  const double lambda = material.lambda, mu = material.mu;
  for (int a = 0; a < 8; ++a) {
    const Lanes trace = mu * (H[0][0][a] + H[1][1][a] + H[2][2][a]);
    for (int i = 0; i < 3; ++i) {
      alignas(64) double value[3][8];
      for (int j = 0; j < 3; ++j) {
        Lanes v = lambda * H[i][j][a] + mu * H[j][i][a];
        if (i == j)
          v += trace;
        __builtin_memcpy(value[j], &v, sizeof v);
      }
      double* row = stiffness + (3 * a + i) * 24;
      for (int b = 0; b < 8; ++b) {
        row[3 * b] = value[0][b];
        row[3 * b + 1] = value[1][b];
        row[3 * b + 2] = value[2][b];
      }
    }
  }
}

void hex8_body_force(const double x[8][3], const double b[3], double* forces) {
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  for (int k = 0; k < 24; ++k)
    forces[k] = 0;
  for (int q = 0; q < 8; ++q) {
    const double weight = hex8_gradients(x, table.dN[q], gradient);
    for (int a = 0; a < 8; ++a) {
      for (int d = 0; d < 3; ++d)
        forces[3 * a + d] += table.N[q][a] * weight * b[d];
    }
  }
}

void hex8_mass(const double x[8][3], double density, bool lumped, double* mass) {
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  double nodal[8][8] = {};
  for (int q = 0; q < 8; ++q) {
    const double weight = density * hex8_gradients(x, table.dN[q], gradient);
    for (int a = 0; a < 8; ++a) {
      for (int b = 0; b < 8; ++b)
        nodal[a][b] += weight * table.N[q][a] * table.N[q][b];
    }
  }
  for (int k = 0; k < 24 * 24; ++k)
    mass[k] = 0;
  for (int a = 0; a < 8; ++a) {
    double row_sum = 0;
    for (int b = 0; b < 8; ++b)
      row_sum += nodal[a][b];
    for (int b = 0; b < 8; ++b) {
      const double value = lumped ? (a == b ? row_sum : 0.0) : nodal[a][b];
      for (int d = 0; d < 3; ++d)
        mass[(3 * a + d) * 24 + 3 * b + d] = value;
    }
  }
}

double hex8_volume(const double x[8][3]) {
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  double volume = 0;
  for (int q = 0; q < 8; ++q)
    volume += hex8_gradients(x, table.dN[q], gradient);
  return volume;
}

void hex8_centre_stress(const double x[8][3], const double* u, const LameConstants& material,
                        double stress[6]) {
  hex8_point_stress(x, u, material, hex8_gauss_table().centre, stress);
}

void hex8_point_stress(const double x[8][3], const double* u, const LameConstants& material,
                       const double dN_ref[3][8], double stress[6]) {
  double gradient[3][8];
  hex8_gradients(x, dN_ref, gradient);
  double du[3][3] = {};  // du[i][j] = ∂u_i/∂x_j
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        du[i][j] += u[3 * a + i] * gradient[j][a];
    }
  }
  const double trace = du[0][0] + du[1][1] + du[2][2];
  const double two_mu = 2 * material.mu;
  stress[0] = material.lambda * trace + two_mu * du[0][0];
  stress[1] = material.lambda * trace + two_mu * du[1][1];
  stress[2] = material.lambda * trace + two_mu * du[2][2];
  stress[3] = material.mu * (du[0][1] + du[1][0]);
  stress[4] = material.mu * (du[1][2] + du[2][1]);
  stress[5] = material.mu * (du[0][2] + du[2][0]);
}

namespace {

// Integrates N_k(s,t) · t(s,t) |∂x/∂s × ∂x/∂t| over the face with 2×2 Gauss points, where the
// traction may depend on the outward unit normal.
template <typename TractionOf>
void integrate_face(const double x[8][3], int face, TractionOf traction_of, double forces[12]) {
  static constexpr double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  for (int k = 0; k < 12; ++k)
    forces[k] = 0;
  for (int q = 0; q < 4; ++q) {
    const double s = g * kCorner[q][0], t = g * kCorner[q][1];
    double dxds[3] = {}, dxdt[3] = {}, N[4];
    for (int k = 0; k < 4; ++k) {
      const double* node = x[kHex8FaceNodes[face][k]];
      N[k] = (1 + kCorner[k][0] * s) * (1 + kCorner[k][1] * t) / 4;
      const double dNds = kCorner[k][0] * (1 + kCorner[k][1] * t) / 4;
      const double dNdt = (1 + kCorner[k][0] * s) * kCorner[k][1] / 4;
      for (int d = 0; d < 3; ++d) {
        dxds[d] += dNds * node[d];
        dxdt[d] += dNdt * node[d];
      }
    }
    const double normal[3] = {dxds[1] * dxdt[2] - dxds[2] * dxdt[1],
                              dxds[2] * dxdt[0] - dxds[0] * dxdt[2],
                              dxds[0] * dxdt[1] - dxds[1] * dxdt[0]};
    const double area =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const double unit[3] = {normal[0] / area, normal[1] / area, normal[2] / area};
    double traction[3];
    traction_of(unit, traction);
    for (int k = 0; k < 4; ++k) {
      for (int d = 0; d < 3; ++d)
        forces[3 * k + d] += N[k] * traction[d] * area;
    }
  }
}

}  // namespace

void hex8_face_traction(const double x[8][3], int face, const double traction[3],
                        double forces[12]) {
  integrate_face(
      x, face,
      [&](const double*, double* t) {
        for (int d = 0; d < 3; ++d)
          t[d] = traction[d];
      },
      forces);
}

void hex8_face_pressure(const double x[8][3], int face, double pressure, double forces[12]) {
  integrate_face(
      x, face,
      [&](const double* n, double* t) {
        for (int d = 0; d < 3; ++d)
          t[d] = -pressure * n[d];
      },
      forces);
}

double hex8_face_area(const double x[8][3], int face) {
  double forces[12];
  const double unit_z[3] = {0, 0, 1};
  hex8_face_traction(x, face, unit_z, forces);
  double area = 0;
  for (int k = 0; k < 4; ++k)
    area += forces[3 * k + 2];
  return area;
}

}  // namespace railfe
