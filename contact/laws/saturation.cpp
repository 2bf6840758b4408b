#include "contact/laws/saturation.hpp"

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

}  // namespace railfe
