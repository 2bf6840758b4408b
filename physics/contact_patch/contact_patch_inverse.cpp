#include "physics/contact_patch/contact_patch_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"

namespace railfe {

void find_creepages(StepContext& context, const HertzPatch& patch, const FrictionLaw& friction,
                    double tolerance, const std::vector<std::array<double, 2>>& forces,
                    std::vector<Creepages>& cases) {
  const ContactGrid& grid = patch.kernels->grid();
  const std::vector<double>& pressure = patch.normal.pressure;
  const double load = std::accumulate(pressure.begin(), pressure.end(), 0.0) * grid.dx * grid.dy;
  const double bound = friction.static_coefficient * load;
  TangentialSettings settings;
  settings.leading_edge = patch.leading_edge;
  settings.row_longitudinal_slip = patch.row_longitudinal_slip;
  const std::string file = context.step_name + "_inverse.csv";
  CsvWriter table(context.output.staging_path(file),
                  {"case", "FN_N", "Fx_N", "Fy_N", "phi_per_m", "xi", "eta", "Fx_found_N",
                   "Fy_found_N", "force_miss_over_muN", "iterations", "adhesion_fraction"},
                  context.model.comm().is_root());
  double largest_miss = 0;
  int most_iterations = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const double Fx = forces[k][0], Fy = forces[k][1];
    const InverseCreepageResult r = solve_for_creepages(
        *patch.kernels, pressure, Fx, Fy, cases[k].spin, friction, tolerance, settings);
    if (!r.converged)
      throw RunError(context.path + ": case " + std::to_string(k) + " (Fx " +
                     CsvWriter::format(Fx) + " N, Fy " + CsvWriter::format(Fy) + " N, mu N " +
                     CsvWriter::format(bound) + " N on the exact solver's grid): no creepages " +
                     "found: " + r.failure);
    cases[k] = r.creepages;
    const double miss = std::hypot(r.solution.forces.Fx - Fx, r.solution.forces.Fy - Fy) / bound;
    largest_miss = std::max(largest_miss, miss);
    most_iterations = std::max(most_iterations, r.iterations);
    table.write_row(
        {std::to_string(k), CsvWriter::format(load), CsvWriter::format(Fx), CsvWriter::format(Fy),
         CsvWriter::format(cases[k].spin), CsvWriter::format(cases[k].longitudinal),
         CsvWriter::format(cases[k].lateral), CsvWriter::format(r.solution.forces.Fx),
         CsvWriter::format(r.solution.forces.Fy), CsvWriter::format(miss),
         std::to_string(r.iterations), CsvWriter::format(r.solution.adhesion_fraction)});
  }
  table.flush();
  const std::string section = "Step " + context.step_name + " (contact patch)";
  context.summary.add(section, "inverse: largest force miss over mu N", largest_miss);
  context.summary.add(section, "inverse: most Newton iterations", most_iterations);
}

}  // namespace railfe
