#pragma once
/// \file
/// A number that carries its first and second derivatives along one parameter (second-order
/// forward differentiation). The contact locus of a yawed wheel is a closed-form but tangled
/// function of the profile parameter; carrying derivatives through it gives the exact tangent
/// and curvature the contact equations and Hertz need, without hand-derived chain rules.

#include <cmath>

namespace railfe {

/// f, f' and f'' of a function of one parameter.
struct Jet {
  double v = 0;   ///< value
  double d = 0;   ///< first derivative
  double dd = 0;  ///< second derivative

  /// A constant.
  static Jet constant(double value) { return {value, 0, 0}; }
};

/// Arithmetic and elementary functions of jets, by the chain and product rules.
inline Jet operator+(Jet a, Jet b) {
  return {a.v + b.v, a.d + b.d, a.dd + b.dd};
}
inline Jet operator-(Jet a, Jet b) {
  return {a.v - b.v, a.d - b.d, a.dd - b.dd};
}
inline Jet operator-(Jet a) {
  return {-a.v, -a.d, -a.dd};
}
inline Jet operator*(Jet a, Jet b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d, a.dd * b.v + 2 * a.d * b.d + a.v * b.dd};
}
inline Jet operator*(double s, Jet a) {
  return {s * a.v, s * a.d, s * a.dd};
}
inline Jet operator/(Jet a, Jet b) {
  const double q = a.v / b.v;
  const double dq = (a.d - q * b.d) / b.v;
  return {q, dq, (a.dd - 2 * dq * b.d - q * b.dd) / b.v};
}

/// g(a) for a function g with value \p g, slope \p g1 and second derivative \p g2 at a.v.
inline Jet compose(Jet a, double g, double g1, double g2) {
  return {g, g1 * a.d, g2 * a.d * a.d + g1 * a.dd};
}
inline Jet sqrt(Jet a) {
  const double r = std::sqrt(a.v);
  return compose(a, r, 0.5 / r, -0.25 / (r * a.v));
}
inline Jet sin(Jet a) {
  return compose(a, std::sin(a.v), std::cos(a.v), -std::sin(a.v));
}
inline Jet cos(Jet a) {
  return compose(a, std::cos(a.v), -std::sin(a.v), -std::cos(a.v));
}
inline Jet asin(Jet a) {
  const double w = 1 - a.v * a.v;
  return compose(a, std::asin(a.v), 1 / std::sqrt(w), a.v / (w * std::sqrt(w)));
}

}  // namespace railfe
