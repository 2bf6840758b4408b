#include "physics/elements/hex8.hpp"

#include <cmath>

#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8_shape.hpp"

namespace railfe {

LameConstants lame_constants(double young, double poisson) {
  return {young * poisson / ((1 + poisson) * (1 - 2 * poisson)), young / (2 * (1 + poisson))};
}

void hex8_stiffness(const double x[8][3], const LameConstants& material, double* stiffness) {
  const Hex8GaussTable& table = hex8_gauss_table();
  // H[p][a][b] = ∫ ∂N_a/∂x_i ∂N_b/∂x_j dV for the pairs (i, j) below; the other three pairs are
  // transposes. K_ab,ij = λ H_ij(a,b) + μ H_ji(a,b) + δ_ij μ Σ_k H_kk(a,b).
  static constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  alignas(64) double H[6][8][8] = {};
  alignas(64) double gradient[3][8];
  for (int q = 0; q < 8; ++q) {
    const double weight = hex8_gradients(x, table.dN[q], gradient);
    for (int p = 0; p < 6; ++p) {
      const double* gi = gradient[kPairs[p][0]];
      const double* gj = gradient[kPairs[p][1]];
      for (int a = 0; a < 8; ++a) {
        const double wa = weight * gi[a];
        for (int b = 0; b < 8; ++b) H[p][a][b] += wa * gj[b];
      }
    }
  }
  // Index of H for (i, j), and whether it is stored transposed.
  static constexpr int kPairOf[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  const double lambda = material.lambda, mu = material.mu;
  for (int a = 0; a < 8; ++a) {
    for (int b = 0; b < 8; ++b) {
      const double trace = H[0][a][b] + H[1][a][b] + H[2][a][b];
      for (int i = 0; i < 3; ++i) {
        double* row = stiffness + (3 * a + i) * 24 + 3 * b;
        for (int j = 0; j < 3; ++j) {
          const int p = kPairOf[i][j];
          const bool stored = i <= j;  // H_ij(a,b) stored as is for i <= j
          const double h_ij = stored ? H[p][a][b] : H[p][b][a];
          const double h_ji = stored ? H[p][b][a] : H[p][a][b];
          row[j] = lambda * h_ij + mu * h_ji + (i == j ? mu * trace : 0.0);
        }
      }
    }
  }
}

void hex8_body_force(const double x[8][3], const double b[3], double* forces) {
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  for (int k = 0; k < 24; ++k) forces[k] = 0;
  for (int q = 0; q < 8; ++q) {
    const double weight = hex8_gradients(x, table.dN[q], gradient);
    for (int a = 0; a < 8; ++a) {
      for (int d = 0; d < 3; ++d) forces[3 * a + d] += table.N[q][a] * weight * b[d];
    }
  }
}

double hex8_volume(const double x[8][3]) {
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  double volume = 0;
  for (int q = 0; q < 8; ++q) volume += hex8_gradients(x, table.dN[q], gradient);
  return volume;
}

void hex8_centre_stress(const double x[8][3], const double* u, const LameConstants& material,
                        double stress[6]) {
  double gradient[3][8];
  hex8_gradients(x, hex8_gauss_table().centre, gradient);
  double du[3][3] = {};  // du[i][j] = ∂u_i/∂x_j
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) du[i][j] += u[3 * a + i] * gradient[j][a];
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
  for (int k = 0; k < 12; ++k) forces[k] = 0;
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
    const double area = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const double unit[3] = {normal[0] / area, normal[1] / area, normal[2] / area};
    double traction[3];
    traction_of(unit, traction);
    for (int k = 0; k < 4; ++k) {
      for (int d = 0; d < 3; ++d) forces[3 * k + d] += N[k] * traction[d] * area;
    }
  }
}

}  // namespace

void hex8_face_traction(const double x[8][3], int face, const double traction[3], double forces[12]) {
  integrate_face(
      x, face,
      [&](const double*, double* t) {
        for (int d = 0; d < 3; ++d) t[d] = traction[d];
      },
      forces);
}

void hex8_face_pressure(const double x[8][3], int face, double pressure, double forces[12]) {
  integrate_face(
      x, face,
      [&](const double* n, double* t) {
        for (int d = 0; d < 3; ++d) t[d] = -pressure * n[d];
      },
      forces);
}

double hex8_face_area(const double x[8][3], int face) {
  double forces[12];
  const double unit_z[3] = {0, 0, 1};
  hex8_face_traction(x, face, unit_z, forces);
  double area = 0;
  for (int k = 0; k < 4; ++k) area += forces[3 * k + 2];
  return area;
}

}  // namespace railfe
