#pragma once
/// \file
/// FASTSIM, Kalker's simplified theory of rolling contact (Kalker 1982): the surface deflects in
/// proportion to the local traction, with the three flexibilities chosen so that small creepages
/// give the linear theory's forces. Each strip across the ellipse is swept from the leading edge
/// (+x, where material enters) to the trailing edge; where the traction would exceed the bound
/// μ p the point slides. The bound is parabolic (Kalker's choice, which makes the force-creepage
/// curve close to the exact one) or elliptic (Hertz's pressure).

#include <vector>

#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// How the traction bound is distributed.
enum class TractionBound {
  parabolic,  ///< 2N / (π a b) (1 - x²/a² - y²/b²)
  elliptic    ///< Hertz: 3N / (2π a b) √(1 - x²/a² - y²/b²)
};

/// FASTSIM settings.
struct FastsimSettings {
  int cells_x = 20;                                ///< cells along each strip (rolling direction)
  int strips = 20;                                 ///< strips across the ellipse (lateral)
  TractionBound bound = TractionBound::parabolic;  ///< the traction bound's shape
  bool fields = true;  ///< keep the per-cell fields (false: forces only, faster)
};

/// A FASTSIM solution.
struct FastsimResult {
  CreepForces forces;  ///< total tangential forces and spin moment on body 1
  /// Per cell (strip-major: strip j, cell i at index j * cells_x + i), when asked for: centre
  /// x, y (m), tractions px, py (Pa), the bound μ p (Pa), and whether it adheres.
  std::vector<double> x, y, px, py, bound;
  std::vector<bool> adhesion;
  double adhesion_fraction = 0;  ///< share of the contact area in adhesion
};

/// FASTSIM for an ellipse \p a × \p b (a along the rolling direction) under normal force
/// \p load, friction coefficient \p friction, combined shear modulus \p G, coefficients \p c
/// (from KalkerTable) and creepages \p creep.
FastsimResult fastsim(const KalkerCoefficients& c, double G, double a, double b, double load,
                      double friction, const Creepages& creep,
                      const FastsimSettings& settings = {});

}  // namespace railfe
