#include "physics/elements/timoshenko_bending.hpp"

#include <cmath>

namespace railfe {

double shear_parameter(double bending_stiffness, double shear_stiffness, double length) {
  return 12 * bending_stiffness / (shear_stiffness * length * length);  // 0 when G A_s = ∞
}

TimoshenkoShape timoshenko_shape(double xi, double phi, double length) {
  const double L = length, c = 1 / (1 + phi);
  const double x2 = xi * xi, x3 = x2 * xi;
  TimoshenkoShape s;
  s.deflection << c * (2 * x3 - 3 * x2 - phi * xi + 1 + phi),
      c * L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi), -c * (2 * x3 - 3 * x2 - phi * xi),
      c * L * (x3 - (1 - phi / 2) * x2 - phi / 2 * xi);
  s.rotation << 6 * c / L * (x2 - xi), c * (3 * x2 - (4 + phi) * xi + 1 + phi),
      -6 * c / L * (x2 - xi), c * (3 * x2 - (2 - phi) * xi);
  return s;
}

Eigen::Matrix4d timoshenko_bending_stiffness(double bending_stiffness, double phi, double length) {
  const double L = length, L2 = L * L;
  Eigen::Matrix4d k;
  k << 12, 6 * L, -12, 6 * L,                         //
      6 * L, (4 + phi) * L2, -6 * L, (2 - phi) * L2,  //
      -12, -6 * L, 12, -6 * L,                        //
      6 * L, (2 - phi) * L2, -6 * L, (4 + phi) * L2;
  return bending_stiffness / ((1 + phi) * L2 * L) * k;
}

Eigen::Matrix4d timoshenko_bending_mass(double mass_per_length, double rotary_per_length,
                                        double phi, double length) {
  // 4-point Gauss–Legendre on [0, 1], exact to degree 7.
  const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5));
  const double b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
  const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
  const double points[4] = {-b, -a, a, b}, weights[4] = {wb, wa, wa, wb};
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  for (int q = 0; q < 4; ++q) {
    const TimoshenkoShape s = timoshenko_shape((1 + points[q]) / 2, phi, length);
    const double dx = weights[q] * length / 2;
    m += dx * (mass_per_length * s.deflection * s.deflection.transpose() +
               rotary_per_length * s.rotation * s.rotation.transpose());
  }
  return m;
}

}  // namespace railfe
