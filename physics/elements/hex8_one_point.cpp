#include "physics/elements/hex8_one_point.hpp"

#include <algorithm>

#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

double hex8_mean_gradients(const double x[8][3], double gradient[24]) {
  const Hex8GaussTable& table = hex8_gauss_table();
  std::fill(gradient, gradient + 24, 0.0);
  double volume = 0;
  for (int q = 0; q < 8; ++q) {
    double g[3][8];
    const double det = hex8_gradients(x, table.dN[q], g);
    volume += det;
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 8; ++a)
        gradient[i * 8 + a] += det * g[i][a];
  }
  for (int k = 0; k < 24; ++k)
    gradient[k] /= volume;
  return volume;
}

void hex8_hourglass_projections(const double x[8][3], double projection[12]) {
  for (int alpha = 0; alpha < 4; ++alpha)
    for (int i = 0; i < 3; ++i) {
      double sum = 0;
      for (int a = 0; a < 8; ++a)
        sum += kHex8HourglassBase.h[alpha][a] * x[a][i];
      projection[alpha * 3 + i] = sum;
    }
}

double hex8_hourglass_stiffness(const double* gradient, double volume, const LameConstants& lame,
                                double kappa) {
  double gradient_norm = 0;
  for (int k = 0; k < 24; ++k)
    gradient_norm += gradient[k] * gradient[k];
  return kappa * (lame.lambda + 2 * lame.mu) * volume * gradient_norm / 3;
}

void hex8_one_point_stiffness(const double x[8][3], const LameConstants& lame, double kappa,
                              double* stiffness) {
  double gradient[24], projection[12], gamma[32];
  const double volume = hex8_mean_gradients(x, gradient);
  hex8_hourglass_projections(x, projection);
  hex8_hourglass_vectors(projection, gradient, gamma);
  const double scale = hex8_hourglass_stiffness(gradient, volume, lame, kappa);
  // K_aibj = V (λ G_ai G_bj + μ (G_aj G_bi + δ_ij G_a·G_b)) + δ_ij C Σ_α γ_αa γ_αb.
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      double dot = 0, hourglass = 0;
      for (int k = 0; k < 3; ++k)
        dot += gradient[k * 8 + a] * gradient[k * 8 + b];
      for (int alpha = 0; alpha < 4; ++alpha)
        hourglass += gamma[alpha * 8 + a] * gamma[alpha * 8 + b];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double value = volume * (lame.lambda * gradient[i * 8 + a] * gradient[j * 8 + b] +
                                   lame.mu * gradient[j * 8 + a] * gradient[i * 8 + b]);
          if (i == j)
            value += volume * lame.mu * dot + scale * hourglass;
          stiffness[(3 * a + i) * 24 + 3 * b + j] = value;
        }
    }
}

}  // namespace railfe
