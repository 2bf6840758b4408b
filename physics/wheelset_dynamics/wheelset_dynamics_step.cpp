#include "physics/wheelset_dynamics/wheelset_dynamics_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/time/newmark.hpp"
#include "framework/time/newton_step.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/common/profile_geometry.hpp"
#include "physics/wheelset_dynamics/time_stepping.hpp"
#include "physics/wheelset_dynamics/wheelset_contact_deck.hpp"
#include "physics/wheelset_dynamics/wheelset_oscillation.hpp"
#include "physics/wheelset_dynamics/wheelset_track.hpp"

namespace railfe {

WheelsetDynamicsStep::WheelsetDynamicsStep(const Teuchos::ParameterList& parameters)
    : parameters_(&parameters) {}

void WheelsetDynamicsStep::check(const CheckContext& context) {
  geometry_ = read_profile_geometry(*parameters_, context);
  check_contact_parameters(*parameters_, context.source(), context.path);
  check_time_stepping_parameters(*parameters_, context.source(), context.path);
  const std::string force = parameters_->get<std::string>("Lateral force");
  if (!force.empty())
    Expression(force, context.source(), context.path + "/Lateral force");
  try {
    WheelRailContact(geometry_, TrackSide::right, false, contact_settings(*parameters_));
  } catch (const std::invalid_argument& error) {
    throw_input_error(context.source(), context.path + "/Contact/Creep theory", error.what(),
                      "Poisson's ratio 0.3 with the table, or another theory");
  }
  const auto& rails = parameters_->sublist("Rails");
  if (rails.get<std::string>("Model") == "springs")
    rail_spring_layout(rails, context.source(), context.path + "/Rails");
  if (rails.get<std::string>("Model") == "beams") {
    const std::string path = context.path + "/Rails";
    const RailBeamLayout layout = rail_beam_layout(rails, context.source(), path);
    const double from = parameters_->get<double>("Start");
    const double to =
        from + parameters_->get<double>("Speed") * parameters_->get<double>("End time");
    if (from < 0 || to > layout.length) {
      std::ostringstream what;
      what << "(" << layout.length << " m from s = 0) does not hold the run: the wheelset goes "
           << "from s = " << from << " m (Start) to " << to << " m";
      throw_input_error(context.source(), path + "/Length", what.str(),
                        "a Length that holds Start and Start + Speed × End time, best with a few "
                        "metres to spare at each end");
    }
  }
  // The frame's yaw acts only through the longitudinal springs, which hold the yaw.
  const auto& suspension = parameters_->sublist("Suspension");
  if (suspension.get<double>("Frame yaw") != 0 &&
      suspension.get<Teuchos::Array<double>>("Stiffness")[0] <= 0)
    throw_input_error(context.source(), context.path + "/Suspension/Frame yaw",
                      "would be ignored: without longitudinal axle-box springs (Stiffness[0] = 0) "
                      "nothing holds the wheelset at that yaw",
                      "0, or a longitudinal Stiffness > 0");
}

void WheelsetDynamicsStep::run(StepContext& context) {
  const auto& p = *parameters_;
  const bool root = context.model.comm().is_root();
  const std::string section = "Step " + context.step_name + " (wheelset dynamics)";
  const auto wall_start = std::chrono::steady_clock::now();
  const double V = p.get<double>("Speed");
  const auto& w = p.sublist("Wheelset");
  WheelsetBody body;
  body.mass = w.get<double>("Mass");
  body.roll_inertia = w.get<double>("Roll inertia");
  body.spin_inertia = w.get<double>("Spin inertia");
  body.yaw_inertia = w.get<double>("Yaw inertia");
  body.axle_load = w.get<double>("Axle load");
  body.gravity = w.get<double>("Gravity");
  body.cant = w.get<double>("Cant");
  const auto& s = p.sublist("Suspension");
  AxleBoxSuspension suspension;
  const auto stiffness = s.get<Teuchos::Array<double>>("Stiffness");
  const auto damping = s.get<Teuchos::Array<double>>("Damping");
  for (int i = 0; i < 3; ++i) {
    suspension.stiffness[i] = stiffness[i];
    suspension.damping[i] = damping[i];
  }
  suspension.half_spacing = s.get<double>("Half spacing");
  suspension.frame_yaw = s.get<double>("Frame yaw");
  const std::string force_text = p.get<std::string>("Lateral force");
  if (!force_text.empty()) {
    auto force =
        std::make_shared<Expression>(force_text, context.source(), context.path + "/Lateral force");
    body.lateral_force = [force](double t) { return (*force)(0, 0, 0, t); };
  }
  WheelsetSystem system(geometry_, contact_settings(p), body, suspension, V, 0.0);
  const auto& contact_list = p.sublist("Contact");
  if (contact_list.get<bool>("Lookup table")) {
    // Rows every 0.1 mm, as the wheelset-on-track scene's default table.
    const double range = contact_list.get<double>("Table half range");
    const auto rows = static_cast<int>(std::lround(2 * range / 1e-4)) + 1;
    auto table = std::make_shared<const ContactTable>(*geometry_, range, rows);
    for (int k = 0; k < n_wheelset_contacts; ++k)
      system.contact(k).use_table(table);
  }
  WheelsetTrack track(p.sublist("Rails"), context.source(), context.path + "/Rails", *geometry_,
                      system,
                      function_of_x(p.get<std::string>("Lateral irregularity"), context.source(),
                                    context.path + "/Lateral irregularity"),
                      function_of_x(p.get<std::string>("Vertical irregularity"), context.source(),
                                    context.path + "/Vertical irregularity"),
                      p.get<double>("Start"), V);
  const std::size_t o = track.offset();  // the wheelset's first unknown

  // Static balance at the initial pose, the internal nodes on the rails.
  std::vector<double> u(o + n_wheelset_unknowns, 0.0), v(u.size(), 0.0), a(u.size(), 0.0);
  const auto offset = track.offsets(0);
  u[o + 1] = p.get<double>("Initial lateral shift") + offset[0];
  u[o + 5] = p.get<double>("Initial yaw");
  WheelsetBalance balance;
  try {
    balance = track.balance(*geometry_, u);
  } catch (const RunError& error) {
    throw RunError(context.path + ": " + error.what());
  }
  auto states = system.contact_states(u.data() + o, v.data() + o);
  track.accept(states);
  const auto right = wheel_forces(states, 0), left = wheel_forces(states, 1);
  context.summary.add(section, "static load right wheel", right[0], "N");
  context.summary.add(section, "static load left wheel", left[0], "N");
  context.summary.add(section, "weight and axle load", balance.weight, "N");
  context.summary.add(section, "static balance iterations", balance.iterations);
  const auto deflection = track.rail_deflection(0, u.data());
  if (track.flexible()) {
    context.summary.add(section, "static rail deflection under the right wheel", deflection[0],
                        "m");
    context.summary.add(section, "static rail deflection under the left wheel", deflection[1], "m");
  }
  {
    CsvWriter file(
        context.output.staging_path(context.step_name + "_static.csv"),
        {"wheel", "Q_N", "Y_N", "contact_angle_rad", "rolling_radius_m", "rail_deflection_m"},
        root);
    for (int side = 0; side < 2; ++side) {
      const auto& tread = states[side == 0 ? 0 : 2];
      const auto f = side == 0 ? right : left;
      file.write_row({side == 0 ? "right" : "left", CsvWriter::format(f[0]),
                      CsvWriter::format(f[1]), CsvWriter::format(tread.point.contact_angle),
                      CsvWriter::format(tread.point.rolling_radius),
                      CsvWriter::format(deflection[side])});
    }
    file.write_row({"total", CsvWriter::format(right[0] + left[0]),
                    CsvWriter::format(right[1] - left[1]), "", "", ""});
    file.write_row({"weight", CsvWriter::format(balance.weight), "0", "", "", ""});
  }

  // The nominal spin: rolling without longitudinal creep at the mean tread radius.
  const double radius = 0.5 * (states[0].point.rolling_radius + states[2].point.rolling_radius);
  system.set_spin(-V / radius);
  system.set_rolling(true);
  if (track.flexible()) {
    try {
      track.balance(*geometry_, u, true);
    } catch (const RunError& error) {
      throw RunError(context.path + ": " + error.what());
    }
    states = system.contact_states(u.data() + o, v.data() + o);
    track.accept(states);
  }
  v[o + 1] = p.get<double>("Initial lateral velocity");
  const NewtonSettings newton = newton_settings(p);
  NewtonStepSolver solver(track.system(), newton);
  solver.constrain(&track.constraints(), &track.saddle());
  {
    // The internal nodes move with the rails' rates (ġ − Ċ u, the rails at rest).
    std::vector<double> rate(3 * n_wheelset_contacts), unused(rate.size());
    track.constraints().rates(0, u.data(), v.data(), rate.size(), rate.data(), unused.data());
    for (std::size_t i = 0; i < rate.size(); ++i)
      v[o + 6 + i] = rate[i];
  }
  solver.initial_acceleration(0, u.data(), v.data(), a.data());
  NewmarkIntegrator integrator(NewmarkScheme::hht(p.get<double>("Alpha")), u.size());

  std::vector<std::string> columns{"time_s",
                                   "x_m",
                                   "y_m",
                                   "z_m",
                                   "roll_rad",
                                   "spin_rad",
                                   "yaw_rad",
                                   "vy_m_per_s",
                                   "yaw_rate_rad_per_s",
                                   "iterations",
                                   "right_rail_deflection_m",
                                   "left_rail_deflection_m"};
  CsvWriter history(context.output.staging_path(context.step_name + "_wheelset.csv"), columns,
                    root);
  std::vector<std::string> contact_columns{"time_s"};
  for (const char* name : wheelset_contact_names)
    for (const char* q : {"active", "rail_y_m", "rail_z_m", "rolling_radius_m", "contact_angle_rad",
                          "N_N", "Fx_N", "Fy_N", "xi", "eta", "phi_per_m"})
      contact_columns.push_back(std::string(name) + "_" + q);
  for (const char* wheel : {"right", "left"})
    for (const char* q : {"Q_N", "Y_N", "Y_over_Q"})
      contact_columns.push_back(std::string(wheel) + "_" + q);
  CsvWriter contacts(context.output.staging_path(context.step_name + "_contacts.csv"),
                     contact_columns, root);
  CsvWriter events(context.output.staging_path(context.step_name + "_contact_events.csv"),
                   {"time_s", "contact", "event", "N_N"}, root);
  auto write_rows = [&](double time, int iterations) {
    const auto rails = track.rail_deflection(time, u.data());
    history.write_row({time, u[o], u[o + 1], u[o + 2], u[o + 3], u[o + 4], u[o + 5], v[o + 1],
                       v[o + 5], static_cast<double>(iterations), rails[0], rails[1]});
    std::vector<double> row{time};
    for (const ContactState& c : states)
      for (double value :
           {c.active ? 1.0 : 0.0, c.point.rail_point.y, c.point.rail_point.z,
            c.point.rolling_radius, c.point.contact_angle, c.hertz.load, c.creep.Fx, c.creep.Fy,
            c.creepage.longitudinal, c.creepage.lateral, c.creepage.spin})
        row.push_back(value);
    for (int side = 0; side < 2; ++side) {
      const auto f = wheel_forces(states, side);
      row.insert(row.end(), {f[0], f[1], f[0] > 0 ? f[1] / f[0] : 0.0});
    }
    contacts.write_row(row);
  };

  const double end = p.get<double>("End time"), dt = p.get<double>("Time step");
  const double interval = p.get<double>("History interval");
  const long n_steps = std::lround(std::ceil(end / dt - 1e-9));
  states = system.contact_states(u.data() + o, v.data() + o);
  write_rows(0, 0);
  std::array<bool, n_wheelset_contacts> active;
  for (int k = 0; k < n_wheelset_contacts; ++k)
    active[k] = states[k].active;
  OscillationMeter oscillation;
  oscillation.add(0, u[o + 1] - offset[0]);
  double next_output = interval;
  std::size_t n_events = 0, n_conformal = 0;
  auto progress = context.progress("time steps", static_cast<double>(n_steps));
  double time = 0, airborne_since = 1e300;
  for (long n = 0; n < n_steps; ++n) {
    step_or_stop(integrator, time, dt, solver, u.data(), v.data(), a.data(), context.path);
    time = (n + 1) * dt;
    states = system.contact_states(u.data() + o, v.data() + o);
    track.accept(states);
    for (const ContactState& c : states)
      if (c.active && c.conformal) {
        ++n_conformal;
        break;
      }
    for (int k = 0; k < n_wheelset_contacts; ++k)
      if (states[k].active != active[k]) {
        active[k] = states[k].active;
        ++n_events;
        events.write_row({CsvWriter::format(time), wheelset_contact_names[k],
                          active[k] ? (k % 2 ? "flange contact" : "contact") : "separation",
                          CsvWriter::format(states[k].hertz.load)});
      }
    oscillation.add(time, u[o + 1] - track.offsets(time)[0]);
    // Both wheels in the air for 50 ms: the wheelset has left the rails (a climb or a jump
    // over), after which nothing it computes means anything. The run ends there, reported.
    const bool airborne = std::none_of(active.begin(), active.end(), [](bool a) { return a; });
    airborne_since = airborne ? std::min(airborne_since, time) : 1e300;
    const bool derailed = time - airborne_since >= 0.05 - 1e-9 * dt;
    if (time >= next_output - 1e-9 * dt || n + 1 == n_steps || derailed) {
      write_rows(time, solver.statistics().last_iterations);
      next_output += interval;
    }
    progress.update(static_cast<double>(n + 1));
    if (derailed) {
      events.write_row(
          {CsvWriter::format(time), "wheelset", "off the rails (no contact for 50 ms)", "0"});
      context.summary.add(section, "left the rails at", airborne_since, "s");
      if (root)
        std::cerr << "warning: " << context.path
                  << ": the wheelset left the rails at t = " << airborne_since
                  << " s (no wheel touching for 50 ms); the run ends at t = " << time << " s\n";
      break;
    }
  }
  progress.finish();

  CsvWriter measurements(
      context.output.staging_path(context.step_name + "_measurements.csv"),
      {"quantity", "period_s", "wavelength_m", "amplitude_m", "growth_per_cycle", "cycles"}, root);
  const OscillationMeasure measure = oscillation.measure();
  if (measure.cycles >= 1)
    measurements.write_row(
        {"lateral", CsvWriter::format(measure.period), CsvWriter::format(measure.period * V),
         CsvWriter::format(measure.amplitude), CsvWriter::format(measure.growth_per_cycle),
         std::to_string(measure.cycles)});
  CsvWriter cycles(context.output.staging_path(context.step_name + "_cycles.csv"),
                   {"cycle", "start_s", "period_s", "wavelength_m", "amplitude_m"}, root);
  for (std::size_t i = 0; i < oscillation.cycles().size(); ++i) {
    const OscillationCycle& c = oscillation.cycles()[i];
    cycles.write_row({static_cast<double>(i + 1), c.start, c.period, c.period * V, c.amplitude});
  }
  history.flush();
  contacts.flush();
  if (p.get<bool>("Chart"))
    draw_chart(context, section, "wheelset_dynamics_chart.py",
               {context.output.staging_path(context.step_name + "_wheelset.csv"),
                context.output.staging_path(context.step_name + "_contacts.csv"),
                context.output.staging_path(context.step_name + "_chart.png")});
  const NewtonStatistics& statistics = solver.statistics();
  add_newton_summary(context.summary, section, statistics);
  context.summary.add(section, "contact events", static_cast<double>(n_events));
  std::size_t jumps = 0, edges = 0;
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    jumps += system.contact(k).table_jumps();
    edges += system.contact(k).edge_contacts();
  }
  context.summary.add(section, "contact evaluations pinned to the searched stretch's edge",
                      static_cast<double>(edges));
  context.summary.add(section, "contact points taken from the lookup table (jumps)",
                      static_cast<double>(jumps));
  context.summary.add(section, "steps with a conformal contact (curvature raised)",
                      static_cast<double>(n_conformal));
  if (measure.cycles >= 1) {
    context.summary.add(section, "lateral wavelength", measure.period * V, "m");
    context.summary.add(section, "lateral growth per cycle", measure.growth_per_cycle);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  context.summary.add(section, "wall time", seconds, "s");
  context.summary.add(section, "wall time per step", seconds / std::max(1L, n_steps), "s");
}

}  // namespace railfe
