#pragma once
/// \file
/// Hertz's elliptic contact of two elastic bodies: from the relative curvatures and the elastic
/// constants, the contact ellipse, maximum pressure, approach and the generalized stiffness
/// K_h (N = K_h δ^{3/2}); and the inverse problems, given the approach or given the semi-axes.
/// Complete elliptic integrals are evaluated exactly (by the arithmetic–geometric mean, to
/// round-off of std::comp_ellint_1/2), not by curve fits. Axes: x is the rolling direction, y
/// lateral. Johnson, Contact Mechanics (1985), §4.2.

namespace railfe {

/// Elastic constants of one body.
struct ElasticBody {
  double young = 210e9;   ///< Young's modulus E (Pa)
  double poisson = 0.28;  ///< Poisson's ratio ν
};

/// The contact modulus E* of two bodies: 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2 (Pa).
double contact_modulus(const ElasticBody& first, const ElasticBody& second);

/// Complete elliptic integrals of the first and second kind.
struct CompleteEllipticIntegrals {
  double K = 0;  ///< K(e)
  double E = 0;  ///< E(e)
};

/// K(e) and E(e) of an ellipse of axis ratio \p g = short / long in (0, 1] (eccentricity
/// e = √(1 − g²)), by the arithmetic–geometric mean.
CompleteEllipticIntegrals complete_elliptic_integrals(double g);

/// A Hertzian contact.
struct HertzContact {
  double A = 0;          ///< relative curvature along x: half the sum of both bodies' (1/m)
  double B = 0;          ///< relative curvature along y (1/m)
  double load = 0;       ///< normal force N (N)
  double a = 0;          ///< semi-axis along x (m)
  double b = 0;          ///< semi-axis along y (m)
  double pressure = 0;   ///< maximum pressure p0 = 3N / (2π a b) (Pa)
  double approach = 0;   ///< approach δ of distant points (m)
  double stiffness = 0;  ///< K_h = N / δ^{3/2} (N/m^{3/2})
};

/// The contact under load \p load (N > 0) between bodies with relative curvatures \p A, \p B
/// (both > 0) and contact modulus \p modulus. Throws std::invalid_argument otherwise.
HertzContact hertz_contact(double A, double B, double modulus, double load);

/// The contact whose approach is \p approach (m > 0): N = K_h δ^{3/2}.
HertzContact hertz_from_approach(double A, double B, double modulus, double approach);

/// The contact with semi-axes \p a (along x) and \p b under \p load: the curvatures A and B that
/// give that ellipse, then the rest.
HertzContact hertz_from_semi_axes(double a, double b, double modulus, double load);

}  // namespace railfe
