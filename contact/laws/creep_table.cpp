#include "contact/laws/creep_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "contact/laws/hertz.hpp"
#include "contact/laws/normal_problem.hpp"
#include "contact/laws/tangential_problem.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

// Lower node and weight of \p x on increasing \p nodes, clamped to the ends.
std::pair<std::size_t, double> locate(const std::vector<double>& nodes, double x) {
  if (x <= nodes.front())
    return {0, 0.0};
  if (x >= nodes.back())
    return {nodes.size() - 2, 1.0};
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1;
  return {i, (x - nodes[i]) / (nodes[i + 1] - nodes[i])};
}

}  // namespace

std::size_t CreepTable::index(std::size_t r, std::size_t i, std::size_t j, std::size_t k) const {
  const std::size_t n = axes_.t.size();
  return 3 * (((r * n + i) * n + j) * n + k);
}

void CreepTable::build(const CreepTableAxes& axes, const std::string& path,
                       void (*progress)(int, int)) {
  const double E = 210e9, nu = axes.poisson, G = E / (2 * (1 + nu)), load = 1e5, mu = 0.3;
  const double a = 5e-3;
  const int m = axes.grid, n = static_cast<int>(axes.t.size());
  std::ofstream out(path);
  out.precision(17);
  out << "# railfe creep-force table (the USETAB role): exact steady-rolling solver, " << m << " x "
      << m << " elements, Coulomb friction\n# poisson " << nu << "\n# grid " << m
      << "\n# s = t / (1 - |t|): s_xi = xi G / (mu p0), s_eta = eta G / (mu p0), s_phi = phi a G "
         "/ (mu p0)\nratio,t_xi,t_eta,t_phi,Fx_over_muN,Fy_over_muN,Mz_over_muNa\n";
  int done = 0;
  const int total = static_cast<int>(axes.ratios.size()) * n * n * n;
  for (double ratio : axes.ratios) {
    const double b = a / ratio;
    const HertzContact h = hertz_from_semi_axes(a, b, contact_modulus({E, nu}, {E, nu}), load);
    const HertzPatch patch = solve_hertz_patch(h, G, nu, m);
    const HalfSpaceKernels& kernels = *patch.kernels;
    const NormalSolution& normal = patch.normal;
    FrictionLaw friction;
    friction.static_coefficient = friction.dynamic_coefficient = mu;
    TangentialSettings settings;
    settings.leading_edge = patch.leading_edge;
    const double unit = mu * h.pressure / G;
    // Forces are odd in the creepages: the node opposite (i, j, k) is its mirror image.
    std::map<std::array<int, 3>, std::array<double, 3>> values;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const std::array<int, 3> mirror{n - 1 - i, n - 1 - j, n - 1 - k};
          std::array<double, 3> v;
          if (auto found = values.find(mirror); found != values.end()) {
            v = {-found->second[0], -found->second[1], -found->second[2]};
          } else {
            auto s = [&](int q) { return axes.t[q] / (1 - std::abs(axes.t[q])); };
            const TangentialSolution t =
                solve_tangential(kernels, normal.pressure,
                                 {s(i) * unit, s(j) * unit, s(k) * unit / a}, friction, settings);
            if (!t.converged)
              throw std::runtime_error("creep table: the exact solver did not settle");
            v = {t.forces.Fx / (mu * load), t.forces.Fy / (mu * load),
                 t.forces.Mz / (mu * load * a)};
          }
          values[{i, j, k}] = v;
          out << ratio << ',' << axes.t[i] << ',' << axes.t[j] << ',' << axes.t[k] << ',' << v[0]
              << ',' << v[1] << ',' << v[2] << '\n';
          if (progress)
            progress(++done, total);
        }
  }
}

CreepTable::CreepTable(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw_input_error(path, "", "creep-force table not found or not readable");
  std::string line;
  int number = 0;
  std::vector<std::array<double, 7>> rows;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("# poisson ", 0) == 0)
      axes_.poisson = std::stod(line.substr(10));
    else if (line.rfind("# grid ", 0) == 0)
      axes_.grid = std::stoi(line.substr(7));
    if (line.empty() || line[0] == '#')
      continue;
    if (!header) {
      header = true;
      continue;
    }
    std::array<double, 7> row;
    std::stringstream fields(line);
    std::string cell;
    for (double& v : row) {
      if (!std::getline(fields, cell, ','))
        throw_input_error(path, "line " + std::to_string(number), "needs 7 values");
      v = std::stod(cell);
    }
    rows.push_back(row);
  }
  for (const auto& row : rows) {
    axes_.ratios.push_back(row[0]);
    axes_.t.push_back(row[1]);
  }
  for (auto* axis : {&axes_.ratios, &axes_.t}) {
    std::sort(axis->begin(), axis->end());
    axis->erase(std::unique(axis->begin(), axis->end()), axis->end());
  }
  const std::size_t n = axes_.t.size();
  if (axes_.ratios.size() < 2 || n < 2 || rows.size() != axes_.ratios.size() * n * n * n)
    throw_input_error(path, "", "the nodes do not form a complete table");
  values_.assign(rows.size() * 3, 0.0);
  auto position = [](const std::vector<double>& axis, double v) {
    return static_cast<std::size_t>(std::lower_bound(axis.begin(), axis.end(), v) - axis.begin());
  };
  for (const auto& row : rows) {
    const std::size_t at = index(position(axes_.ratios, row[0]), position(axes_.t, row[1]),
                                 position(axes_.t, row[2]), position(axes_.t, row[3]));
    values_[at] = row[4];
    values_[at + 1] = row[5];
    values_[at + 2] = row[6];
  }
  for (double r : axes_.ratios)
    log_ratios_.push_back(std::log(r));
}

const CreepTable& CreepTable::shipped() {
  static const CreepTable table(RAILFE_CREEP_TABLE);
  return table;
}

CreepForces CreepTable::forces(double a, double b, double G, double nu, double load,
                               double friction, const Creepages& creep) const {
  const double ratio = a / b;
  if (ratio < axes_.ratios.front() * (1 - 1e-12) || ratio > axes_.ratios.back() * (1 + 1e-12))
    throw std::invalid_argument("a / b outside the creep table");
  if (std::abs(nu - axes_.poisson) > 1e-6)
    throw std::invalid_argument("the creep table was made for another Poisson's ratio");
  const double p0 = 3 * load / (2 * M_PI * a * b), unit = G / (friction * p0);
  const auto [r, wr] = locate(log_ratios_, std::log(ratio));
  // Cubic (Catmull-Rom) weights along each creepage axis, over the nodes i-1 .. i+2 (ends
  // repeated): the creep curve bends too much between nodes for linear weights.
  const std::size_t n = axes_.t.size();
  auto cubic = [&](double s, std::size_t nodes[4], double weights[4]) {
    const auto [i, w] = locate(axes_.t, s / (1 + std::abs(s)));
    const double w2 = w * w, w3 = w2 * w;
    weights[0] = 0.5 * (-w3 + 2 * w2 - w);
    weights[1] = 0.5 * (3 * w3 - 5 * w2 + 2);
    weights[2] = 0.5 * (-3 * w3 + 4 * w2 + w);
    weights[3] = 0.5 * (w3 - w2);
    for (int q = 0; q < 4; ++q)
      nodes[q] = static_cast<std::size_t>(
          std::clamp<long>(static_cast<long>(i) - 1 + q, 0, static_cast<long>(n) - 1));
  };
  std::size_t ni[4], nj[4], nk[4];
  double wi[4], wj[4], wk[4];
  cubic(creep.longitudinal * unit, ni, wi);
  cubic(creep.lateral * unit, nj, wj);
  cubic(creep.spin * a * unit, nk, wk);
  double v[3] = {0, 0, 0};
  for (int dr = 0; dr < 2; ++dr) {
    const double w_r = dr ? wr : 1 - wr;
    if (w_r == 0)
      continue;
    for (int qi = 0; qi < 4; ++qi)
      for (int qj = 0; qj < 4; ++qj)
        for (int qk = 0; qk < 4; ++qk) {
          const double w = w_r * wi[qi] * wj[qj] * wk[qk];
          const std::size_t at = index(r + dr, ni[qi], nj[qj], nk[qk]);
          for (int q = 0; q < 3; ++q)
            v[q] += w * values_[at + q];
        }
  }
  const double scale = friction * load;
  return {v[0] * scale, v[1] * scale, v[2] * scale * a};
}

}  // namespace railfe
