// railfe-moving-study: a vehicle crossing a simply supported bridge by the direct method
// (physics/implicit/moving_crossing.hpp) for the sprung-mass verification
// (physics/tests/moving_sprung_mass.py), the speed/accuracy study and the benchmark.
// Arguments key=value, named as the fields of CrossingSettings (speed in km/h as speed_kmh);
// writes the histories to csv=PATH and a key=value summary on stdout.
#include <fstream>
#include <functional>
#include <iostream>
#include <map>

#include "framework/base/error.hpp"
#include "physics/implicit/moving_crossing.hpp"

namespace {

using namespace railfe;

int run(int argc, char** argv) {
  CrossingSettings s;
  std::string csv;
  std::map<std::string, std::function<void(const std::string&)>> keys = {
      {"span", [&](const std::string& x) { s.span = std::stod(x); }},
      {"elements", [&](const std::string& x) { s.elements = std::stoi(x); }},
      {"lines", [&](const std::string& x) { s.lines = std::stoi(x); }},
      {"young", [&](const std::string& x) { s.young = std::stod(x); }},
      {"inertia", [&](const std::string& x) { s.inertia = std::stod(x); }},
      {"mass_per_length", [&](const std::string& x) { s.mass_per_length = std::stod(x); }},
      {"lumped", [&](const std::string& x) { s.lumped = x == "1"; }},
      {"wheels", [&](const std::string& x) { s.wheels = std::stoi(x); }},
      {"vehicle_dofs", [&](const std::string& x) { s.vehicle_dofs = std::stoi(x); }},
      {"vehicle_mass", [&](const std::string& x) { s.vehicle_mass = std::stod(x); }},
      {"wheel_mass", [&](const std::string& x) { s.wheel_mass = std::stod(x); }},
      {"stiffness", [&](const std::string& x) { s.stiffness = std::stod(x); }},
      {"speed_kmh", [&](const std::string& x) { s.speed = std::stod(x) / 3.6; }},
      {"bump_height", [&](const std::string& x) { s.bump_height = std::stod(x); }},
      {"bump_length", [&](const std::string& x) { s.bump_length = std::stod(x); }},
      {"bump_start", [&](const std::string& x) { s.bump_start = std::stod(x); }},
      {"dt", [&](const std::string& x) { s.dt = std::stod(x); }},
      {"alpha", [&](const std::string& x) { s.alpha = std::stod(x); }},
      {"solver", [&](const std::string& x) { s.solver = x; }},
      {"moving_force", [&](const std::string& x) { s.moving_force = x == "1"; }},
      {"steps", [&](const std::string& x) { s.steps = std::stoi(x); }},
      {"every", [&](const std::string& x) { s.every = std::stoi(x); }},
      {"csv", [&](const std::string& x) { csv = x; }}};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto equals = arg.find('=');
    const auto key = keys.find(arg.substr(0, equals));
    if (equals == std::string::npos || key == keys.end())
      throw RunError("unknown argument '" + arg + "' (expected key=value)");
    key->second(arg.substr(equals + 1));
  }
  const CrossingResult r = run_crossing(s);
  if (!csv.empty()) {
    std::ofstream out(csv);
    out.precision(12);
    out << "time,position,midspan_deflection,vehicle_displacement,vehicle_acceleration,"
           "contact_force\n";
    for (std::size_t i = 0; i < r.time.size(); ++i)
      out << r.time[i] << ',' << r.position[i] << ',' << r.midspan_deflection[i] << ','
          << r.vehicle_displacement[i] << ',' << r.vehicle_acceleration[i] << ','
          << r.contact_force[i] << '\n';
  }
  std::cout.precision(10);
  std::cout << "unknowns=" << r.unknowns << "\nstructure_unknowns=" << r.structure_unknowns
            << "\nsteps=" << r.steps << "\nnewton_iterations=" << r.iterations
            << "\nstructure_factorizations=" << r.structure_factorizations
            << "\nrestarts=" << r.restarts << "\nwall_s=" << r.wall_seconds
            << "\ncpu_s=" << r.cpu_seconds << "\n";
  for (const ContactEvent& e : r.events)
    std::cout << "event=" << (e.separation ? "separation" : "contact") << ',' << e.contact << ','
              << e.time << ',' << e.position << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "railfe-moving-study: " << e.what() << "\n";
    return 2;
  }
}
