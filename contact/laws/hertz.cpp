#include "contact/laws/hertz.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace railfe {

namespace {

// K, E and (K − E) / e² of an ellipse of axis ratio g = short / long (e² = 1 − g²), which stays
// finite as the ellipse becomes a circle (series there, where K − E loses its digits).
struct Elliptic {
  double K, E, K_minus_E_over_e2;
};

Elliptic elliptic(double g) {
  const CompleteEllipticIntegrals f = complete_elliptic_integrals(g);
  const double e2 = 1 - g * g;
  Elliptic r{f.K, f.E, 0};
  r.K_minus_E_over_e2 =
      e2 < 1e-4 ? M_PI / 4 * (1 + 3 * e2 / 8 + 15 * e2 * e2 / 64) : (r.K - r.E) / e2;
  return r;
}

// Ratio of the larger to the smaller relative curvature that an ellipse of axis ratio g needs:
// (E / g^2 - K) / (K - E) = E / (g^2 (K - E) / e^2) - 1, which grows from 1 (circle) as g falls.
double curvature_ratio(double g) {
  const Elliptic f = elliptic(g);
  return f.E / (g * g * f.K_minus_E_over_e2) - 1;
}

// Axis ratio g (short / long) for a curvature ratio r >= 1: the root in x = log g of
// curvature_ratio(e^x) = r, which falls monotonically in x. Bracketed around the classical
// estimate g ≈ r^(-2/3), then false position with the Illinois modification (superlinear, about
// ten evaluations instead of bisection's fifty) down to the same 1e-15 in x.
double bracketed_axis_ratio(double r) {
  if (r <= 1)
    return 1;
  auto f = [r](double x) { return curvature_ratio(std::exp(x)) - r; };
  const double floor = std::log(1e-12);
  const double guess = std::max(-2.0 / 3.0 * std::log(r), floor);
  double lo = std::max(guess - 0.25, floor), hi = std::min(guess + 0.25, 0.0);
  double f_lo = f(lo), f_hi = hi < 0 ? f(hi) : 1 - r;
  while (f_lo < 0 && lo > floor) {  // widen until f(lo) > 0 > f(hi)
    hi = lo, f_hi = f_lo;
    lo = std::max(lo - 1, floor);
    f_lo = f(lo);
  }
  while (f_hi > 0 && hi < 0) {
    lo = hi, f_lo = f_hi;
    hi = std::min(hi + 1, 0.0);
    f_hi = hi < 0 ? f(hi) : 1 - r;
  }
  int side = 0;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi))
      x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx > 0) {
      lo = x, f_lo = fx;
      if (side == -1)
        f_hi *= 0.5;
      side = -1;
    } else {
      hi = x, f_hi = fx;
      if (side == 1)
        f_lo *= 0.5;
      side = 1;
    }
    if (fx == 0)
      return std::exp(x);
  }
  return std::exp(0.5 * (lo + hi));
}

// log g against log r at steps of 0.01 up to r = 1e8, from bracketed_axis_ratio(): a start
// within about 1e-5 of the root, from which the secant method needs three or four evaluations.
constexpr double kTableStep = 0.01;
constexpr int kTableSize = 1843;  // log(1e8) / 0.01 + 1

const std::vector<double>& axis_ratio_table() {
  static const std::vector<double> table = [] {
    std::vector<double> t(kTableSize);
    for (int i = 0; i < kTableSize; ++i)
      t[i] = std::log(bracketed_axis_ratio(std::exp(i * kTableStep)));
    return t;
  }();
  return table;
}

// The root of bracketed_axis_ratio() by the secant method from the table's start (Hertz is
// evaluated at every contact point of every Newton iteration); the bracketed search where the
// table ends or the secant does not settle.
double axis_ratio(double r) {
  if (r <= 1)
    return 1;
  const double t = std::log(r) / kTableStep;
  if (!(t < kTableSize - 1))
    return bracketed_axis_ratio(r);
  const auto& table = axis_ratio_table();
  const int i = static_cast<int>(t);
  const double w = t - i;
  auto f = [r](double x) { return curvature_ratio(std::exp(x)) - r; };
  double x0 = (1 - w) * table[i] + w * table[i + 1], x1 = x0 - 1e-7;
  double f0 = f(x0), f1 = f(x1);
  for (int k = 0; k < 8; ++k) {
    if (f1 == 0)
      return std::exp(x1);
    if (f1 == f0)
      break;
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    if (!(x2 < 0) || !std::isfinite(x2))
      break;
    if (std::abs(x2 - x1) <= 1e-15)
      return std::exp(x2);
    x0 = x1, f0 = f1;
    x1 = x2, f1 = f(x2);
  }
  return bracketed_axis_ratio(r);
}

// Completes a contact whose A, B, load and semi-axes are set.
HertzContact finish(HertzContact c, double modulus, const Elliptic& f) {
  c.pressure = 3 * c.load / (2 * M_PI * c.a * c.b);
  c.approach = c.pressure * std::min(c.a, c.b) * f.K / modulus;
  c.stiffness = c.load / std::pow(c.approach, 1.5);
  return c;
}

}  // namespace

CompleteEllipticIntegrals complete_elliptic_integrals(double g) {
  // Gauss's arithmetic–geometric mean: K = π / (2 M(1, g)) and E = K (1 − Σ 2^(n−1) c_n²) with
  // c_0² = e² and c_(n+1) = (a_n − b_n) / 2; quadratic convergence, five or six rounds to full
  // precision for the ellipses of wheel–rail contact (ten at g = 1e-12). Five times faster than
  // std::comp_ellint_1/2, which Newton's contact evaluations call thousands of times a second.
  double a = 1, b = g, weight = 0.5, sum = 0.5 * (1 - g * g);
  for (int i = 0; i < 40; ++i) {
    const double c = 0.5 * (a - b);
    if (std::abs(c) <= 1e-17 * a)
      break;
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
    weight *= 2;
    sum += weight * c * c;
  }
  const double K = M_PI / (2 * a);
  return {K, K * (1 - sum)};
}

double contact_modulus(const ElasticBody& first, const ElasticBody& second) {
  return 1 / ((1 - first.poisson * first.poisson) / first.young +
              (1 - second.poisson * second.poisson) / second.young);
}

HertzContact hertz_contact(double A, double B, double modulus, double load) {
  if (!(A > 0 && B > 0 && modulus > 0 && load > 0))
    throw std::invalid_argument("Hertz needs positive curvatures A and B, modulus and load");
  HertzContact c;
  c.A = A;
  c.B = B;
  c.load = load;
  // The long semi-axis lies along the smaller curvature (Johnson 4.39).
  const double small = std::min(A, B);
  const double g = axis_ratio(std::max(A, B) / small);
  const Elliptic f = elliptic(g);
  const double longer = std::cbrt(3 * load * f.K_minus_E_over_e2 / (2 * M_PI * modulus * small));
  c.a = A <= B ? longer : g * longer;
  c.b = A <= B ? g * longer : longer;
  return finish(c, modulus, f);
}

HertzContact hertz_from_approach(double A, double B, double modulus, double approach) {
  if (!(approach > 0))
    throw std::invalid_argument("Hertz needs a positive approach");
  // Stiffness does not depend on the load: find it at a unit load. The ellipse keeps its shape,
  // its semi-axes growing as N^(1/3), so the unit contact scales to the load.
  const HertzContact unit = hertz_contact(A, B, modulus, 1.0);
  const double load = unit.stiffness * std::pow(approach, 1.5), scale = std::cbrt(load);
  HertzContact c = unit;
  c.load = load;
  c.a = unit.a * scale;
  c.b = unit.b * scale;
  c.pressure = 3 * load / (2 * M_PI * c.a * c.b);
  c.approach = approach;
  return c;
}

HertzContact hertz_from_semi_axes(double a, double b, double modulus, double load) {
  if (!(a > 0 && b > 0 && modulus > 0 && load > 0))
    throw std::invalid_argument("Hertz needs positive semi-axes, modulus and load");
  const double longer = std::max(a, b);
  const double g = std::min(a, b) / longer;
  const Elliptic f = elliptic(g);
  const double small =
      3 * load * f.K_minus_E_over_e2 / (2 * M_PI * modulus * longer * longer * longer);
  const double large = small * curvature_ratio(g);
  HertzContact c;
  c.A = a >= b ? small : large;
  c.B = a >= b ? large : small;
  c.load = load;
  c.a = a;
  c.b = b;
  return finish(c, modulus, f);
}

}  // namespace railfe
