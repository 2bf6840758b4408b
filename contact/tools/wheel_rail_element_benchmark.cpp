// railfe-wheel-rail-benchmark: the per-iteration costs of the implicit wheel-rail contact element
// (issue 18, "Benchmark": contact search ≤ 20 µs per wheel, creep forces ≤ 1 µs per point by
// table).
//
//   railfe-wheel-rail-benchmark benchmark OUT.csv
//
// An S1002 wheelset on 60E1 rails (the shipped benchmark profiles) moves through lateral shifts
// of −6 to +6 mm and back in steps of 0.01 mm, as a wheelset does from one Newton iteration to the
// next, so every search starts from the point of the previous pose. Timed, each the median of 7
// batches of at least 50 ms: the search of one wheel (tread and flange, warm started), the creep
// forces of one point by each theory at a tread contact (N 57 kN, ξ 1e-3, η 2e-3, φ 0.05 /m), and
// the element's evaluation (search, Hertz, creep-force table) and tangent (forward differences) of
// one point. Writes one row per quantity to OUT.csv (quantity, value, unit, target), as
// regression/benchmarks/tool_benchmark.py reads it.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "contact/enforcement/wheel_rail_contact.hpp"
#include "contact/geometry/profile_file.hpp"
#include "contact/laws/creep_table.hpp"
#include "contact/laws/fastsim.hpp"
#include "contact/laws/saturation.hpp"

namespace {

using namespace railfe;

constexpr int kRepetitions = 7;
constexpr double kBatchSeconds = 0.05;

// Median time of one call of \p work in ns (batches of at least kBatchSeconds).
double median_ns(const std::function<void()>& work) {
  using clock = std::chrono::steady_clock;
  long calls = 1;
  for (;;) {
    const auto start = clock::now();
    for (long i = 0; i < calls; ++i)
      work();
    if (std::chrono::duration<double>(clock::now() - start).count() >= kBatchSeconds)
      break;
    calls *= 2;
  }
  std::vector<double> times;
  for (int r = 0; r < kRepetitions; ++r) {
    const auto start = clock::now();
    for (long i = 0; i < calls; ++i)
      work();
    times.push_back(std::chrono::duration<double, std::nano>(clock::now() - start).count() /
                    static_cast<double>(calls));
  }
  std::sort(times.begin(), times.end());
  return times[kRepetitions / 2];
}

// Lateral shifts −6..6 mm and back in 0.01 mm steps, cycled.
struct ShiftCycle {
  int index = 0;
  double next() {
    const int n = 1200, k = index++ % (2 * n);
    return 1e-5 * (k < n ? k - n / 2 : n / 2 - (k - n));
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || std::string(argv[1]) != "benchmark") {
    std::cerr << "usage: railfe-wheel-rail-benchmark benchmark OUT.csv\n";
    return 2;
  }
  TrackLayout track;
  track.profile_inclined = true;
  auto geometry = std::make_shared<WheelRailGeometry>(shipped_curve("MBench_UIC60_v3.prr"),
                                                      shipped_curve("MBench_S1002_v3.prw"), track,
                                                      WheelsetLayout{});
  struct Row {
    Row(std::string n, double t, std::string goal = "")
        : name(std::move(n)), ns(t), target(std::move(goal)) {}
    std::string name;
    double ns;
    std::string target;  // µs, or empty
  };
  std::vector<Row> rows;
  volatile double sink = 0;

  {  // One wheel's search: tread and flange, each from its last point.
    ShiftCycle cycle;
    double start[2][2];
    for (int part = 0; part < 2; ++part) {
      const GapSample s = least_gap_sample(*geometry, TrackSide::right, part == 1, WheelsetPose{});
      start[part][0] = s.s_wheel;
      start[part][1] = s.s_rail;
    }
    rows.push_back({"contact search per wheel (tread and flange, warm)", median_ns([&] {
                      WheelsetPose pose;
                      pose.lateral = cycle.next();
                      for (int part = 0; part < 2; ++part) {
                        const ContactPoint c =
                            search_contact(*geometry, TrackSide::right, part == 1, pose,
                                           start[part][0], start[part][1]);
                        start[part][0] = c.s_wheel;
                        start[part][1] = c.s_rail;
                        sink = sink + c.gap;
                      }
                    }),
                    "20"});
  }

  {  // Creep forces of one point.
    const double a = 6e-3, b = 4.5e-3, G = 210e9 / 2.6, N = 57e3, mu = 0.3;
    const Creepages creep{1e-3, 2e-3, 0.05};
    const KalkerCoefficients c = KalkerTable::shipped().at(a, b, 0.3);
    rows.push_back({"creep forces per point: table", median_ns([&] {
                      sink = sink + CreepTable::shipped().forces(a, b, G, 0.3, N, mu, creep).Fy;
                    }),
                    "1"});
    rows.push_back({"creep forces per point: Kalker coefficients (table lookup)",
                    median_ns([&] { sink = sink + KalkerTable::shipped().at(a, b, 0.3).C22; })});
    rows.push_back({"creep forces per point: linear (coefficients given)",
                    median_ns([&] { sink = sink + kalker_linear(c, G, a, b, creep).Fy; })});
    rows.push_back(
        {"creep forces per point: Shen-Hedrick-Elkins (coefficients given)", median_ns([&] {
           sink = sink + shen_hedrick_elkins(kalker_linear(c, G, a, b, creep), N, mu).Fy;
         })});
    PolachParameters polach_parameters;
    polach_parameters.friction = mu;
    rows.push_back({"creep forces per point: Polach (coefficients given)", median_ns([&] {
                      sink = sink + polach(c, G, a, b, N, creep, polach_parameters).Fy;
                    })});
    FastsimSettings fast;
    fast.cells_x = fast.strips = 10;
    fast.fields = false;
    rows.push_back({"creep forces per point: FASTSIM 10 x 10 (coefficients given)", median_ns([&] {
                      sink = sink + fastsim(c, G, a, b, N, mu, creep, fast).forces.Fy;
                    })});
  }

  {  // The element: evaluation and tangent of the right tread.
    WheelRailContactSettings settings;
    settings.wheel = settings.rail = ElasticBody{210e9, 0.3};
    settings.theory = CreepTheory::table;
    WheelRailContact element(geometry, TrackSide::right, false, settings);
    const RigidContact rigid = solve_rigid_contact(*geometry, 0, 0, nullptr);
    ContactKinematics state;
    state.wheelset_u = {0, 0, rigid.vertical + 6e-5, rigid.roll, 0, 0};
    state.wheelset_v = {0, 0.05, 0, 0, 0, 0};
    state.speed = 30;
    state.spin = -30 / 0.46;
    ShiftCycle cycle;
    rows.push_back({"element evaluation per point (search, Hertz, table)", median_ns([&] {
                      state.wheelset_u[1] = 0.2 * cycle.next();
                      sink = sink + element.evaluate(state).hertz.load;
                    })});
    state.wheelset_u[1] = 0;
    const ContactState at = element.evaluate(state);
    double k[81], c[81];
    rows.push_back({"element tangent per point (forward differences)", median_ns([&] {
                      element.tangent(state, at, k, c);
                      sink = sink + k[10];
                    })});
  }

  std::ofstream out(argv[2]);
  out << "quantity,value,unit,target\n";
  for (const Row& row : rows) {
    out << '"' << row.name << "\"," << row.ns * 1e-3 << ",us," << row.target << "\n";
    std::cout << row.name << ": " << row.ns * 1e-3 << " us\n";
  }
  return sink == 12345.0 ? 1 : 0;
}
