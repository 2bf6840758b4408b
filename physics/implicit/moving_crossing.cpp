#include "physics/implicit/moving_crossing.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>

#include "framework/base/error.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"
#include "framework/time/hht_integrator.hpp"
#include "framework/time/sparse_system.hpp"
#include "physics/implicit/moving_bridge_model.hpp"

namespace railfe {
namespace {

constexpr double kGravity = 9.81;

// Vehicle matrices: wheels (mass wheel_mass) first, then bodies in chains, body b sprung on wheel
// b mod wheels and joined to body b + wheels; the weight vehicle_mass·g per wheel, shared by its
// bodies (or carried by the wheel itself without bodies). `start`: static state, wheels at zero.
struct VehicleModel {
  Eigen::MatrixXd mass, stiffness;
  Eigen::VectorXd force, start;
};

VehicleModel make_vehicle(const CrossingSettings& s) {
  const int n = s.vehicle_dofs, wheels = s.wheels, bodies = n - wheels;
  if (wheels < 1 || bodies < 0)
    throw RunError("a vehicle needs at least one wheel and no fewer unknowns than wheels");
  VehicleModel v{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n),
                 Eigen::VectorXd::Zero(n)};
  auto spring = [&v](int a, int b, double k) {
    v.stiffness(a, a) += k;
    v.stiffness(b, b) += k;
    v.stiffness(a, b) -= k;
    v.stiffness(b, a) -= k;
  };
  const int per_wheel = std::max(1, bodies / wheels);
  for (int w = 0; w < wheels; ++w) {
    v.mass(w, w) = s.wheel_mass;
    v.force[w] = -kGravity * (s.wheel_mass + (bodies == 0 ? s.vehicle_mass : 0.0));
  }
  for (int b = 0; b < bodies; ++b) {
    v.mass(wheels + b, wheels + b) = s.vehicle_mass / per_wheel;
    v.force[wheels + b] = -kGravity * s.vehicle_mass / per_wheel;
    spring(wheels + b, b % wheels, s.stiffness / per_wheel);
    if (b + wheels < bodies)
      spring(wheels + b, wheels + b + wheels, 5 * s.stiffness);
  }
  if (bodies > 0)
    v.start.tail(bodies) =
        v.stiffness.bottomRightCorner(bodies, bodies).ldlt().solve(v.force.tail(bodies));
  return v;
}

Irregularity bump(const CrossingSettings& s) {
  if (s.bump_height == 0)
    return {};
  const double height = s.bump_height, length = s.bump_length, start = s.bump_start;
  return Irregularity(
      [=](double x) {
        const double r = (x - start) / length;
        return r > 0 && r < 1 ? 0.5 * height * (1 - std::cos(2 * M_PI * r)) : 0.0;
      },
      {});
}

}  // namespace

CrossingResult run_crossing(const CrossingSettings& s) {
  const BeamSection section{1.0, s.inertia, s.inertia, 2 * s.inertia, INFINITY, INFINITY};
  const BeamMaterial material{s.young, s.young / 2.6, s.mass_per_length};
  const BridgeModel bridge =
      simply_supported_bridge(s.span, s.elements, s.lines, 2.0, material, section,
                              s.lumped ? BeamMass::lumped : BeamMass::consistent);
  const long ns = static_cast<long>(bridge.n_unknowns);
  const VehicleModel model = make_vehicle(s);
  const double last_start = 2.5 * (s.wheels - 1);
  std::vector<MovingContactPoint> points;
  for (int w = 0; w < s.wheels; ++w)
    points.push_back({"wheel " + std::to_string(w + 1), ns + w, -1, last_start - 2.5 * w, s.speed,
                      bump(s), true});
  MovingContacts contacts(BeamPath(bridge.path), points);

  // The moving-force reference: the wheels' weight as consistent nodal loads, no vehicle.
  auto moving_load = [&](double t, double* f) {
    std::fill(f, f + ns, 0.0);
    for (int w = 0; w < s.wheels; ++w)
      contacts.add_point_load(contacts.position(w, t), model.force[w], f);
  };
  SparseLinearSystem structure(bridge.mass, {}, bridge.stiffness,
                               s.moving_force ? std::function<void(double, double*)>(moving_load)
                                              : std::function<void(double, double*)>());
  const int nv = s.vehicle_dofs;
  LinearDenseSystem vehicle(
      model.mass, Eigen::MatrixXd::Zero(nv, nv), model.stiffness,
      [f = model.force](double, double* out) { Eigen::Map<Eigen::VectorXd>(out, f.size()) = f; });
  CoupledSystem coupled(structure, vehicle);
  std::unique_ptr<SaddlePointSolver> saddle;
  if (s.solver == "block") {
    saddle = std::make_unique<BlockSaddlePointSolver>(coupled);
    structure.check_solutions(false);  // the block solver checks the coupled solution instead
  } else if (s.solver == "monolithic")
    saddle = std::make_unique<MonolithicSaddlePointSolver>(coupled);
  else
    throw RunError("solver '" + s.solver + "': expected block or monolithic");
  SecondOrderSystem& system = s.moving_force ? static_cast<SecondOrderSystem&>(structure) : coupled;
  HhtIntegrator integrator(NewmarkScheme::hht(s.alpha), system);
  if (!s.moving_force)
    integrator.constrain(contacts, *saddle);

  const std::size_t n = system.n_unknowns();
  std::vector<double> u(n, 0.0), v(n, 0.0), a(n, 0.0);
  if (!s.moving_force)
    for (int i = 0; i < nv; ++i)
      u[ns + i] = model.start[i];
  const double crossing = (s.span - last_start) / s.speed;
  const int steps = s.steps > 0 ? s.steps : static_cast<int>(std::ceil(crossing / s.dt - 1e-9));
  const long body = s.moving_force ? -1 : ns + (nv > s.wheels ? s.wheels : 0);

  CrossingResult result;
  auto record = [&](double t) {
    result.time.push_back(t);
    result.position.push_back(contacts.position(0, t));
    result.midspan_deflection.push_back(u[bridge.midspan_vertical]);
    result.vehicle_displacement.push_back(body >= 0 ? u[body] : 0.0);
    result.vehicle_acceleration.push_back(body >= 0 ? a[body] : 0.0);
    result.contact_force.push_back(
        s.moving_force ? -model.force[0]
                       : contacts.contact_forces(integrator.multipliers().data())[0]);
  };
  const auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  integrator.initialize(0.0, u.data(), v.data(), a.data());
  record(0.0);
  for (int step = 0; step < steps; ++step) {
    const double t = step * s.dt, h = s.steps > 0 ? s.dt : std::min(s.dt, crossing - t);
    integrator.advance(t, h, u.data(), v.data(), a.data());
    if ((step + 1) % s.every == 0 || step + 1 == steps)
      record(t + h);
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  result.events = contacts.events();
  result.unknowns = n;
  result.structure_unknowns = static_cast<std::size_t>(ns);
  result.steps = integrator.newton_statistics().steps;
  result.iterations = integrator.newton_statistics().iterations;
  result.restarts = integrator.newton_statistics().restarts;
  result.structure_factorizations = s.moving_force ? integrator.newton_statistics().factorizations
                                                   : coupled.structure_factorizations();
  return result;
}

}  // namespace railfe
