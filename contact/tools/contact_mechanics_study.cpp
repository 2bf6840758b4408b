// railfe-contact-mechanics: contact-mechanics studies that need many solves, kept out of the
// unit tests. "falling-friction OUT.csv" maps where the exact steady-rolling solver finds more
// than one steady state as friction falls with slip velocity (Hertz patch of the issue's
// wheel on a crown, 20 x 20 grid, ξ = 2e-3, V = 30 m/s, μs = 0.4). "creep-table OUT.csv" builds
// the creep-force table shipped as inputs/kalker/creep_table_nu030.csv (exact solver at 30 x 30,
// about a minute).
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "contact/laws/creep_table.hpp"
#include "contact/laws/hertz.hpp"
#include "contact/laws/normal_problem.hpp"
#include "contact/laws/tangential_problem.hpp"

#include "contact/tools/study_main.hpp"

namespace railfe {
namespace {

int falling_friction(const std::string& out) {
  const double E = 210e9, nu = 0.3, G = E / (2 * (1 + nu)), load = 1e5;
  const HertzContact h =
      hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({E, nu}, {E, nu}), load);
  const int m = 20;
  const ContactGrid grid{-1.1 * h.a, -1.1 * h.b, 2.2 * h.a / m, 2.2 * h.b / m, m, m};
  const HalfSpaceKernels kernels(grid, G, nu);
  std::vector<double> separation(grid.size());
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i)
      separation[j * m + i] = h.A * grid.x(i) * grid.x(i) + h.B * grid.y(j) * grid.y(j);
  const NormalSolution normal = solve_normal(kernels, separation, load);
  std::ofstream csv(out);
  csv << "mu_static,mu_dynamic,decay_s_per_m,speed_m_per_s,xi,spread_of_starts,unique,Fx_N,"
         "sweeps\n";
  for (int k = 0; k <= 7; ++k)
    for (int l = 0; l <= 10; ++l) {
      FrictionLaw friction;
      friction.static_coefficient = 0.4;
      friction.dynamic_coefficient = 0.4 - 0.05 * k;
      friction.decay = l == 0 ? 0.0 : std::pow(10.0, 0.5 * (l - 1));
      friction.rolling_speed = 30;
      double spread = 0;
      const TangentialSolution t =
          solve_steady_rolling(kernels, normal.pressure, {2e-3, 0, 0}, friction, 1e-6, &spread);
      csv << friction.static_coefficient << ',' << friction.dynamic_coefficient << ','
          << friction.decay << ',' << friction.rolling_speed << ",0.002," << spread << ','
          << (t.converged ? 1 : 0) << ',' << t.forces.Fx << ',' << t.sweeps << '\n';
    }
  std::cout << "wrote " << out << '\n';
  return 0;
}

void report(int done, int total) {
  if (done % 200 == 0 || done == total)
    std::cerr << "creep table: " << done << " / " << total << " nodes\n";
}

int creep_table(const std::string& out) {
  CreepTableAxes axes;
  axes.ratios = {0.2, 1.0 / 3, 0.5, 0.75, 1.0, 4.0 / 3, 2, 3, 5};
  for (int k = -4; k <= 4; ++k)
    axes.t.push_back(0.2 * k);
  axes.poisson = 0.3;
  axes.grid = 30;
  CreepTable::build(axes, out, report);
  std::cout << "wrote " << out << '\n';
  return 0;
}

}  // namespace
}  // namespace railfe

int main(int argc, char** argv) {
  return railfe::run_study(
      argc, argv, "railfe-contact-mechanics",
      {{"falling-friction", railfe::falling_friction}, {"creep-table", railfe::creep_table}});
}
