#include "contact/laws/normal_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
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

namespace {

// \p values at \p at, linear between the points \p y (increasing); +infinity outside them.
double linear_between(const std::vector<double>& y, const std::vector<double>& values, double at) {
  if (y.size() < 2 || at < y.front() || at > y.back())
    return std::numeric_limits<double>::infinity();
  const std::size_t k = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(y.begin(), y.end(), at) - y.begin()), y.size() - 1);
  const double t = (at - y[k - 1]) / (y[k] - y[k - 1]);
  return values[k - 1] + t * (values[k] - values[k - 1]);
}

}  // namespace

double LateralSeparation::at(double at) const {
  return linear_between(y, s, at) - *std::min_element(s.begin(), s.end());
}

namespace {

// Per row, x of the leading edge (material enters at +x): the row's pressure taken as a half
// ellipse in x (exact for Hertz's, and the separation is A x² along every row), whose half-length
// is twice the pressure's standard deviation about its centre; kept between the row leader's
// centre and the first element beyond it (Hertz's edge may cut the leader). NaN for rows with fewer
// than two elements in contact. (Read from the two or three leading pressures instead, the edge
// misses by a fraction of an element, and the creep force at small creepage converges at first
// order: 0.9 % high at 40 x 40 on Hertz's.)
std::vector<double> row_leading_edge(const ContactGrid& grid, const std::vector<double>& pressure) {
  std::vector<double> edge(static_cast<std::size_t>(grid.my), std::nan(""));
  for (int j = 0; j < grid.my; ++j) {
    double sum = 0, first = 0, second = 0;
    int count = 0, lead = -1;
    for (int i = 0; i < grid.mx; ++i) {
      const double p = pressure[static_cast<std::size_t>(j * grid.mx + i)];
      if (p > 0) {
        sum += p;
        first += p * grid.x(i);
        second += p * grid.x(i) * grid.x(i);
        ++count;
        lead = i;
      }
    }
    if (count < 2)
      continue;
    const double centre = first / sum;
    const double half_length = 2 * std::sqrt(std::max(second / sum - centre * centre, 0.0));
    edge[static_cast<std::size_t>(j)] =
        std::clamp(centre + half_length, grid.x(lead), grid.x(lead) + 1.5 * grid.dx);
  }
  return edge;
}

}  // namespace

HertzPatch solve_separation_patch(const LateralSeparation& lateral, double A, double load, double G,
                                  double nu, int mx, int my, SeparationPatchInfo* info) {
  if (lateral.y.size() < 3 || lateral.y.size() != lateral.s.size())
    throw std::invalid_argument("a lateral separation needs at least 3 points (y, s)");
  const double reach_x = std::max(1.1, 1 / (1 - 3.0 / mx)),
               reach_y = std::max(1.1, 1 / (1 - 3.0 / my));
  // A box [x_low, x_high] × [y_low, y_high] widened as Hertz's grid is about its ellipse.
  auto grid_over = [&](double x_low, double x_high, double y_low, double y_high) {
    const double half_x = 0.5 * (x_high - x_low), half_y = 0.5 * (y_high - y_low);
    const ContactGrid grid{0.5 * (x_low + x_high) - reach_x * half_x,
                           0.5 * (y_low + y_high) - reach_y * half_y,
                           2 * reach_x * half_x / mx,
                           2 * reach_y * half_y / my,
                           mx,
                           my};
    if (grid.y0 < lateral.y.front() || grid.y0 + grid.my * grid.dy > lateral.y.back())
      throw std::invalid_argument("the contact reaches the ends of the lateral separation (y " +
                                  std::to_string(lateral.y.front()) + " to " +
                                  std::to_string(lateral.y.back()) +
                                  " m): give the profiles' separation over a wider range");
    return grid;
  };
  // The separation less its least value (LateralSeparation::at without its search for the least).
  const double least = *std::min_element(lateral.s.begin(), lateral.s.end());
  const auto gap = [&](double y) { return linear_between(lateral.y, lateral.s, y) - least; };
  HertzPatch patch;
  auto solve_on = [&](const ContactGrid& grid) {
    patch.kernels = std::make_unique<HalfSpaceKernels>(grid, G, nu);
    std::vector<double> separation(static_cast<std::size_t>(grid.size()));
    for (int j = 0; j < my; ++j)
      for (int i = 0; i < mx; ++i)
        separation[static_cast<std::size_t>(j * mx + i)] =
            A * grid.x(i) * grid.x(i) + gap(grid.y(j));
    patch.normal = solve_normal(*patch.kernels, separation, load, 1e-8, 2000);
  };
  // The contact lies where the separation is below the approach δ (the elastic displacements
  // only add to it). So a grid over that region, grown until δ stays below the value it was
  // fitted to, holds the contact; Hertz's δ for the curvature A across as well starts it.
  const ElasticBody body{2 * G * (1 + nu), nu};
  double approach = hertz_contact(A, A, contact_modulus(body, body), load).approach;
  const double spacing = (lateral.y.back() - lateral.y.front()) / (lateral.y.size() - 1);
  int refits = 0;
  for (;; ++refits) {
    double y_low = std::numeric_limits<double>::infinity(), y_high = -y_low;
    for (double y : lateral.y)
      if (gap(y) <= approach) {
        y_low = std::min(y_low, y - spacing);
        y_high = std::max(y_high, y + spacing);
      }
    const double half_x = std::sqrt(approach / A);
    solve_on(grid_over(-half_x, half_x, y_low, y_high));
    if (patch.normal.approach <= approach)
      break;
    if (refits >= 40)
      throw std::invalid_argument("the non-Hertzian patch's grid did not settle in 40 refits");
    approach = 1.25 * patch.normal.approach;
  }
  // Then a grid over the contact found, 10 % (and 1.5 elements) beyond it as Hertz's: regrown
  // while the contact touches its outer elements.
  double grow = 1;
  for (int tries = 0; tries < 10; ++tries, ++refits) {
    const ContactGrid& g = patch.kernels->grid();
    double x_low = std::numeric_limits<double>::infinity(), x_high = -x_low, y_low = x_low,
           y_high = -x_low;
    for (int e = 0; e < g.size(); ++e)
      if (patch.normal.pressure[static_cast<std::size_t>(e)] > 0) {
        x_low = std::min(x_low, g.x(e % g.mx) - 0.5 * g.dx);
        x_high = std::max(x_high, g.x(e % g.mx) + 0.5 * g.dx);
        y_low = std::min(y_low, g.y(e / g.mx) - 0.5 * g.dy);
        y_high = std::max(y_high, g.y(e / g.mx) + 0.5 * g.dy);
      }
    const double cx = 0.5 * (x_low + x_high), cy = 0.5 * (y_low + y_high);
    const double hx = 0.5 * grow * (x_high - x_low), hy = 0.5 * grow * (y_high - y_low);
    solve_on(grid_over(cx - hx, cx + hx, cy - hy, cy + hy));
    const ContactGrid& fitted = patch.kernels->grid();
    bool touches = false;
    for (int j = 0; j < my; ++j)
      for (int i = 0; i < mx; ++i)
        if ((i == 0 || j == 0 || i == mx - 1 || j == my - 1) &&
            patch.normal.pressure[static_cast<std::size_t>(j * fitted.mx + i)] > 0)
          touches = true;
    if (!touches)
      break;
    grow *= 1.2;
  }
  if (info)
    info->refits = refits;
  if (!lateral.rolling_radius.empty()) {
    if (lateral.rolling_radius.size() != lateral.y.size() || lateral.y.front() > 0 ||
        lateral.y.back() < 0)
      throw std::invalid_argument(
          "rolling radii need one per point and a range of y that holds y = 0 (where the "
          "creepage is given)");
    const ContactGrid& g = patch.kernels->grid();
    const auto radius = [&](double y) {
      return linear_between(lateral.y, lateral.rolling_radius, y);
    };
    const double centre = radius(0);
    for (int j = 0; j < g.my; ++j)
      patch.row_longitudinal_slip.push_back(-(radius(g.y(j)) - centre) / centre);
  }
  patch.leading_edge = row_leading_edge(patch.kernels->grid(), patch.normal.pressure);
  return patch;
}

}  // namespace railfe
