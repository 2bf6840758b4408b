#include "physics/contact_geometry/wheelset_on_track_step.hpp"

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "contact/geometry/conicity.hpp"
#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/elastic_wheelset.hpp"
#include "contact/geometry/profile_file.hpp"
#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/common/profile_geometry.hpp"

namespace railfe {

namespace {

// A result about to be written must be finite: a non-finite one is a failed computation.
double finite(double value, const std::string& where) {
  if (!std::isfinite(value))
    throw RunError(where + " is not finite (" + std::to_string(value) + ")");
  return value;
}

const char* side_name(TrackSide side) {
  return side == TrackSide::left ? "left" : "right";
}

// Every value of a row about to be written must be finite.
void require_finite(std::initializer_list<double> values, const std::string& where) {
  for (double value : values)
    finite(value, where);
}

}  // namespace

WheelsetOnTrackStep::WheelsetOnTrackStep(const Teuchos::ParameterList& parameters)
    : parameters_(&parameters) {}

void WheelsetOnTrackStep::check(const CheckContext& context) {
  geometry_ = read_profile_geometry(*parameters_, context);

  poses_.clear();
  const auto& poses = parameters_->sublist("Poses");
  for (auto it = poses.begin(); it != poses.end(); ++it) {
    const auto& p = poses.sublist(poses.name(it));
    poses_.push_back({poses.name(it),
                      {p.get<double>("Lateral shift"), p.get<double>("Vertical"),
                       p.get<double>("Roll"), p.get<double>("Yaw")},
                      p.get<bool>("Rigid")});
  }
  const double range = parameters_->get<double>("Table half range");
  const double resolution = parameters_->get<double>("Table resolution");
  if (range / resolution > 50000)
    throw_input_error(context.source(), context.path + "/Table resolution",
                      "gives more than 100001 table rows", "at least Table half range / 50000");
  for (double amplitude : parameters_->get<Teuchos::Array<double>>("Conicity amplitudes"))
    if (amplitude > range)
      throw_input_error(context.source(), context.path + "/Conicity amplitudes",
                        std::to_string(amplitude) + " m lies beyond the contact table",
                        "at most Table half range (" + std::to_string(range) + " m)");
}

void WheelsetOnTrackStep::run(StepContext& context) {
  const bool root = context.model.comm().is_root();
  const std::string section = "Step " + context.step_name + " (wheelset on track)";
  const WheelRailGeometry& geometry = *geometry_;
  const double range = parameters_->get<double>("Table half range");
  const int half_rows =
      static_cast<int>(std::lround(range / parameters_->get<double>("Table resolution")));
  const int check_samples = parameters_->get<int>("Check samples");
  auto progress = context.progress("contact table", 1);
  const ContactTable table(geometry, range, 2 * half_rows + 1, check_samples);
  progress.finish();

  CsvWriter rows(context.output.staging_path(context.step_name + "_contact_table.csv"),
                 {"lateral_m", "vertical_m", "roll_rad", "delta_r_m", "converged", "left_part",
                  "left_rolling_radius_m", "left_contact_angle_rad", "left_y_m", "right_part",
                  "right_rolling_radius_m", "right_contact_angle_rad", "right_y_m"},
                 root);
  int unconverged = 0;
  for (std::size_t i = 0; i < table.rows().size(); ++i) {
    const RigidContact& r = table.rows()[i];
    unconverged += r.converged ? 0 : 1;
    require_finite({r.vertical, r.roll, table.rolling_radius_difference(i)},
                   context.path + ": contact table row at " + CsvWriter::format(r.lateral) + " m");
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      const ContactPoint& c = r.active(side);
      require_finite({c.rolling_radius, c.contact_angle, c.rail_point.y},
                     context.path + ": contact table row at " + CsvWriter::format(r.lateral) +
                         " m, " + side_name(side) + " wheel");
    }
    std::vector<std::string> cells = {
        CsvWriter::format(r.lateral), CsvWriter::format(r.vertical), CsvWriter::format(r.roll),
        CsvWriter::format(table.rolling_radius_difference(i)), r.converged ? "1" : "0"};
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      const ContactPoint& c = r.active(side);
      cells.insert(cells.end(),
                   {c.flange ? "flange" : "tread", CsvWriter::format(c.rolling_radius),
                    CsvWriter::format(c.contact_angle), CsvWriter::format(c.rail_point.y)});
    }
    rows.write_row(cells);
  }

  CsvWriter contacts(context.output.staging_path(context.step_name + "_contacts.csv"),
                     {"contact",
                      "pose",
                      "lateral_m",
                      "vertical_m",
                      "roll_rad",
                      "yaw_rad",
                      "side",
                      "part",
                      "status",
                      "iterations",
                      "y_m",
                      "z_m",
                      "x_m",
                      "contact_angle_rad",
                      "rolling_radius_m",
                      "gap_m",
                      "penetration_m",
                      "wheel_lateral_curvature_1pm",
                      "rail_lateral_curvature_1pm",
                      "wheel_rolling_curvature_1pm",
                      "A_1pm",
                      "B_1pm"},
                     root);
  int searches = 0, failed = 0, iterations = 0;
  for (const DeckPose& deck_pose : poses_) {
    WheelsetPose pose = deck_pose.pose;
    if (deck_pose.rigid) {
      const RigidContact rigid =
          solve_rigid_contact(geometry, pose.lateral, pose.yaw, nullptr, check_samples);
      if (!rigid.converged)
        throw RunError(context.path + "/Poses/" + deck_pose.name +
                       ": the rigid wheelset's vertical position and roll did not converge; check "
                       "that Track/Gauge, Track/Back to back and Track/Nominal radius fit the "
                       "profiles (in m) and the profiles' length unit");
      pose.vertical = rigid.vertical;
      pose.roll = rigid.roll;
    }
    for (TrackSide side : {TrackSide::left, TrackSide::right})
      for (bool flange : {false, true}) {
        auto start = table.start(side, flange, pose.lateral);
        ContactPoint c = search_contact(geometry, side, flange, pose, start[0], start[1]);
        if (c.status == SearchStatus::not_converged || c.status == SearchStatus::not_a_minimum) {
          const GapSample sample = least_gap_sample(geometry, side, flange, pose);
          c = search_contact(geometry, side, flange, pose, sample.s_wheel, sample.s_rail);
        }
        ++searches;
        failed += c.status == SearchStatus::not_converged ? 1 : 0;
        iterations += c.iterations;
        require_finite(
            {c.rail_point.y, c.rail_point.z, c.x, c.contact_angle, c.rolling_radius, c.gap,
             c.wheel_lateral_curvature, c.rail_lateral_curvature, c.wheel_rolling_curvature},
            context.path + "/Poses/" + deck_pose.name + ": the " + side_name(side) +
                (flange ? " flange" : " tread") + " search");
        contacts.write_row(
            {deck_pose.name + " " + side_name(side) + (flange ? " flange" : " tread"),
             deck_pose.name,
             CsvWriter::format(pose.lateral),
             CsvWriter::format(pose.vertical),
             CsvWriter::format(pose.roll),
             CsvWriter::format(pose.yaw),
             side_name(side),
             flange ? "flange" : "tread",
             status_name(c.status),
             std::to_string(c.iterations),
             CsvWriter::format(c.rail_point.y),
             CsvWriter::format(c.rail_point.z),
             CsvWriter::format(c.x),
             CsvWriter::format(c.contact_angle),
             CsvWriter::format(c.rolling_radius),
             CsvWriter::format(c.gap),
             CsvWriter::format(c.penetration()),
             CsvWriter::format(c.wheel_lateral_curvature),
             CsvWriter::format(c.rail_lateral_curvature),
             CsvWriter::format(c.wheel_rolling_curvature),
             CsvWriter::format(c.relative_curvature_rolling()),
             CsvWriter::format(c.relative_curvature_lateral())});
      }
  }

  const double e = table.half_contact_distance(), r0 = table.centred_rolling_radius();
  const double first = table.rows().front().lateral;
  const double step = table.rows()[1].lateral - first;
  auto delta_r = [&](double y) {
    const double position = std::clamp((y - first) / step, 0.0, table.rows().size() - 1.0);
    const std::size_t i = std::min<std::size_t>(position, table.rows().size() - 2);
    const double w = position - i;
    return (1 - w) * table.rolling_radius_difference(i) +
           w * table.rolling_radius_difference(i + 1);
  };
  const double flange_shift = std::min(std::abs(table.flange_contact_shift(TrackSide::right)),
                                       std::abs(table.flange_contact_shift(TrackSide::left)));
  const bool regression = parameters_->get<std::string>("Conicity method") == "linear regression";
  CsvWriter conicity(context.output.staging_path(context.step_name + "_conicity.csv"),
                     {"amplitude_m", "wavelength_m", "kinematic_conicity", "regression_conicity",
                      "equivalent_conicity", "reaches_flange"},
                     root);
  const auto& amplitudes = parameters_->get<Teuchos::Array<double>>("Conicity amplitudes");
  for (double amplitude : amplitudes) {
    const std::string where =
        context.path + "/Conicity amplitudes: at " + CsvWriter::format(amplitude) + " m";
    const double wavelength = kinematic_wavelength(delta_r, e, r0, amplitude);
    const double linear =
        finite(regression_conicity(delta_r, amplitude), where + " the regression conicity");
    // Where dr does not restore the wheelset (a hollow worn tread, or a profile mirrored or
    // upside down) there is no kinematic oscillation and no wavelength: the regression's
    // (negative) slope is still defined, so that route can go on with the kinematic cells left
    // empty; the kinematic route cannot.
    const bool oscillates = std::isfinite(wavelength);
    if (!oscillates && !regression)
      throw RunError(where + " the rolling radius difference (" +
                     CsvWriter::format(delta_r(amplitude)) +
                     " m) does not restore the wheelset, so there is no kinematic oscillation "
                     "(regression conicity " +
                     CsvWriter::format(linear) +
                     "): is a profile upside down or mirrored (Profiles/Wheel mirrored, Rail "
                     "mirrored), or use Conicity method = linear regression");
    const double kinematic = oscillates ? finite(equivalent_conicity(wavelength, e, r0),
                                                 where + " the kinematic conicity")
                                        : 0.0;
    const double gamma = regression ? linear : kinematic;
    // NaN flange shift (no flange contact in the table) compares false: not reached.
    const bool reaches = amplitude >= flange_shift;
    conicity.write_row({CsvWriter::format(amplitude),
                        oscillates ? CsvWriter::format(wavelength) : std::string(),
                        oscillates ? CsvWriter::format(kinematic) : std::string(),
                        CsvWriter::format(linear), CsvWriter::format(gamma), reaches ? "1" : "0"});
    if (std::abs(amplitude - 0.003) < 1e-12)
      context.summary.add(section, "equivalent conicity at 3 mm", gamma);
  }
  const double load = parameters_->get<double>("Vertical load");
  if (load > 0)
    write_elastic_contacts(context, load);
  CsvWriter results(
      context.output.staging_path(context.step_name + "_contact_summary.csv"),
      {"step", "flange_contact_right_m", "flange_contact_left_m", "half_contact_distance_m",
       "centred_rolling_radius_m", "table_rows_not_converged"},
      root);
  // No flange contact within the table (a cone, a short table): an empty cell, not NaN.
  auto shift_cell = [&](TrackSide side) {
    const double shift = table.flange_contact_shift(side);
    return std::isfinite(shift) ? CsvWriter::format(shift) : std::string();
  };
  results.write_row({context.step_name, shift_cell(TrackSide::right), shift_cell(TrackSide::left),
                     CsvWriter::format(finite(e, context.path + ": the half contact distance")),
                     CsvWriter::format(finite(r0, context.path + ": the centred rolling radius")),
                     std::to_string(unconverged)});
  results.flush();
  context.summary.add(section, "table rows", static_cast<double>(table.rows().size()));
  context.summary.add(section, "table rows not converged", unconverged);
  for (TrackSide side : {TrackSide::left, TrackSide::right}) {
    const double shift = table.flange_contact_shift(side);
    const std::string key = std::string("flange contact from, ") + side_name(side);
    if (std::isfinite(shift))
      context.summary.add(section, key, shift * 1e3, "mm");
    else
      context.summary.add(section, key, "not within the table");
  }
  context.summary.add(section, "half distance between contact points", e, "m");
  context.summary.add(section, "centred rolling radius", r0, "m");
  context.summary.add(section, "pose searches", searches);
  context.summary.add(section, "pose searches not converged", failed);
  context.summary.add(section, "mean iterations per search",
                      searches ? double(iterations) / searches : 0.0);
  if (unconverged > 0)
    context.summary.add(section, "warning",
                        std::to_string(unconverged) +
                            " table rows did not converge (see converged in " + context.step_name +
                            "_contact_table.csv)");

  CsvWriter profile_points(context.output.staging_path(context.step_name + "_profiles.csv"),
                           {"pose", "body", "side", "y_m", "z_m"}, root);
  for (TrackSide side : {TrackSide::left, TrackSide::right}) {
    const ProfileCurve& rail = geometry.rail(side);
    for (int k = 0; k <= 400; ++k) {
      const Vec2 p = rail.at(rail.begin() + (rail.end() - rail.begin()) * k / 400).p;
      profile_points.write_row(
          {"", "rail", side_name(side), CsvWriter::format(p.y), CsvWriter::format(p.z)});
    }
  }
  for (const DeckPose& deck_pose : poses_) {
    WheelsetPose pose = deck_pose.pose;
    if (deck_pose.rigid) {
      const RigidContact rigid = solve_rigid_contact(geometry, pose.lateral, pose.yaw, nullptr, 0);
      pose.vertical = rigid.vertical;
      pose.roll = rigid.roll;
    }
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      const ProfileCurve& wheel = geometry.wheel(side);
      for (int k = 0; k <= 400; ++k) {
        const LocusPoint p =
            geometry.locus(side, wheel.begin() + (wheel.end() - wheel.begin()) * k / 400, pose);
        profile_points.write_row({deck_pose.name, "wheel", side_name(side),
                                  CsvWriter::format(p.y.v), CsvWriter::format(p.z.v)});
      }
    }
  }
  rows.flush();
  contacts.flush();
  conicity.flush();
  profile_points.flush();
  if (parameters_->get<bool>("Chart"))
    draw_chart(context, section, "contact_geometry_chart.py",
               {context.output.staging_path(context.step_name + "_profiles.csv"),
                context.output.staging_path(context.step_name + "_contacts.csv"),
                context.output.staging_path(context.step_name + "_contact_table.csv"),
                context.output.staging_path(context.step_name + "_geometry.png")});
}

void WheelsetOnTrackStep::write_elastic_contacts(StepContext& context, double load) {
  const bool root = context.model.comm().is_root();
  const std::string section = "Step " + context.step_name + " (wheelset on track)";
  const double modulus = contact_modulus(
      {parameters_->get<double>("Young's modulus"), parameters_->get<double>("Poisson's ratio")},
      {parameters_->get<double>("Young's modulus"), parameters_->get<double>("Poisson's ratio")});
  CsvWriter patches(context.output.staging_path(context.step_name + "_elastic_contacts.csv"),
                    {"contact", "pose", "side", "part", "loaded", "y_m", "z_m", "contact_angle_rad",
                     "rolling_radius_m", "approach_m", "normal_force_N", "lateral_force_N",
                     "vertical_force_N", "a_m", "b_m", "max_pressure_Pa", "A_1pm", "B_1pm"},
                    root);
  CsvWriter poses(context.output.staging_path(context.step_name + "_elastic_poses.csv"),
                  {"pose", "lateral_m", "vertical_m", "roll_rad", "sink_m", "load_N",
                   "vertical_force_N", "lateral_force_N", "roll_moment_Nm", "iterations"},
                  root);
  for (const DeckPose& deck_pose : poses_) {
    const std::string where = context.path + "/Poses/" + deck_pose.name;
    const RigidContact rigid =
        solve_rigid_contact(*geometry_, deck_pose.pose.lateral, deck_pose.pose.yaw, nullptr,
                            parameters_->get<int>("Check samples"));
    if (!rigid.converged)
      throw RunError(where + ": the rigid start of the elastic solution did not converge");
    const ElasticContact elastic =
        solve_elastic_contact(*geometry_, rigid, deck_pose.pose.yaw, load, modulus);
    if (!elastic.converged)
      throw RunError(where + ": the elastic equilibrium under Vertical load = " +
                     CsvWriter::format(load) + " N failed: " + elastic.failure);
    double vertical = 0;
    for (TrackSide side : {TrackSide::left, TrackSide::right})
      for (int part = 0; part < 2; ++part) {
        const ElasticPatch& patch = elastic.patches[static_cast<int>(side)][part];
        const ContactPoint& c = patch.point;
        if (!c.valid())
          continue;
        const std::string name =
            deck_pose.name + " " + side_name(side) + (part ? " flange" : " tread");
        auto number = [&](double value, const char* what) {
          return CsvWriter::format(finite(value, where + ": " + name + " " + what));
        };
        vertical += patch.force_z;
        patches.write_row(
            {name, deck_pose.name, side_name(side), part ? "flange" : "tread",
             patch.loaded() ? "1" : "0", number(c.rail_point.y, "y"), number(c.rail_point.z, "z"),
             number(c.contact_angle, "contact angle"), number(c.rolling_radius, "rolling radius"),
             number(patch.hertz.approach, "approach"), number(patch.hertz.load, "normal force"),
             number(patch.force_y, "lateral force"), number(patch.force_z, "vertical force"),
             number(patch.hertz.a, "a"), number(patch.hertz.b, "b"),
             number(patch.hertz.pressure, "pressure"), number(c.relative_curvature_rolling(), "A"),
             number(c.relative_curvature_lateral(), "B")});
      }
    poses.write_row({deck_pose.name, CsvWriter::format(elastic.pose.lateral),
                     CsvWriter::format(elastic.pose.vertical), CsvWriter::format(elastic.pose.roll),
                     CsvWriter::format(elastic.pose.vertical - rigid.vertical),
                     CsvWriter::format(load), CsvWriter::format(-vertical),
                     CsvWriter::format(elastic.lateral_force),
                     CsvWriter::format(elastic.roll_residual), std::to_string(elastic.iterations)});
    if (std::abs(deck_pose.pose.lateral) < 1e-15) {
      const ElasticPatch& right = elastic.patches[1][0];
      context.summary.add(section, "elastic centred contact angle, right tread",
                          right.point.contact_angle * 180 / M_PI, "degree");
      context.summary.add(section, "elastic centred max pressure, right tread",
                          right.hertz.pressure / 1e6, "MPa");
    }
  }
  patches.flush();
  poses.flush();
}

}  // namespace railfe
