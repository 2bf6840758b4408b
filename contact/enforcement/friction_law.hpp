#pragma once
/// \file
/// Friction coefficients for penalty contact: Coulomb's constant μ, or the velocity-dependent
/// (falling) law μ(v) = μd + (μs − μd) exp(−c |v|) of the squeal model (Yang & Li 2019, after
/// Oden and Martins), with v the slip speed.

#include <cmath>

namespace railfe {

/// The friction law of a contact pair.
struct FrictionLaw {
  /// Which law.
  enum class Kind {
    none,               ///< frictionless
    coulomb,            ///< constant μ = static coefficient
    velocity_dependent  ///< μd + (μs − μd) exp(−c |v|)
  };
  Kind kind = Kind::none;          ///< the law
  double static_coefficient = 0;   ///< μs, or Coulomb's μ
  double dynamic_coefficient = 0;  ///< μd (velocity-dependent law only)
  double decay = 0;                ///< c (s/m, velocity-dependent law only)

  /// The coefficient at slip speed \p slip_speed (m/s, ≥ 0).
  double coefficient(double slip_speed) const {
    switch (kind) {
      case Kind::none:
        return 0;
      case Kind::coulomb:
        return static_coefficient;
      case Kind::velocity_dependent:
        return dynamic_coefficient +
               (static_coefficient - dynamic_coefficient) * std::exp(-decay * slip_speed);
    }
    return 0;
  }
};

}  // namespace railfe
