#include "physics/wheelset_dynamics/vehicle_dynamics_step.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/solvers/prescribed_saddle_point_solver.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/common/profile_geometry.hpp"
#include "physics/common/structure_deviation.hpp"
#include "physics/wheelset_dynamics/time_stepping.hpp"
#include "physics/wheelset_dynamics/vehicle_balance.hpp"
#include "physics/wheelset_dynamics/vehicle_recorder.hpp"
#include "physics/wheelset_dynamics/vehicle_structure.hpp"
#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"
#include "physics/wheelset_dynamics/wheelset_system.hpp"

namespace railfe {

namespace {

// The deck's Structure deviation sublist.
StructureDeviationSettings deviation_settings(const Teuchos::ParameterList& step) {
  const auto& d = step.sublist("Structure deviation");
  StructureDeviationSettings settings;
  const std::string shape = d.get<std::string>("Shape");
  settings.shape = shape == "bending"       ? DeviationShape::bending
                   : shape == "translation" ? DeviationShape::translation
                                            : DeviationShape::none;
  if (settings.shape == DeviationShape::none)
    return settings;
  settings.start = d.get<double>("Start");
  settings.span = d.get<double>("Span");
  settings.amplitude = d.get<double>("Amplitude");
  settings.pad_stiffness = d.get<double>("Pad stiffness");
  settings.rail_inertia = d.get<double>("Rail lateral inertia");
  settings.rail_modulus = d.get<double>("Rail Young's modulus");
  return settings;
}

}  // namespace

VehicleDynamicsStep::VehicleDynamicsStep(const Teuchos::ParameterList& parameters)
    : parameters_(&parameters) {}

void VehicleDynamicsStep::check(const CheckContext& context) {
  const auto& p = *parameters_;
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  geometry_ = read_profile_geometry(p, context);
  check_contact_parameters(*parameters_, context.source(), context.path);
  check_time_stepping_parameters(p, deck, context.path);
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
  // The contact element places each wheel's profile about the wheelset centre with the track's
  // nominal rolling radius: a mesh whose wheelset centres sit at another height would give the
  // suspensions the wrong levers.
  const double radius = geometry_->wheelset().nominal_radius;
  for (GlobalIndex node : wheelsets_) {
    const double height = -mesh.node(node)[2];
    std::ostringstream what;
    what << "(" << radius << " m) differs from the height of wheelset node " << node + 1
         << " above the rails (" << height
         << " m; the mesh is in track axes, z down), which the suspensions' levers are measured "
            "from";
    if (std::abs(height - radius) > 1e-3)
      throw_input_error(deck, context.path + "/Track/Nominal radius", what.str(),
                        "the same radius in both (Mesh/Vehicle/Wheel radius for the vehicle "
                        "generator)");
  }
  for (GlobalIndex node : wheelsets_)
    if (model_->unknown_of(node) < 0)
      throw_input_error(deck, set_path,
                        "holds node " + std::to_string(node + 1) +
                            ", which a rigid link carries; a wheelset's motions need a node of "
                            "its own",
                        "the wheelset centres (the masters of their links)");
  const std::string reference = p.get<std::string>("Compare with step");
  if (!reference.empty()) {
    const auto& steps = context.model.deck().parameters->sublist("Steps");
    bool earlier = false;
    for (auto it = steps.begin(); it != steps.end(); ++it) {
      const std::string name = steps.name(it);
      if (name == context.step_name)
        break;
      if (name == reference && steps.isSublist(name) &&
          steps.sublist(name).get<std::string>("Module") == "vehicle dynamics")
        earlier = true;
    }
    if (!earlier)
      throw_input_error(deck, context.path + "/Compare with step",
                        "'" + reference + "' is not a vehicle dynamics step before this one",
                        "the name of an earlier vehicle dynamics step of the deck");
    if (names_sweep_cases(steps.sublist(reference)))
      throw_input_error(deck, context.path + "/Compare with step",
                        "'" + reference + "' is a sweep, whose cases have histories of their own",
                        "an earlier vehicle dynamics step without a Sweep");
  }
  const double start = p.get<double>("Start");
  const VehicleCase base{p.get<double>("Speed"), p.get<double>("End time"), deviation_settings(p)};
  cases_ = sweep_cases(p, base, deck, context.path);
  if (!cases_.empty() && !reference.empty())
    throw_input_error(deck, context.path + "/Compare with step",
                      "is given with a Sweep, whose cases draw no chart of their own to compare",
                      "no Compare with step in a sweep (its chart is <step>_sweep.png)");
  girders_.reset();
  const auto& structure = p.sublist("Structure");
  if (structure_is_girders(structure)) {
    const std::string path = context.path + "/Structure";
    girders_ = girder_layout(structure, deck, path);
    // The girders start at rest and unloaded: the vehicle must start before them.
    for (GlobalIndex node : wheelsets_)
      if (start + mesh.node(node)[0] >= girders_->start) {
        std::ostringstream what;
        what << "(" << girders_->start << " m) is not ahead of wheelset node " << node + 1
             << ", at s = " << start + mesh.node(node)[0]
             << " m at t = 0: the girders start at rest and unloaded, so the vehicle must "
                "start before them";
        throw_input_error(deck, path + "/Start", what.str(),
                          "a Start beyond every wheelset's s at t = 0 (Start + its x)");
      }
    if (base.deviation.shape != DeviationShape::none &&
        std::abs(girders_->span - base.deviation.span) > 1e-9 * base.deviation.span)
      throw_input_error(deck, path + "/Span",
                        "differs from Structure deviation/Span: the deviation displaces the "
                        "girders' piers",
                        "the deviation's Span (" + CsvWriter::format(base.deviation.span) + " m)");
    for (const VehicleCase& c : cases_.empty() ? std::vector<VehicleCase>{base} : cases_)
      check_deviation_on_girders(*girders_, c.deviation, deck, path);
  }
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
  if (girders_ && p.get<double>("Alpha") > -0.05) {
    // Trapezoidal-like steps put no damping on the Nyquist ringing of the moving ties to the
    // girder: Newton needs more iterations step by step until it fails (docs/verification.md).
    const std::string warning =
        "HHT alpha " + CsvWriter::format(p.get<double>("Alpha")) +
        " over girders: the moving ties to the girder ring at the step's Nyquist frequency "
        "without numerical damping (Newton slows, then may fail); -0.1 damps it";
    context.summary.add("Step " + context.step_name + " (vehicle dynamics)", "warning", warning);
    if (context.model.comm().is_root())
      std::cerr << "warning: " << context.path << ": " << warning << "\n";
  }
  if (cases_.empty()) {
    const VehicleCase base{p.get<double>("Speed"), p.get<double>("End time"),
                           deviation_settings(p)};
    run_case(context, base, context.model.comm().is_root(), true);
    return;
  }
  run_sweep(
      context, cases_,
      [this](StepContext& case_context, const VehicleCase& c) {
        return run_case(case_context, c, true, false);
      },
      "Step " + context.step_name + " (vehicle dynamics)");
}

CaseOutcome VehicleDynamicsStep::run_case(StepContext& context, const VehicleCase& c, bool writes,
                                          bool alone) {
  const auto& p = *parameters_;
  const std::string section = "Step " + context.step_name + " (vehicle dynamics)";
  const auto wall_start = std::chrono::steady_clock::now();
  const Mesh& mesh = context.model.mesh();
  const double V = c.speed;
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
  // The rails' lateral offset: the deck's irregularity plus the structure's deviation.
  const auto irregularity = function_of_x(p.get<std::string>("Lateral irregularity"),
                                          context.source(), context.path + "/Lateral irregularity");
  const auto deviation = std::make_shared<StructureDeviation>(c.deviation);
  const std::function<double(double)> lateral = [irregularity, deviation](double s) {
    return (irregularity ? irregularity(s) : 0.0) + deviation->rail(s);
  };
  const auto vertical = function_of_x(p.get<std::string>("Vertical irregularity"), context.source(),
                                      context.path + "/Vertical irregularity");
  const double start = p.get<double>("Start");
  const double end = c.end_time, dt = p.get<double>("Time step");

  // The structure: none (rigid rails) or girders coupled to the vehicle, whose unknowns then
  // follow the girders'.
  std::unique_ptr<VehicleStructure> structure;
  std::size_t offset = 0;
  std::vector<RailedWheelset> railed;
  if (girders_) {
    GirderLayout layout = *girders_;
    if (c.deviation.shape != DeviationShape::none)
      layout.span = c.deviation.span;  // a sweep's span
    structure = std::make_unique<VehicleStructure>(layout, *geometry_, system);
    offset = structure->offset();
  }
  for (int w = 0; w < n_wheelsets; ++w)
    railed.push_back({mesh.node(wheelsets_[w])[0], system.wheelset(w).unknowns().nodes});
  std::unique_ptr<ConstraintSet> rails;
  BeamRails* beam_rails = nullptr;
  if (structure) {
    auto ties = std::make_unique<BeamRails>(structure->girders(), offset, lateral, vertical, start,
                                            V, railed);
    beam_rails = ties.get();
    rails = std::move(ties);
  } else {
    rails = std::make_unique<RigidRails>(lateral, vertical, start, V, railed);
  }
  SecondOrderSystem& whole =
      structure ? structure->system() : static_cast<SecondOrderSystem&>(system);
  if (c.deviation.shape != DeviationShape::none) {
    // The track's lateral offset along the stretch the vehicle runs over, for charts.
    CsvWriter file(context.output.staging_path(context.step_name + "_deviation.csv"),
                   {"s_m", "structure_m", "rail_m"}, writes);
    double first = start, last = start + V * end;
    for (const RailedWheelset& r : railed) {
      first = std::min(first, start + r.position);
      last = std::max(last, start + r.position + V * end);
    }
    for (double s = first; s <= last + 1e-9; s += 0.05)
      file.write_row({s, deviation->structure(s), deviation->rail(s)});
  }

  // The internal nodes on the rails (the girders start at rest, unloaded: the vehicle starts
  // before them), then the static balance of the vehicle.
  const std::size_t n = whole.n_unknowns();
  std::vector<double> u(n, 0.0), v(n, 0.0), a(n, 0.0);
  ConstraintRows rows;
  rails->rows_at(0, rows);
  for (std::size_t r = 0; r < rows.size(); ++r)
    u[rows.columns[rows.offsets[r]]] = rows.rhs[r] / rows.values[rows.offsets[r]];
  const auto vehicle_part = [offset](std::vector<double>& x) { return x.data() + offset; };
  std::vector<double> uv(u.begin() + static_cast<long>(offset), u.end());
  VehicleBalance balance;
  try {
    balance = balance_vehicle(system, *geometry_, uv);
  } catch (const RunError& error) {
    throw RunError(context.path + ": " + error.what());
  }
  std::copy(uv.begin(), uv.end(), vehicle_part(u));
  context.summary.add(section, "weight", balance.weight, "N");
  context.summary.add(section, "static balance iterations", balance.iterations);
  std::vector<std::array<ContactState, n_wheelset_contacts>> states(n_wheelsets);
  auto evaluate_states = [&]() {
    for (int w = 0; w < n_wheelsets; ++w) {
      states[w] = system.wheelset(w).states(vehicle_part(u), vehicle_part(v));
      if (beam_rails)
        beam_rails->set_levers(states[w], w);
    }
  };
  evaluate_states();
  std::vector<std::array<double, 2>> static_loads(n_wheelsets);
  write_static_loads(context, section, states, static_loads, writes);

  // Rolling: each wheelset spins without longitudinal creep at its mean tread radius.
  for (int w = 0; w < n_wheelsets; ++w) {
    const double radius =
        0.5 * (states[w][0].point.rolling_radius + states[w][2].point.rolling_radius);
    system.wheelset(w).set_spin(-V / radius);
    system.wheelset(w).set_rolling(true);
  }
  const NewtonSettings newton = newton_settings(p);
  std::unique_ptr<SaddlePointSolver> saddle;
  if (structure)
    saddle = std::make_unique<BlockSaddlePointSolver>(structure->coupled());
  else
    saddle = std::make_unique<PrescribedSaddlePointSolver>(system);
  NewtonStepSolver solver(whole, newton);
  solver.constrain(rails.get(), saddle.get());
  {
    // The internal nodes move with the rails' rates.
    std::vector<double> rate(rows.size()), unused(rows.size());
    rails->rates(0, u.data(), v.data(), rate.size(), rate.data(), unused.data());
    for (std::size_t r = 0; r < rows.size(); ++r)
      v[rows.columns[rows.offsets[r]]] = rate[r];
  }
  solver.initial_acceleration(0, u.data(), v.data(), a.data());
  NewmarkIntegrator integrator(NewmarkScheme::hht(p.get<double>("Alpha")), n);

  std::vector<Eigen::MatrixXd> point_motion;
  for (GlobalIndex node : points_)
    point_motion.push_back(model_->node_motion(node));
  VehicleRecorder recorder(context, system, point_names_, point_motion, static_loads, writes);
  const double window = p.get<double>("Y/Q window");
  recorder.set_sliding_mean(static_cast<int>(std::lround(window / (V * dt))), window);
  std::unique_ptr<GirderRecorder> girder_recorder;
  if (structure)
    girder_recorder = std::make_unique<GirderRecorder>(context, *structure, writes);
  const double interval = p.get<double>("History interval");
  const long n_steps = std::lround(std::ceil(end / dt - 1e-9));
  const auto record = [&](double time, int iterations, bool row) {
    recorder.record(time, iterations, vehicle_part(u), vehicle_part(v), vehicle_part(a), states,
                    row);
    if (girder_recorder)
      girder_recorder->record(time, u.data(), row);
  };
  record(0, 0, true);
  double next_output = interval;
  std::vector<double> airborne_since(n_wheelsets, 1e300);
  auto progress = context.progress("time steps", static_cast<double>(n_steps));
  const auto stepping_start = std::chrono::steady_clock::now();
  double time = 0;
  CaseOutcome outcome;
  for (long step = 0; step < n_steps; ++step) {
    try {
      step_or_stop(integrator, time, dt, solver, u.data(), v.data(), a.data(), context.path);
    } catch (const RunError& error) {
      if (alone)  // a run of its own fails; a sweep's case reports it and the sweep goes on
        throw;
      outcome.stop = "Newton failed";
      outcome.stopped_at = time;
      outcome.message = error.what();
      break;
    }
    time = (step + 1) * dt;
    evaluate_states();
    // A wheelset with no wheel touching for 50 ms has left the rails (a climb or a jump over):
    // nothing computed after that means anything, so the run ends there, reported.
    int derailed = -1;
    for (int w = 0; w < n_wheelsets; ++w) {
      const bool airborne = std::none_of(states[w].begin(), states[w].end(),
                                         [](const ContactState& c) { return c.active; });
      airborne_since[w] = airborne ? std::min(airborne_since[w], time) : 1e300;
      if (time - airborne_since[w] >= 0.05 - 1e-9 * dt)
        derailed = w;
    }
    const bool row = time >= next_output - 1e-9 * dt || step + 1 == n_steps || derailed >= 0;
    record(time, solver.statistics().last_iterations, row);
    if (row)
      next_output += interval;
    progress.update(static_cast<double>(step + 1));
    if (derailed >= 0) {
      context.summary.add(section,
                          "wheelset " + std::to_string(derailed + 1) + " left the rails at",
                          airborne_since[derailed], "s");
      outcome.stop = "wheelset " + std::to_string(derailed + 1) + " left the rails";
      outcome.stopped_at = airborne_since[derailed];
      if (writes && alone)
        std::cerr << "warning: " << context.path << ": wheelset " << derailed + 1
                  << " left the rails at t = " << airborne_since[derailed]
                  << " s (no wheel touching for 50 ms); the run ends at t = " << time << " s\n";
      break;
    }
  }
  progress.finish();
  const double stepping =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - stepping_start).count();
  recorder.finish(time, context.summary, section);
  if (girder_recorder)
    girder_recorder->finish(context.summary, section);
  if (alone && p.get<bool>("Chart")) {
    const std::string reference = p.get<std::string>("Compare with step");
    const auto path = [&](const char* name) {
      return context.output.staging_path(context.step_name + name);
    };
    const auto reference_file = [&](const char* name) {
      return reference.empty() ? std::string() : context.output.staged_path_of(reference + name);
    };
    draw_chart(
        context, section, "vehicle_dynamics_chart.py",
        {path("_wheelsets.csv"), path("_wheels.csv"), path("_points.csv"),
         path("_flange_impacts.csv"),
         c.deviation.shape != DeviationShape::none ? path("_deviation.csv") : "-",
         CsvWriter::format(V), CsvWriter::format(start), CsvWriter::format(railed[0].position),
         path("_chart.png"), context.step_name, reference_file("_wheelsets.csv"),
         reference_file("_wheels.csv"), reference_file("_points.csv"), reference});
  }

  const NewtonStatistics& statistics = solver.statistics();
  std::size_t jumps = 0, offline = 0;
  for (int w = 0; w < n_wheelsets; ++w)
    for (int k = 0; k < n_wheelset_contacts; ++k) {
      jumps += system.wheelset(w).contact(k).table_jumps();
      offline += system.wheelset(w).contact(k).offline_points();
    }
  context.summary.add(section, "contact points taken from the lookup table (jumps)",
                      static_cast<double>(jumps));
  if (contact_settings(p).offline_table)
    context.summary.add(section, "contact points from the offline table",
                        static_cast<double>(offline));
  context.summary.add(section, "wheelsets", static_cast<double>(n_wheelsets));
  context.summary.add(section,
                      structure ? "unknowns (girders, vehicle, internal nodes)"
                                : "unknowns (vehicle, internal nodes)",
                      static_cast<double>(n));
  add_newton_summary(context.summary, section, statistics);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  context.summary.add(section, "wall time", seconds, "s");
  context.summary.add(section, "wall time per step", seconds / std::max(1L, n_steps), "s");
  context.summary.add(section, "wall time of the time steps (with their output)", stepping, "s");
  context.summary.add(section, "simulated time per wall time of the time steps",
                      time / std::max(stepping, 1e-9));
  return outcome;
}

void VehicleDynamicsStep::write_static_loads(
    StepContext& context, const std::string& section,
    const std::vector<std::array<ContactState, n_wheelset_contacts>>& states,
    std::vector<std::array<double, 2>>& loads, bool writes) const {
  CsvWriter file(context.output.staging_path(context.step_name + "_static.csv"),
                 {"wheelset", "wheel", "Q_N", "Y_N", "contact_angle_rad", "rolling_radius_m"},
                 writes);
  const char* sides[2] = {"right", "left"};
  double total = 0, lightest = 1e300, heaviest = 0;
  for (std::size_t w = 0; w < states.size(); ++w)
    for (int side = 0; side < 2; ++side) {
      const auto f = wheel_forces(states[w], side);
      const ContactState& tread = states[w][2 * side];
      file.write_row({std::to_string(w + 1), sides[side], CsvWriter::format(f[0]),
                      CsvWriter::format(f[1]), CsvWriter::format(tread.point.contact_angle),
                      CsvWriter::format(tread.point.rolling_radius)});
      loads[w][side] = f[0];
      total += f[0];
      lightest = std::min(lightest, f[0]);
      heaviest = std::max(heaviest, f[0]);
    }
  context.summary.add(section, "static wheel load, lightest", lightest, "N");
  context.summary.add(section, "static wheel load, heaviest", heaviest, "N");
  context.summary.add(section, "static wheel loads, total", total, "N");
}

}  // namespace railfe
