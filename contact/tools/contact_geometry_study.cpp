// railfe-contact-geometry: the contact-geometry studies that need many searches and a clock,
// kept out of the unit tests. "stability OUT.csv" runs the online search across the S1002/60E1
// shift range three ways (plain Newton or trust region, centred or table start) against a fine
// table; "benchmark OUT.csv" times the online search, the table lookup and a 3000-shift table;
// "resolution OUT.csv" charts the table's build time against its accuracy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/profile_file.hpp"

#include "framework/tools/study_main.hpp"

namespace railfe {
namespace {

WheelRailGeometry benchmark_geometry() {
  TrackLayout track;
  track.profile_inclined = true;
  return WheelRailGeometry(shipped_curve("MBench_UIC60_v3.prr"),
                           shipped_curve("MBench_S1002_v3.prw"), track, WheelsetLayout{});
}

int stability(const std::string& out) {
  const WheelRailGeometry geometry = benchmark_geometry();
  const ContactTable fine(geometry, 0.015, 3001), coarse(geometry, 0.015, 121);
  const RigidContact& centre = fine.rows()[fine.rows().size() / 2];
  std::ofstream csv(out);
  csv << "shift_mm,method,start,part,status,iterations,correct,rail_y_error_mm\n";
  for (std::size_t i = fine.rows().size() / 2; i < fine.rows().size(); i += 2) {
    const RigidContact& row = fine.rows()[i];
    const ContactPoint& expected = row.active(TrackSide::right);
    const int part = expected.flange ? 1 : 0;
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    for (bool trust : {false, true})
      for (bool from_table : {false, true}) {
        SearchSettings settings;
        settings.use_trust_region = trust;
        const auto start = from_table ? coarse.start(TrackSide::right, expected.flange, row.lateral)
                                      : std::array<double, 2>{centre.parts[1][part].s_wheel,
                                                              centre.parts[1][part].s_rail};
        const ContactPoint found = search_contact(geometry, TrackSide::right, expected.flange, pose,
                                                  start[0], start[1], settings);
        const double error = found.rail_point.y - expected.rail_point.y;
        csv << row.lateral * 1e3 << ',' << (trust ? "trust region" : "plain Newton") << ','
            << (from_table ? "table" : "centred") << ',' << (expected.flange ? "flange" : "tread")
            << ',' << status_name(found.status) << ',' << found.iterations << ','
            << (found.valid() && std::abs(error) < 1e-6 ? 1 : 0) << ',' << error * 1e3 << '\n';
      }
  }
  std::cout << "wrote " << out << '\n';
  return 0;
}

int benchmark(const std::string& out) {
  const WheelRailGeometry geometry = benchmark_geometry();
  double build = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    const ContactTable table(geometry, 0.015, 3001);
    build = std::min(build, seconds_since(start));
  }
  const ContactTable table(geometry, 0.015, 3001), coarse(geometry, 0.015, 121);
  // Poses from the fine table, searched from the coarse one: what a time step does.
  std::mt19937 random(1);
  std::uniform_int_distribution<std::size_t> pick(0, table.rows().size() - 1);
  std::vector<std::size_t> rows(20000);
  for (auto& r : rows)
    r = pick(random);
  long iterations = 0;
  int failed = 0;
  auto start = std::chrono::steady_clock::now();
  for (std::size_t r : rows) {
    const RigidContact& row = table.rows()[r];
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      const bool flange = row.active(side).flange;
      const auto s = coarse.start(side, flange, row.lateral);
      const ContactPoint p = search_contact(geometry, side, flange, pose, s[0], s[1]);
      iterations += p.iterations;
      failed += p.valid() ? 0 : 1;
    }
  }
  const double search = seconds_since(start) / (2.0 * rows.size());
  std::vector<double> shifts(1000000);
  std::uniform_real_distribution<double> shift(-0.015, 0.015);
  for (auto& y : shifts)
    y = shift(random);
  double sink = 0;
  start = std::chrono::steady_clock::now();
  for (double y : shifts)
    sink += table.start(TrackSide::right, false, y)[0];
  const double lookup = seconds_since(start) / shifts.size();
  std::ofstream csv(out);
  csv << "quantity,value,unit,target\n"
      << "online search per wheel," << search * 1e6 << ",us,20\n"
      << "online search iterations per call," << double(iterations) / (2.0 * rows.size()) << ",1,\n"
      << "online searches not converged," << failed << ",1,\n"
      << "table lookup," << lookup * 1e6 << ",us,0.5\n"
      << "3001-shift table build," << build << ",s,1\n";
  std::cout << "wrote " << out << " (checksum " << sink << ")\n";
  return 0;
}

// Speed against accuracy of the table: build time and the error of its interpolated rolling
// radius difference and flange contact shift against a 0.002 mm table, per resolution.
int resolution(const std::string& out) {
  const WheelRailGeometry geometry = benchmark_geometry();
  const double range = 0.015;
  const ContactTable reference(geometry, range, 15001);
  const double flange = reference.flange_contact_shift(TrackSide::right);
  std::ofstream csv(out);
  csv << "resolution_m,rows,build_s,delta_r_rms_error_m,delta_r_median_error_m,"
         "flange_shift_error_m\n";
  for (double step : {1e-3, 5e-4, 2.5e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6}) {
    const int rows = 2 * static_cast<int>(std::lround(range / step)) + 1;
    double build = 1e300;
    std::unique_ptr<ContactTable> table;
    for (int repeat = 0; repeat < 3; ++repeat) {
      const auto start = std::chrono::steady_clock::now();
      table = std::make_unique<ContactTable>(geometry, range, rows);
      build = std::min(build, seconds_since(start));
    }
    std::vector<double> errors;
    for (std::size_t i = 0; i < reference.rows().size(); ++i) {
      const double y = reference.rows()[i].lateral;
      const double position = (y + range) / step;
      const std::size_t k = std::min<std::size_t>(position, table->rows().size() - 2);
      const double w = position - k;
      const double interpolated = (1 - w) * table->rolling_radius_difference(k) +
                                  w * table->rolling_radius_difference(k + 1);
      errors.push_back(std::abs(interpolated - reference.rolling_radius_difference(i)));
    }
    double sum = 0;
    for (double e : errors)
      sum += e * e;
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    csv << step << ',' << rows << ',' << build << ',' << std::sqrt(sum / errors.size()) << ','
        << errors[errors.size() / 2] << ','
        << std::abs(table->flange_contact_shift(TrackSide::right) - flange) << '\n';
    std::cout << "resolution " << step * 1e3 << " mm: " << build << " s\n";
  }
  std::cout << "wrote " << out << '\n';
  return 0;
}

}  // namespace
}  // namespace railfe

int main(int argc, char** argv) {
  return railfe::run_study(argc, argv, "railfe-contact-geometry",
                           {{"stability", railfe::stability},
                            {"benchmark", railfe::benchmark},
                            {"resolution", railfe::resolution}});
}
