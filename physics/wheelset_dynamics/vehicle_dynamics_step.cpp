#include "physics/wheelset_dynamics/vehicle_dynamics_step.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/solvers/prescribed_saddle_point_solver.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"
#include "physics/common/profile_geometry.hpp"
#include "physics/wheelset_dynamics/vehicle_balance.hpp"
#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"
#include "physics/wheelset_dynamics/wheelset_system.hpp"

namespace railfe {

namespace {

const char* kSides[2] = {"right", "left"};

// Vertical (Q, up on the wheel) and lateral (Y, towards the track centre on the wheel) forces
// of wheel \p side (0 right, 1 left), summed over its tread and flange.
std::array<double, 2> wheel_forces(const std::array<ContactState, n_wheelset_contacts>& states,
                                   int side) {
  const int first = 2 * side;
  const double inward = side == 0 ? -1.0 : 1.0;  // the right wheel's centre side is −y
  double Q = 0, Y = 0;
  for (int k = first; k < first + 2; ++k) {
    Q -= states[k].force[2];
    Y += inward * states[k].force[1];
  }
  return {Q, Y};
}

}  // namespace

VehicleDynamicsStep::VehicleDynamicsStep(const Teuchos::ParameterList& parameters)
    : parameters_(&parameters) {}

void VehicleDynamicsStep::check(const CheckContext& context) {
  const auto& p = *parameters_;
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  geometry_ = read_profile_geometry(p, context);
  for (const char* key : {"Lateral irregularity", "Vertical irregularity"})
    function_of_x(p.get<std::string>(key), deck, context.path + "/" + key);
  if (p.get<double>("Time step") > p.get<double>("End time"))
    throw_input_error(deck, context.path + "/Time step", "is longer than End time",
                      "at most End time");
  const SectionTable sections =
      structural_sections(context.model, "the vehicle dynamics step '" + context.step_name + "'");
  model_ = std::make_unique<DenseStructuralModel>(mesh, sections, deck);

  const std::string set_path = context.path + "/Wheelsets";
  const NodeSet& set = mesh.node_set(p.get<std::string>("Wheelsets"), deck, set_path);
  if (set.nodes.empty())
    throw_input_error(deck, set_path, "names an empty node set", "the wheelset centres' set");
  wheelsets_ = set.nodes;
  std::sort(wheelsets_.begin(), wheelsets_.end(),
            [&mesh](GlobalIndex a, GlobalIndex b) { return mesh.node(a)[0] > mesh.node(b)[0]; });
  for (GlobalIndex node : wheelsets_)
    if (model_->unknown_of(node) < 0)
      throw_input_error(deck, set_path,
                        "holds node " + std::to_string(node + 1) +
                            ", which a rigid link carries; a wheelset's motions need a node of "
                            "its own",
                        "the wheelset centres (the masters of their links)");
  points_.clear();
  point_names_.clear();
  for (const std::string& name : p.get<Teuchos::Array<std::string>>("Measuring points")) {
    const NodeSet& points = mesh.node_set(name, deck, context.path + "/Measuring points");
    for (std::size_t i = 0; i < points.nodes.size(); ++i) {
      points_.push_back(points.nodes[i]);
      point_names_.push_back(points.nodes.size() == 1 ? name : name + "_" + std::to_string(i + 1));
    }
  }
}

void VehicleDynamicsStep::run(StepContext& context) {
  const auto& p = *parameters_;
  const bool root = context.model.comm().is_root();
  const std::string section = "Step " + context.step_name + " (vehicle dynamics)";
  const auto wall_start = std::chrono::steady_clock::now();
  const Mesh& mesh = context.model.mesh();
  const double V = p.get<double>("Speed");
  const Eigen::VectorXd weight =
      model_->gravity_load(Eigen::Vector3d(0, 0, p.get<double>("Gravity")));
  VehicleSystem system(*model_, wheelsets_, geometry_, contact_settings(p), V, weight);
  const int n_wheelsets = system.n_wheelsets();
  const auto& contact_list = p.sublist("Contact");
  if (contact_list.get<bool>("Lookup table")) {
    // Rows every 0.1 mm, as the wheelset-on-track scene's default table.
    const double range = contact_list.get<double>("Table half range");
    const auto rows = static_cast<int>(std::lround(2 * range / 1e-4)) + 1;
    auto table = std::make_shared<const ContactTable>(*geometry_, range, rows);
    for (int w = 0; w < n_wheelsets; ++w)
      for (int k = 0; k < n_wheelset_contacts; ++k)
        system.wheelset(w).contact(k).use_table(table);
  }
  std::vector<RailedWheelset> railed;
  for (int w = 0; w < n_wheelsets; ++w)
    railed.push_back({mesh.node(wheelsets_[w])[0], system.wheelset(w).unknowns().nodes});
  RigidRails rails(function_of_x(p.get<std::string>("Lateral irregularity"), context.source(),
                                 context.path + "/Lateral irregularity"),
                   function_of_x(p.get<std::string>("Vertical irregularity"), context.source(),
                                 context.path + "/Vertical irregularity"),
                   p.get<double>("Start"), V, railed);

  // The internal nodes on the rails, then the static balance.
  const std::size_t n = system.n_unknowns();
  std::vector<double> u(n, 0.0), v(n, 0.0), a(n, 0.0);
  ConstraintRows rows;
  rails.rows_at(0, rows);
  for (std::size_t r = 0; r < rows.size(); ++r)
    u[rows.columns[rows.offsets[r]]] = rows.rhs[r] / rows.values[rows.offsets[r]];
  VehicleBalance balance;
  try {
    balance = balance_vehicle(system, *geometry_, u);
  } catch (const RunError& error) {
    throw RunError(context.path + ": " + error.what());
  }
  context.summary.add(section, "weight", balance.weight, "N");
  context.summary.add(section, "static balance iterations", balance.iterations);
  std::vector<std::array<ContactState, n_wheelset_contacts>> states(n_wheelsets);
  auto evaluate_states = [&]() {
    for (int w = 0; w < n_wheelsets; ++w)
      states[w] = system.wheelset(w).states(u.data(), v.data());
  };
  evaluate_states();
  {
    CsvWriter file(context.output.staging_path(context.step_name + "_static.csv"),
                   {"wheelset", "wheel", "Q_N", "Y_N", "contact_angle_rad", "rolling_radius_m"},
                   root);
    double total = 0, lightest = 1e300, heaviest = 0;
    for (int w = 0; w < n_wheelsets; ++w)
      for (int side = 0; side < 2; ++side) {
        const auto f = wheel_forces(states[w], side);
        const ContactState& tread = states[w][2 * side];
        file.write_row({std::to_string(w + 1), kSides[side], CsvWriter::format(f[0]),
                        CsvWriter::format(f[1]), CsvWriter::format(tread.point.contact_angle),
                        CsvWriter::format(tread.point.rolling_radius)});
        total += f[0];
        lightest = std::min(lightest, f[0]);
        heaviest = std::max(heaviest, f[0]);
      }
    file.write_row({"total", "", CsvWriter::format(total), "", "", ""});
    file.write_row({"weight", "", CsvWriter::format(balance.weight), "", "", ""});
    context.summary.add(section, "static wheel load, lightest", lightest, "N");
    context.summary.add(section, "static wheel load, heaviest", heaviest, "N");
    context.summary.add(section, "static wheel loads, total", total, "N");
  }

  // Rolling: each wheelset spins without longitudinal creep at its mean tread radius.
  for (int w = 0; w < n_wheelsets; ++w) {
    const double radius =
        0.5 * (states[w][0].point.rolling_radius + states[w][2].point.rolling_radius);
    system.wheelset(w).set_spin(-V / radius);
    system.wheelset(w).set_rolling(true);
  }
  NewtonSettings newton;
  newton.max_iterations = p.get<int>("Newton iterations");
  newton.line_search = p.get<bool>("Line search");
  newton.residual_relative = newton.increment_relative = p.get<double>("Newton tolerance");
  PrescribedSaddlePointSolver saddle(system);
  NewtonStepSolver solver(system, newton);
  solver.constrain(&rails, &saddle);
  {
    // The internal nodes move with the rails' rates.
    std::vector<double> rate(rows.size()), unused(rows.size());
    rails.rates(0, u.data(), v.data(), rate.size(), rate.data(), unused.data());
    for (std::size_t r = 0; r < rows.size(); ++r)
      v[rows.columns[rows.offsets[r]]] = rate[r];
  }
  solver.initial_acceleration(0, u.data(), v.data(), a.data());
  NewmarkIntegrator integrator(NewmarkScheme::hht(p.get<double>("Alpha")), n);

  std::vector<std::string> wheelset_columns{"time_s", "iterations"};
  std::vector<std::string> wheel_columns{"time_s"};
  for (int w = 0; w < n_wheelsets; ++w) {
    const std::string name = "w" + std::to_string(w + 1) + "_";
    for (const char* q : {"y_m", "z_m", "roll_rad", "yaw_rad", "vy_m_per_s", "ay_m_per_s2"})
      wheelset_columns.push_back(name + q);
    for (const char* side : kSides)
      for (const char* q : {"Q_N", "Y_N", "Y_over_Q", "flange"})
        wheel_columns.push_back(name + side + "_" + q);
  }
  std::vector<std::string> point_columns{"time_s"};
  for (const std::string& name : point_names_)
    for (const char* q : {"y_m", "z_m", "ay_m_per_s2", "az_m_per_s2"})
      point_columns.push_back(name + "_" + q);
  CsvWriter wheelset_file(context.output.staging_path(context.step_name + "_wheelsets.csv"),
                          wheelset_columns, root);
  CsvWriter wheel_file(context.output.staging_path(context.step_name + "_wheels.csv"),
                       wheel_columns, root);
  CsvWriter point_file(context.output.staging_path(context.step_name + "_points.csv"),
                       point_columns, root);
  CsvWriter events(context.output.staging_path(context.step_name + "_contact_events.csv"),
                   {"time_s", "wheelset", "contact", "event", "N_N"}, root);
  std::vector<Eigen::MatrixXd> point_motion;
  for (GlobalIndex node : points_)
    point_motion.push_back(model_->node_motion(node));
  const Eigen::Index n_model = system.n_model_unknowns();
  auto write_rows = [&](double time, int iterations) {
    std::vector<double> row{time, static_cast<double>(iterations)};
    for (int w = 0; w < n_wheelsets; ++w) {
      const std::size_t o = system.wheelset(w).unknowns().wheelset;
      row.insert(row.end(), {u[o + 1], u[o + 2], u[o + 3], u[o + 5], v[o + 1], a[o + 1]});
    }
    wheelset_file.write_row(row);
    row.assign(1, time);
    for (int w = 0; w < n_wheelsets; ++w)
      for (int side = 0; side < 2; ++side) {
        const auto f = wheel_forces(states[w], side);
        row.insert(row.end(), {f[0], f[1], f[0] > 0 ? f[1] / f[0] : 0.0,
                               states[w][2 * side + 1].active ? 1.0 : 0.0});
      }
    wheel_file.write_row(row);
    row.assign(1, time);
    const Eigen::Map<const Eigen::VectorXd> uu(u.data(), n_model), aa(a.data(), n_model);
    for (const Eigen::MatrixXd& motion : point_motion) {
      const Eigen::VectorXd du = motion * uu, acceleration = motion * aa;
      row.insert(row.end(), {du(1), du(2), acceleration(1), acceleration(2)});
    }
    point_file.write_row(row);
  };

  const double end = p.get<double>("End time"), dt = p.get<double>("Time step");
  const double interval = p.get<double>("History interval");
  const long n_steps = std::lround(std::ceil(end / dt - 1e-9));
  write_rows(0, 0);
  std::vector<std::array<bool, n_wheelset_contacts>> active(n_wheelsets);
  for (int w = 0; w < n_wheelsets; ++w)
    for (int k = 0; k < n_wheelset_contacts; ++k)
      active[w][k] = states[w][k].active;
  const char* contact_names[n_wheelset_contacts] = {"right_tread", "right_flange", "left_tread",
                                                    "left_flange"};
  double next_output = interval;
  std::size_t n_events = 0;
  double peak_Y_over_Q = 0;
  auto progress = context.progress("time steps", static_cast<double>(n_steps));
  double time = 0;
  for (long step = 0; step < n_steps; ++step) {
    try {
      integrator.step(time, dt, solver, u.data(), v.data(), a.data());
    } catch (const StepNotConverged& error) {
      std::ostringstream message;
      message << context.path << ": Newton did not converge in the step from t = " << error.time
              << " s (Δt " << error.step << " s): " << error.what()
              << "; the run stops here rather than go on with an unbalanced state";
      throw RunError(message.str());
    }
    time = (step + 1) * dt;
    evaluate_states();
    for (int w = 0; w < n_wheelsets; ++w) {
      for (int k = 0; k < n_wheelset_contacts; ++k)
        if (states[w][k].active != active[w][k]) {
          active[w][k] = states[w][k].active;
          ++n_events;
          events.write_row({CsvWriter::format(time), std::to_string(w + 1), contact_names[k],
                            active[w][k] ? (k % 2 ? "flange contact" : "contact") : "separation",
                            CsvWriter::format(states[w][k].hertz.load)});
        }
      for (int side = 0; side < 2; ++side) {
        const auto f = wheel_forces(states[w], side);
        if (f[0] > 0)
          peak_Y_over_Q = std::max(peak_Y_over_Q, std::abs(f[1] / f[0]));
      }
    }
    if (time >= next_output - 1e-9 * dt || step + 1 == n_steps) {
      write_rows(time, solver.statistics().last_iterations);
      next_output += interval;
    }
    progress.update(static_cast<double>(step + 1));
  }
  progress.finish();

  const NewtonStatistics& statistics = solver.statistics();
  context.summary.add(section, "wheelsets", static_cast<double>(n_wheelsets));
  context.summary.add(section, "unknowns (vehicle, internal nodes)", static_cast<double>(n));
  context.summary.add(section, "steps", static_cast<double>(statistics.steps));
  context.summary.add(section, "Newton iterations per step",
                      statistics.steps ? double(statistics.iterations) / statistics.steps : 0.0);
  context.summary.add(section, "most Newton iterations in a step",
                      static_cast<double>(statistics.most_iterations));
  context.summary.add(section, "wall time per Newton iteration (solve only)",
                      statistics.iterations ? statistics.seconds / statistics.iterations : 0.0,
                      "s");
  context.summary.add(section, "contact events", static_cast<double>(n_events));
  context.summary.add(section, "peak |Y/Q|", peak_Y_over_Q);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  context.summary.add(section, "wall time", seconds, "s");
  context.summary.add(section, "wall time per step", seconds / std::max(1L, n_steps), "s");
  context.summary.add(section, "simulated time per wall time", end / seconds);
}

}  // namespace railfe
