#include "contact/laws/saturation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railfe {

CreepForces shen_hedrick_elkins(const CreepForces& linear, double load, double friction) {
  if (!(load > 0 && friction >= 0))
    throw std::invalid_argument("saturation needs a positive load and a friction coefficient");
  const double resultant = std::hypot(linear.Fx, linear.Fy);
  const double limit = friction * load;
  if (resultant == 0 || limit == 0)
    return limit == 0 ? CreepForces{} : linear;
  const double beta = resultant / limit;
  const double saturated =
      beta < 3 ? limit * (beta - beta * beta / 3 + beta * beta * beta / 27) : limit;
  const double scale = saturated / resultant;
  return {linear.Fx * scale, linear.Fy * scale, linear.Mz * scale};
}

CreepForces polach(const KalkerCoefficients& c, double G, double a, double b, double load,
                   const Creepages& creep, const PolachParameters& parameters) {
  const PolachParameters& p = parameters;
  if (!(load > 0 && a > 0 && b > 0 && G > 0 && p.friction > 0 && p.rolling_speed > 0 &&
        p.friction_decay >= 0))
    throw std::invalid_argument(
        "Polach's model needs positive load, semi-axes, modulus, friction and rolling speed, and "
        "a non-negative friction decay");
  if (!(p.adhesion_reduction > 0 && p.adhesion_reduction <= 1 && p.slip_reduction > 0 &&
        p.slip_reduction <= p.adhesion_reduction && p.friction_ratio > 0 && p.friction_ratio <= 1))
    throw std::invalid_argument(
        "Polach's reduction factors need 0 < k_S <= k_A <= 1 and the friction ratio 0 < A <= 1");
  const double xi = creep.longitudinal, eta = creep.lateral, phi = creep.spin;
  // Spin counts towards the resultant only where it adds to the lateral creepage.
  const double eta_spin = std::abs(eta + phi * a) > std::abs(eta) ? eta + phi * a : eta;
  const double resultant = std::hypot(xi, eta_spin);
  if (resultant == 0)
    return {};
  const double mu = p.friction * ((1 - p.friction_ratio) *
                                      std::exp(-p.friction_decay * p.rolling_speed * resultant) +
                                  p.friction_ratio);
  const double translation = std::hypot(xi, eta);
  const double c_jj =
      translation > 0 ? std::hypot(c.C11 * xi / translation, c.C22 * eta / translation) : 0.0;
  const double epsilon = M_PI * G * a * b * c_jj * resultant / (4 * mu * load);
  const double kA = p.adhesion_reduction * epsilon;
  const double F =
      2 * mu * load / M_PI * (kA / (1 + kA * kA) + std::atan(p.slip_reduction * epsilon));
  const double shape = 1 + 6.3 * (1 - std::exp(-a / b));
  const double eps_m =
      8 * G * b * std::sqrt(a * b) * c.C23 * std::abs(eta_spin) / (3 * mu * load * shape);
  const double delta = (eps_m * eps_m - 1) / (eps_m * eps_m + 1);
  const double k_m = eps_m * (delta * delta * delta / 3 - delta * delta / 2 + 1.0 / 6) -
                     std::pow(std::max(1 - delta * delta, 0.0), 1.5) / 3;
  const double spin_force = 9.0 / 16 * a * mu * load * k_m * shape * phi / resultant;
  return {-F * xi / resultant, -F * eta / resultant + spin_force, std::nan("")};
}

}  // namespace railfe
