#include "contact/laws/tangential_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

double FrictionLaw::at(double speed) const {
  if (decay == 0 || dynamic_coefficient == static_coefficient)  // Coulomb: no exp per element
    return static_coefficient;
  return dynamic_coefficient +
         (static_coefficient - dynamic_coefficient) * std::exp(-decay * std::abs(speed));
}

TangentialSolution solve_tangential(const HalfSpaceKernels& kernels,
                                    const std::vector<double>& pressure, const Creepages& creep,
                                    const FrictionLaw& friction,
                                    const TangentialSettings& settings) {
  const ContactGrid& g = kernels.grid();
  const int mx = g.mx;
  const std::size_t n = static_cast<std::size_t>(g.size());
  TangentialSolution t;
  t.qx.assign(n, 0.0);
  t.qy.assign(n, 0.0);
  t.sx.assign(n, 0.0);
  t.sy.assign(n, 0.0);
  t.adhesion.assign(n, false);
  // Displacements are kept on the grid plus one column beyond its leading edge (row stride
  // mx + 1), so that the second-order difference of an element next to the edge still reads two
  // neighbours ahead: the kernels reach that column from every element but the first.
  const int stride = mx + 1;
  const auto at = [stride, mx](int e) { return e / mx * stride + e % mx; };
  // Elements in contact, and the runs of points (per row) whose displacement they read:
  // themselves and their neighbours towards the leading edge.
  std::vector<int> contact;
  std::vector<char> is_relevant(static_cast<std::size_t>(stride) * g.my, 0);
  for (std::size_t e = 0; e < n; ++e)
    if (pressure[e] > 0) {
      const int i = static_cast<int>(e % mx), j = static_cast<int>(e / mx);
      if (i == 0 || i + 1 >= mx || j == 0 || j + 1 >= g.my)
        throw std::invalid_argument(
            "the contact reaches the edge of the grid: the grid must enclose it with at least "
            "one element to spare on every side");
      contact.push_back(static_cast<int>(e));
      const int d = at(static_cast<int>(e));
      is_relevant[d] = is_relevant[d + 1] = is_relevant[d + 2] = 1;
    }
  struct Run {
    int j, begin, end;  // row, first and one-past-last element
  };
  std::vector<Run> runs;
  for (int j = 0; j < g.my; ++j)
    for (int i = 0; i <= mx; ++i)
      if (is_relevant[static_cast<std::size_t>(j) * stride + i]) {
        if (runs.empty() || runs.back().j != j || runs.back().end != i)
          runs.push_back({j, i, i + 1});
        else
          ++runs.back().end;
      }
  // Each element's step divides its residual by its self-influence, more than the slip's true
  // response to its traction (the self-influence less that on the neighbours ahead, as the
  // difference weighs them): an under-relaxation that keeps the sweeps stable, since the
  // neighbours ahead have already taken their step. Dividing by the true response diverges, as
  // over-relaxation does. The second-order difference's true response is smaller than the first
  // order's, so its divisor is scaled down in the same ratio: the first order's proven damping,
  // and a fifth fewer sweeps than the plain self-influence (1.5 times that ratio still settles,
  // twice it barely, three times diverges).
  const bool second_order = settings.transport != TransportScheme::first_order;
  if (!settings.leading_edge.empty() &&
      settings.leading_edge.size() != static_cast<std::size_t>(g.my))
    throw std::invalid_argument("the tangential solve needs one leading edge per row of the grid");
  if (!settings.row_longitudinal_slip.empty() &&
      settings.row_longitudinal_slip.size() != static_cast<std::size_t>(g.my))
    throw std::invalid_argument("the tangential solve needs one rigid slip per row of the grid");
  // ∂u/∂x at the centre ≈ (c1 (u_e+1 - u_e) + c2 (u_e+2 - u_e)) / dx per element in contact:
  // BDF2 (2, -1/2), first order (1, 0), and for the element that leads its row the fit of
  // u = u_e + v (x - x_e) + c (x - x_L)^{3/2}, x > x_L, to its two neighbours ahead: u is smooth
  // inside the contact, but outside it ∂u/∂x has the square-root singularity of the edge x_L, so
  // the smooth BDF2 misreads the slip there (the error falls only as dx^0.7 where the leading
  // edge adheres under a large rigid slip, as in small spin). Each element's divisor is scaled
  // by its own stencil.
  struct Local {
    double c1, c2;  // the stencil
    double xx, yy;  // the divisors
  };
  double self_xx, self_xy, self_yy, next_xx, next_xy, next_yy, far_xx, far_xy, far_yy;
  kernels.tangential_influence(0, 0, self_xx, self_xy, self_yy);
  kernels.tangential_influence(1, 0, next_xx, next_xy, next_yy);
  kernels.tangential_influence(2, 0, far_xx, far_xy, far_yy);
  const auto local = [&](double c1, double c2) {
    const double w1 = c1 / (c1 + c2), w2 = c2 / (c1 + c2);
    return Local{c1, c2, self_xx * (self_xx - w1 * next_xx - w2 * far_xx) / (self_xx - next_xx),
                 self_yy * (self_yy - w1 * next_yy - w2 * far_yy) / (self_yy - next_yy)};
  };
  std::vector<Local> locals(n, second_order ? local(2, -0.5) : local(1, 0));
  if (settings.transport == TransportScheme::second_order)
    for (int e : contact) {
      const int i = e % mx, j = e / mx;
      if (pressure[static_cast<std::size_t>(e) + 1] > 0)
        continue;
      const double edge = settings.leading_edge.empty() ? std::nan("") : settings.leading_edge[j];
      const double t = std::isnan(edge) ? 0.5 : std::clamp((edge - g.x(i)) / g.dx, 0.0, 1.0);
      const double near = std::pow(1 - t, 1.5), far = std::pow(2 - t, 1.5);
      locals[e] = local(far / (far - 2 * near), -near / (far - 2 * near));
    }
  double p_max = 0;
  for (int e : contact)
    p_max = std::max(p_max, pressure[e]);
  const double scale = friction.static_coefficient * p_max;
  // The steady state is the fixed point of rolling one element length: each material point's
  // displacement is the one it had an element ahead, less the rigid slip, unless it slides.
  // Sweeping each strip from the leading edge, every element takes the traction that best meets
  // that target with the others held (a projected Gauss–Seidel step on the symmetric influence
  // matrix, so |q| <= μp and slip opposes traction), reading the target from the displacement
  // its neighbour ahead has just received.
  // The longitudinal rigid slip of each row: the spin's −φ y, or the rows' given slip.
  std::vector<double> longitudinal_slip(static_cast<std::size_t>(g.my));
  for (int j = 0; j < g.my; ++j)
    longitudinal_slip[static_cast<std::size_t>(j)] =
        settings.row_longitudinal_slip.empty()
            ? creep.longitudinal - creep.spin * g.y(j)
            : creep.longitudinal + settings.row_longitudinal_slip[static_cast<std::size_t>(j)];
  std::vector<double> ux(is_relevant.size(), 0.0), uy(is_relevant.size(), 0.0);
  // Adds the displacements of a traction change on element (i, j) to the relevant points.
  const auto spread_change = [&](int i, int j, double dqx, double dqy) {
    for (const Run& run : runs) {
      const double *xx, *xy, *yy;
      kernels.tangential_rows(run.begin - i, run.j - j, xx, xy, yy);
      double* tx = &ux[static_cast<std::size_t>(run.j) * stride + run.begin];
      double* ty = &uy[static_cast<std::size_t>(run.j) * stride + run.begin];
      for (int k = 0; k < run.end - run.begin; ++k) {
        tx[k] += xx[k] * dqx + xy[k] * dqy;
        ty[k] += xy[k] * dqx + yy[k] * dqy;
      }
    }
  };
  if (settings.start_in_full_slip)
    for (int e : contact) {
      const double wx = longitudinal_slip[static_cast<std::size_t>(e / mx)];
      const double wy = creep.lateral + creep.spin * g.x(e % mx);
      const double w = std::hypot(wx, wy);
      if (w > 0) {
        t.qx[e] = -friction.static_coefficient * pressure[e] * wx / w;
        t.qy[e] = -friction.static_coefficient * pressure[e] * wy / w;
        spread_change(e % mx, e / mx, t.qx[e], t.qy[e]);
      }
    }
  const bool speed_dependent = friction.at(1e300) != friction.static_coefficient;
  // Falling friction takes μ at a slip speed that moves half way to each sweep's slip: with the
  // full step the sweeps can wander instead of settling (20 x 20 Hertz patch, ξ 2e-3, μs 0.4,
  // μd 0.1, c 10 s/m: no end in 5000 sweeps; halved, 130). The settled state is the same.
  std::vector<double> slip_speed(speed_dependent ? n : 0, 0.0);
  std::vector<int> order = contact;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return a / mx != b / mx ? a / mx < b / mx : a % mx > b % mx; });
  for (t.sweeps = 1; t.sweeps <= settings.max_sweeps; ++t.sweeps) {
    double largest_squared = 0;
    for (int e : order) {
      const int i = e % mx, j = e / mx, d = at(e);
      const double x = g.x(i);
      // The slip at the centre is (u_e - b) / h: b is the displacement the material brings from
      // ahead less the rigid slip over the step h. With the stencil (c1, c2), h = dx / (c1 + c2)
      // and b = (c1 u_e+1 + c2 u_e+2) / (c1 + c2) - w h (BDF2: b = (4 u_e+1 - u_e+2) / 3 - w h,
      // h = 2 dx / 3).
      const Local& l = locals[e];
      const double c1 = l.c1, c2 = l.c2, h = g.dx / (c1 + c2);
      const double wx = longitudinal_slip[static_cast<std::size_t>(j)],
                   wy = creep.lateral + creep.spin * x;
      const double bx = (c1 * ux[d + 1] + c2 * ux[d + 2]) / (c1 + c2) - wx * h;
      const double by = (c1 * uy[d + 1] + c2 * uy[d + 2]) / (c1 + c2) - wy * h;
      // Coulomb friction needs no slip speed (the square roots here cost a tenth of a sweep).
      const double bound =
          (speed_dependent ? friction.at(slip_speed[e]) : friction.static_coefficient) *
          pressure[e];
      // The element's exact block minimisation: min ½ (q - q0)ᵀ D (q - q0) + rᵀ q over |q| <= bound
      // with D its self-influence and r its residual; where the bound is active the slip
      // r + D (q - q0) = -λ q opposes the traction, as Coulomb requires.
      const double rx = ux[d] - bx - l.xx * t.qx[e], ry = uy[d] - by - l.yy * t.qy[e];
      double qx = -rx / l.xx, qy = -ry / l.yy;
      if (bound <= 0) {
        qx = qy = 0;
      } else if (qx * qx + qy * qy > bound * bound) {
        // |q(λ)|² - bound² is convex and falls with λ: Newton from λ = 0 climbs to the root
        // without overshooting.
        double lambda = 0;
        for (int k = 0; k < 50; ++k) {
          const double ax = rx / (l.xx + lambda), ay = ry / (l.yy + lambda);
          const double f = ax * ax + ay * ay - bound * bound;
          const double df = -2 * (ax * ax / (l.xx + lambda) + ay * ay / (l.yy + lambda));
          const double step = -f / df;
          lambda += step;
          if (step <= 1e-14 * lambda)
            break;
        }
        qx = -rx / (l.xx + lambda);
        qy = -ry / (l.yy + lambda);
      }
      const double dqx = qx - t.qx[e], dqy = qy - t.qy[e];
      largest_squared = std::max(largest_squared, dqx * dqx + dqy * dqy);
      t.qx[e] = qx;
      t.qy[e] = qy;
      if (dqx != 0 || dqy != 0)
        spread_change(i, j, dqx, dqy);
      t.sx[e] = (ux[d] - bx) / h;
      t.sy[e] = (uy[d] - by) / h;
      if (speed_dependent)
        slip_speed[e] +=
            0.5 * (friction.rolling_speed * std::hypot(t.sx[e], t.sy[e]) - slip_speed[e]);
    }
    if (largest_squared <= settings.tolerance * scale * settings.tolerance * scale) {
      t.converged = true;
      break;
    }
  }
  for (int e : contact) {
    const double bound =
        friction.at(friction.rolling_speed * std::hypot(t.sx[e], t.sy[e])) * pressure[e];
    t.adhesion[e] = std::hypot(t.qx[e], t.qy[e]) < bound * (1 - 1e-9);
    if (t.adhesion[e])
      t.sx[e] = t.sy[e] = 0;
  }
  const double cell = g.dx * g.dy;
  double adhesion_area = 0, area = 0;
  for (int e : contact) {
    const double x = g.x(e % mx), y = g.y(e / mx);
    t.forces.Fx += t.qx[e] * cell;
    t.forces.Fy += t.qy[e] * cell;
    t.forces.Mz += (x * t.qy[e] - y * t.qx[e]) * cell;
    area += cell;
    adhesion_area += t.adhesion[e] ? cell : 0.0;
  }
  t.adhesion_fraction = area > 0 ? adhesion_area / area : 0.0;
  if (!t.converged)  // no number that could be mistaken for a result
    t.forces = {std::nan(""), std::nan(""), std::nan("")};
  return t;
}

TangentialSolution solve_steady_rolling(const HalfSpaceKernels& kernels,
                                        const std::vector<double>& pressure, const Creepages& creep,
                                        const FrictionLaw& friction, double spread,
                                        double* spread_found, const TangentialSettings& settings) {
  const bool falling =
      friction.dynamic_coefficient < friction.static_coefficient && friction.decay > 0;
  // Falling friction slows the sweeps' convergence: the two starts are settled far below the
  // spread that tells them apart, so that a slow approach is not mistaken for two solutions.
  TangentialSettings tight = settings;
  if (falling)
    tight.tolerance = std::min(settings.tolerance, 1e-4 * spread);
  TangentialSolution first = solve_tangential(kernels, pressure, creep, friction, tight);
  if (spread_found)
    *spread_found = 0;
  if (!falling || !first.converged)
    return first;
  TangentialSettings other = tight;
  other.start_in_full_slip = !settings.start_in_full_slip;
  const TangentialSolution second = solve_tangential(kernels, pressure, creep, friction, other);
  const ContactGrid& g = kernels.grid();
  double load = 0;
  for (double p : pressure)
    load += p * g.dx * g.dy;
  const double apart = second.converged ? std::hypot(first.forces.Fx - second.forces.Fx,
                                                     first.forces.Fy - second.forces.Fy) /
                                              (friction.static_coefficient * load)
                                        : std::numeric_limits<double>::infinity();
  if (spread_found)
    *spread_found = apart;
  if (apart > spread) {
    first.converged = false;
    first.forces = {std::nan(""), std::nan(""), std::nan("")};
  }
  return first;
}

}  // namespace railfe
