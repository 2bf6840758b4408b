#pragma once
/// \file
/// The normal contact problem on the half-space grid: pressures p ≥ 0 such that the deformed
/// separation h + u(p) equals the approach δ where p > 0 and exceeds it elsewhere, under a given
/// total force. Solved by Polonsky & Keer's constrained conjugate gradients (Wear 231, 1999):
/// an active-set method that moves elements in and out of contact, so any separation h works,
/// elliptic or not (two-point contact, conformal patches).

#include <vector>

#include "contact/laws/halfspace.hpp"

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
/// one value per element of \p kernels' grid; zero where the bodies first touch).
NormalSolution solve_normal(const HalfSpaceKernels& kernels, const std::vector<double>& separation,
                            double load, double tolerance = 1e-12, int max_iterations = 2000);

}  // namespace railfe
