#pragma once
/// \file
/// The normal contact problem on the half-space grid: pressures p ≥ 0 such that the deformed
/// separation h + u(p) equals the approach δ where p > 0 and exceeds it elsewhere, under a given
/// total force. Solved by Polonsky & Keer's constrained conjugate gradients (Wear 231, 1999):
/// an active-set method that moves elements in and out of contact, so any separation h works,
/// elliptic or not (two-point contact, conformal patches).

#include <memory>
#include <vector>

#include "contact/laws/halfspace.hpp"
#include "contact/laws/hertz.hpp"

namespace railfe {

/// A normal solution.
struct NormalSolution {
  std::vector<double> pressure;  ///< per element (Pa)
  double approach = 0;           ///< δ: the rigid approach of the bodies (m)
  double load = 0;               ///< Σ p dA (N)
  double max_pressure = 0;       ///< Pa
  double area = 0;               ///< area in contact (m²)
  int iterations = 0;            ///< conjugate-gradient iterations
  bool converged = false;        ///< the relative pressure change fell below the tolerance
};

/// Pressures under total force \p load (N > 0) for the undeformed separation \p separation (m,
/// one value per element of \p kernels' grid; zero where the bodies first touch). The
/// iterations start from \p start (Pa per element, scaled to the load; its positive elements
/// form the first contact set) when given, else from a uniform pressure on the whole grid.
NormalSolution solve_normal(const HalfSpaceKernels& kernels, const std::vector<double>& separation,
                            double load, double tolerance = 1e-10, int max_iterations = 2000,
                            const std::vector<double>* start = nullptr);

/// Per row of \p grid, x (m) of the leading edge of \p hertz's ellipse centred at the origin,
/// a √(1 − y²/b²) at the row's centre (NaN for rows outside it): TangentialSettings::leading_edge.
std::vector<double> hertz_leading_edge(const HertzContact& hertz, const ContactGrid& grid);

/// A Hertzian patch on the grid the exact solver uses: its kernels and normal solution.
struct HertzPatch {
  std::unique_ptr<HalfSpaceKernels> kernels;  ///< grid and influence coefficients
  NormalSolution normal;                      ///< pressures under the Hertz load
  std::vector<double> leading_edge;           ///< the ellipse's leading edge per row (m)
  /// Per row, TangentialSettings::row_longitudinal_slip (a separation's rolling radii; empty:
  /// the spin's −φ y).
  std::vector<double> row_longitudinal_slip;
};

/// The normal problem of the separation A x² + B y² of \p hertz under its load, on an \p m × \p m
/// grid reaching 10 % (and at least 1.5 elements) beyond the Hertz ellipse, so that the contact
/// never reaches the grid's edge; both bodies of shear modulus \p G and Poisson's ratio \p nu.
/// Starts from Hertz's pressure.
HertzPatch solve_hertz_patch(const HertzContact& hertz, double G, double nu, int m);

/// The same on an \p mx × \p my grid (\p mx along the rolling direction), each side reaching 10 %
/// (and at least 1.5 elements) beyond the ellipse: the grids of Kalker's CONTACT program.
HertzPatch solve_hertz_patch(const HertzContact& hertz, double G, double nu, int mx, int my);

/// The undeformed separation across the rolling direction of a non-Hertzian (profile) contact:
/// points (y, s) with y strictly increasing, read piecewise linearly; only differences of s count
/// (its least value is the first touch).
struct LateralSeparation {
  std::vector<double> y;  ///< across the rolling direction (m)
  std::vector<double> s;  ///< separation (m)
  /// Optional, one per point: the wheel's rolling radius R at y (m). The longitudinal rigid slip
  /// across the patch is then ξ − (R(y) − R(0)) / R(0), ξ that of y = 0, instead of ξ − φ y.
  std::vector<double> rolling_radius;
  /// s at \p at less the least s (linear between points; outside the points, +infinity: the
  /// profiles end there, so the contact must not reach it).
  double at(double at) const;
};

/// How a non-Hertzian patch's grid was found.
struct SeparationPatchInfo {
  int refits = 0;  ///< grids solved before the final one
};

/// The normal problem of the separation A x² + \p lateral(y) (Kalker's CONTACT calls it the
/// undeformed distance; A the rolling direction's relative curvature) under \p load, on an
/// \p mx × \p my grid fitted to the contact: the contact lies where the separation is below the
/// approach δ, so the grid covers that region (with 5 % beyond) and is refitted until δ no longer
/// grows past it. Per row the leading edge is placed where the square of the pressure,
/// extrapolated from the row's two leading elements, falls to zero (within the first element
/// beyond them). With rolling radii, sets the patch's row_longitudinal_slip from them. Throws
/// std::invalid_argument where the contact reaches the separation's ends, or rolling radii do not
/// reach y = 0.
HertzPatch solve_separation_patch(const LateralSeparation& lateral, double A, double load, double G,
                                  double nu, int mx, int my, SeparationPatchInfo* info = nullptr);

}  // namespace railfe
