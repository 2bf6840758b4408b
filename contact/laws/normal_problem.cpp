#include "contact/laws/normal_problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace railfe {

NormalSolution solve_normal(const HalfSpaceKernels& kernels, const std::vector<double>& separation,
                            double load, double tolerance, int max_iterations,
                            const std::vector<double>* start) {
  const ContactGrid& grid = kernels.grid();
  const std::size_t n = static_cast<std::size_t>(grid.size());
  if (separation.size() != n || !(load > 0) || (start && start->size() != n))
    throw std::invalid_argument(
        "the normal problem needs a separation (and a start, if any) per element and a load");
  const double cell = grid.dx * grid.dy;
  NormalSolution s;
  s.pressure.assign(n, load / (cell * static_cast<double>(n)));
  if (start) {
    double total = 0;
    for (double p : *start)
      total += std::max(p, 0.0) * cell;
    if (total > 0)
      for (std::size_t i = 0; i < n; ++i)
        s.pressure[i] = std::max((*start)[i], 0.0) * load / total;
  }
  std::vector<double> gap(n), direction(n, 0.0), previous(n);
  // u = A p is carried from one iteration to the next (one convolution per iteration, of the
  // direction): the step p - τ d moves it by -τ A d, and the few elements the step clips to zero
  // or brings into contact add their columns directly; when many change, it is recomputed.
  std::vector<double> u = kernels.normal(s.pressure);
  std::vector<std::pair<int, double>> changed;
  const std::size_t direct_limit = 16;
  double gap_norm_old = 1;
  bool restart = true;
  for (s.iterations = 1; s.iterations <= max_iterations; ++s.iterations) {
    // Gap relative to its mean over the contact set: the mean is the approach.
    double mean = 0;
    int in_contact = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gap[i] = separation[i] + u[i];
      if (s.pressure[i] > 0) {
        mean += gap[i];
        ++in_contact;
      }
    }
    mean /= std::max(in_contact, 1);
    s.approach = mean;
    double gap_norm = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gap[i] -= mean;
      if (s.pressure[i] > 0)
        gap_norm += gap[i] * gap[i];
    }
    for (std::size_t i = 0; i < n; ++i)
      direction[i] = s.pressure[i] > 0
                         ? gap[i] + (restart ? 0.0 : gap_norm / gap_norm_old * direction[i])
                         : 0.0;
    gap_norm_old = gap_norm;
    const std::vector<double> r = kernels.normal(direction);
    double r_mean = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (s.pressure[i] > 0)
        r_mean += r[i];
    r_mean /= std::max(in_contact, 1);
    double numerator = 0, denominator = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (s.pressure[i] > 0) {
        numerator += gap[i] * direction[i];
        denominator += (r[i] - r_mean) * direction[i];
      }
    const double tau = denominator != 0 ? numerator / denominator : 0.0;
    previous = s.pressure;
    changed.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (s.pressure[i] > 0) {
        const double trial = s.pressure[i] - tau * direction[i];
        s.pressure[i] = std::max(trial, 0.0);
        if (trial < 0)
          changed.emplace_back(static_cast<int>(i), -trial);
      }
    // Elements outside the contact that penetrate join it.
    restart = false;
    for (std::size_t i = 0; i < n; ++i)
      if (s.pressure[i] == 0 && previous[i] == 0 && gap[i] < 0) {
        s.pressure[i] = -tau * gap[i];
        changed.emplace_back(static_cast<int>(i), s.pressure[i]);
        restart = true;
      }
    double total = 0;
    for (double p : s.pressure)
      total += p * cell;
    if (total <= 0)
      break;
    const double factor = load / total;
    double change = 0;
    for (std::size_t i = 0; i < n; ++i) {
      s.pressure[i] *= factor;
      change += std::abs(s.pressure[i] - previous[i]) * cell;
    }
    if (changed.size() > direct_limit) {
      u = kernels.normal(s.pressure);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        u[i] -= tau * r[i];
      for (const auto& [element, pressure] : changed)
        kernels.add_normal_influence(element, pressure, u);
      for (double& value : u)
        value *= factor;
    }
    if (change / load < tolerance) {
      s.converged = true;
      break;
    }
  }
  s.load = 0;
  for (double p : s.pressure) {
    s.load += p * cell;
    s.max_pressure = std::max(s.max_pressure, p);
    s.area += p > 0 ? cell : 0.0;
  }
  return s;
}

std::vector<double> hertz_leading_edge(const HertzContact& hertz, const ContactGrid& grid) {
  std::vector<double> edge(static_cast<std::size_t>(grid.my), std::nan(""));
  for (int j = 0; j < grid.my; ++j) {
    const double inside = 1 - (grid.y(j) / hertz.b) * (grid.y(j) / hertz.b);
    if (inside > 0)
      edge[static_cast<std::size_t>(j)] = hertz.a * std::sqrt(inside);
  }
  return edge;
}

HertzPatch solve_hertz_patch(const HertzContact& hertz, double G, double nu, int m) {
  return solve_hertz_patch(hertz, G, nu, m, m);
}

HertzPatch solve_hertz_patch(const HertzContact& hertz, double G, double nu, int mx, int my) {
  const double reach_x = std::max(1.1, 1 / (1 - 3.0 / mx)),
               reach_y = std::max(1.1, 1 / (1 - 3.0 / my));
  const ContactGrid grid{-reach_x * hertz.a,
                         -reach_y * hertz.b,
                         2 * reach_x * hertz.a / mx,
                         2 * reach_y * hertz.b / my,
                         mx,
                         my};
  HertzPatch patch;
  patch.kernels = std::make_unique<HalfSpaceKernels>(grid, G, nu);
  std::vector<double> separation(grid.size()), start(grid.size());
  for (int j = 0; j < my; ++j)
    for (int i = 0; i < mx; ++i) {
      const double x = grid.x(i), y = grid.y(j);
      separation[j * mx + i] = hertz.A * x * x + hertz.B * y * y;
      const double inside = 1 - (x / hertz.a) * (x / hertz.a) - (y / hertz.b) * (y / hertz.b);
      start[j * mx + i] = hertz.pressure * std::sqrt(std::max(inside, 0.0));
    }
  // 1e-8 of the load in the pressures' last change: the creep forces then lie within 3e-10 μN of
  // those at 1e-10 (a/b = 0.5 patch, 24 x 22 and 48 x 44), below the tangential solve's own
  // 1e-9, in a quarter fewer iterations.
  patch.normal = solve_normal(*patch.kernels, separation, hertz.load, 1e-8, 2000, &start);
  patch.leading_edge = hertz_leading_edge(hertz, grid);
  return patch;
}

}  // namespace railfe
