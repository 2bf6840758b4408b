#include "physics/common/structure_deviation.hpp"

#include <cmath>

namespace railfe {

StructureDeviation::StructureDeviation(const StructureDeviationSettings& settings)
    : beta_(std::pow(settings.pad_stiffness / (4 * settings.rail_modulus * settings.rail_inertia),
                     0.25)) {
  const double s0 = settings.start, L = settings.span, d = settings.amplitude;
  switch (settings.shape) {
    case DeviationShape::none:
      break;
    case DeviationShape::bending:  // up over the first span, back over the second
      kinks_ = {{s0, d / L, 0}, {s0 + L, -2 * d / L, 0}, {s0 + 2 * L, d / L, 0}};
      break;
    case DeviationShape::translation:  // up over the first span, level over the second, back
      kinks_ = {{s0, d / L, 0}, {s0 + L, -d / L, 0}, {s0 + 2 * L, 0, -d}};
      break;
  }
}

double StructureDeviation::structure(double s) const {
  double w = 0;
  for (const Kink& k : kinks_)
    if (s > k.at)
      w += k.slope_jump * (s - k.at) + k.offset_jump;
  return w;
}

double StructureDeviation::rail(double s) const {
  double w = 0;
  for (const Kink& k : kinks_) {
    const double x = s - k.at, bx = beta_ * std::abs(x);
    const double decay = std::exp(-bx), c = std::cos(bx), sn = std::sin(bx);
    // The ramp beyond the kink, rounded: ramp + Δs (cos − sin) e^(−β|x|) / (4β).
    w += k.slope_jump * (std::max(x, 0.0) + decay * (c - sn) / (4 * beta_));
    // The step, rounded: Δ F(x), F the integral of G.
    w += k.offset_jump * (x > 0 ? 1 - 0.5 * decay * c : 0.5 * decay * c);
  }
  return w;
}

}  // namespace railfe
