#include "contact/laws/inverse_creepage.hpp"

#include <cmath>
#include <numeric>

namespace railfe {

InverseCreepageResult solve_for_creepages(const HalfSpaceKernels& kernels,
                                          const std::vector<double>& pressure, double Fx, double Fy,
                                          double spin, const FrictionLaw& friction,
                                          double tolerance, const TangentialSettings& settings) {
  InverseCreepageResult result;
  const ContactGrid& grid = kernels.grid();
  const double load = std::accumulate(pressure.begin(), pressure.end(), 0.0) * grid.dx * grid.dy;
  const double bound = friction.static_coefficient * load;
  result.creepages.spin = spin;
  if (!(load > 0)) {
    result.failure = "no normal load";
    return result;
  }
  if (std::hypot(Fx, Fy) >= bound) {
    result.failure = "the force exceeds the traction bound mu N: full sliding, no finite creepage";
    return result;
  }
  auto forces_at = [&](double xi, double eta, TangentialSolution* keep) {
    TangentialSolution s = solve_tangential(kernels, pressure, {xi, eta, spin}, friction, settings);
    const std::array<double, 2> f = {s.forces.Fx, s.forces.Fy};
    const bool ok = s.converged;
    if (keep)
      *keep = std::move(s);
    return std::make_pair(f, ok);
  };
  // A creepage scale: the one Kalker's linear theory would need for μs N on this patch is
  // unknown here, so take it from the first solve's slope.
  double xi = 0, eta = 0;
  TangentialSolution current;
  auto [f, ok] = forces_at(xi, eta, &current);
  auto miss = [&](const std::array<double, 2>& g) { return std::hypot(g[0] - Fx, g[1] - Fy); };
  double h = 1e-6;
  for (int iteration = 0; iteration < 60; ++iteration) {
    result.iterations = iteration;
    if (!ok) {
      result.failure = "the tangential solve did not settle";
      return result;
    }
    if (miss(f) <= tolerance * bound) {
      result.converged = true;
      result.creepages = {xi, eta, spin};
      result.solution = std::move(current);
      return result;
    }
    // Jacobian by forward differences, steps small against the creepages reached so far.
    h = std::max(1e-7, 1e-4 * std::hypot(xi, eta));
    const auto [fx, okx] = forces_at(xi + h, eta, nullptr);
    const auto [fy, oky] = forces_at(xi, eta + h, nullptr);
    if (!okx || !oky) {
      result.failure = "the tangential solve did not settle";
      return result;
    }
    const double j11 = (fx[0] - f[0]) / h, j21 = (fx[1] - f[1]) / h;
    const double j12 = (fy[0] - f[0]) / h, j22 = (fy[1] - f[1]) / h;
    const double det = j11 * j22 - j12 * j21;
    if (!(std::abs(det) > 0)) {
      result.failure = "the forces do not change with the creepages (saturated)";
      return result;
    }
    const double rx = Fx - f[0], ry = Fy - f[1];
    const double dxi = (j22 * rx - j12 * ry) / det, deta = (-j21 * rx + j11 * ry) / det;
    // Backtracking: halve the step until the miss shrinks (the forces saturate, so a full
    // Newton step from the linear part overshoots near the bound).
    double step = 1;
    bool improved = false;
    for (int halving = 0; halving < 30; ++halving, step /= 2) {
      TangentialSolution trial;
      const auto [g, good] = forces_at(xi + step * dxi, eta + step * deta, &trial);
      if (good && miss(g) < miss(f)) {
        xi += step * dxi;
        eta += step * deta;
        f = g;
        current = std::move(trial);
        improved = true;
        break;
      }
    }
    if (!improved) {
      result.failure = "no step towards the forces reduces the miss";
      return result;
    }
  }
  result.failure = "no convergence in 60 Newton iterations";
  return result;
}

}  // namespace railfe
