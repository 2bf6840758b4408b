#include "physics/wheelset_dynamics/vehicle_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railfe {

namespace {

const char* kSides[2] = {"right", "left"};

std::vector<std::string> wheelset_columns(int n) {
  std::vector<std::string> columns{"time_s", "iterations"};
  for (int w = 0; w < n; ++w)
    for (const char* q :
         {"x_m", "y_m", "z_m", "roll_rad", "spin_rad", "yaw_rad", "vy_m_per_s", "ay_m_per_s2"})
      columns.push_back("w" + std::to_string(w + 1) + "_" + q);
  return columns;
}

std::vector<std::string> wheel_columns(int n) {
  std::vector<std::string> columns{"time_s"};
  for (int w = 0; w < n; ++w)
    for (const char* side : kSides)
      for (const char* q : {"Q_N", "Y_N", "Y_over_Q", "flange"})
        columns.push_back("w" + std::to_string(w + 1) + "_" + side + "_" + q);
  return columns;
}

std::vector<std::string> point_columns(const std::vector<std::string>& names) {
  std::vector<std::string> columns{"time_s"};
  for (const std::string& name : names)
    for (const char* q : {"y_m", "z_m", "ay_m_per_s2", "az_m_per_s2"})
      columns.push_back(name + "_" + q);
  return columns;
}

}  // namespace

VehicleRecorder::VehicleRecorder(StepContext& context, VehicleSystem& system,
                                 std::vector<std::string> point_names,
                                 std::vector<Eigen::MatrixXd> point_motion,
                                 std::vector<std::array<double, 2>> static_loads, bool writes)
    : system_(system),
      writes_(writes),
      point_names_(std::move(point_names)),
      point_motion_(std::move(point_motion)),
      static_loads_(std::move(static_loads)),
      wheelsets_(context.output.staging_path(context.step_name + "_wheelsets.csv"),
                 wheelset_columns(system.n_wheelsets()), writes_),
      wheels_(context.output.staging_path(context.step_name + "_wheels.csv"),
              wheel_columns(system.n_wheelsets()), writes_),
      points_(context.output.staging_path(context.step_name + "_points.csv"),
              point_columns(point_names_), writes_),
      events_(context.output.staging_path(context.step_name + "_contact_events.csv"),
              {"time_s", "wheelset", "contact", "event", "N_N"}, writes_),
      impacts_path_(context.output.staging_path(context.step_name + "_flange_impacts.csv")),
      safety_path_(context.output.staging_path(context.step_name + "_safety.csv")),
      comfort_path_(context.output.staging_path(context.step_name + "_comfort.csv")),
      active_(system.n_wheelsets()),
      open_impact_(system.n_wheelsets(), {-1, -1}),
      peaks_(system.n_wheelsets()),
      peak_ay_(point_names_.size(), 0.0),
      sum_ay2_(point_names_.size(), 0.0) {}

void VehicleRecorder::set_sliding_mean(int samples, double length) {
  window_ = std::max(1, samples);
  window_length_ = length;
}

void VehicleRecorder::record(
    double time, int iterations, const double* u, const double* v, const double* a,
    const std::vector<std::array<ContactState, n_wheelset_contacts>>& states, bool write_row) {
  const int n = system_.n_wheelsets();
  const bool first = samples_ == 0;
  for (int w = 0; w < n; ++w) {
    for (int k = 0; k < n_wheelset_contacts; ++k) {
      const bool now = states[w][k].active;
      if (!first && now != active_[w][k]) {
        ++n_events_;
        events_.write_row({CsvWriter::format(time), std::to_string(w + 1),
                           wheelset_contact_names[k],
                           now ? (k % 2 ? "flange contact" : "contact") : "separation",
                           CsvWriter::format(states[w][k].hertz.load)});
      }
      active_[w][k] = now;
    }
    for (int side = 0; side < 2; ++side) {
      const auto f = wheel_forces(states[w], side);
      WheelPeaks& peak = peaks_[w][side];
      const double Q0 = static_loads_[w][side];
      peak.unloading = std::max(peak.unloading, std::min(1.0, (Q0 - f[0]) / Q0));
      peak.Y = std::max(peak.Y, std::abs(f[1]));
      const double quotient = f[0] > 0 ? std::abs(f[1]) / f[0] : 0.0;
      peak.Y_over_Q = std::max(peak.Y_over_Q, quotient);
      // The sliding mean over the window: a lifted wheel's Y/Q of an instant says little.
      if (peak.recent.size() < static_cast<std::size_t>(window_)) {
        peak.recent.push_back(quotient);
      } else {
        const std::size_t slot = samples_ % static_cast<std::size_t>(window_);
        peak.sum -= peak.recent[slot];
        peak.recent[slot] = quotient;
      }
      peak.sum += quotient;
      if (peak.recent.size() == static_cast<std::size_t>(window_))
        peak.mean_Y_over_Q = std::max(peak.mean_Y_over_Q, peak.sum / window_);
      // A flange impact lasts from the flange's first touch to its release.
      const ContactState& flange = states[w][2 * side + 1];
      int& open = open_impact_[w][side];
      if (flange.active && open < 0) {
        open = static_cast<int>(impacts_.size());
        impacts_.push_back({w, side, time, time, 0, 0, 0});
      }
      if (open >= 0) {
        Impact& impact = impacts_[open];
        impact.end = time;
        impact.peak_flange = std::max(impact.peak_flange, flange.hertz.load);
        impact.peak_Y = std::max(impact.peak_Y, std::abs(f[1]));
        impact.peak_Y_over_Q = std::max(impact.peak_Y_over_Q, quotient);
        if (!flange.active)
          open = -1;
      }
    }
  }
  const Eigen::Index n_model = system_.n_model_unknowns();
  const Eigen::Map<const Eigen::VectorXd> uu(u, n_model), aa(a, n_model);
  std::vector<double> point_row{time};
  for (std::size_t p = 0; p < point_motion_.size(); ++p) {
    const Eigen::VectorXd du = point_motion_[p] * uu, ddu = point_motion_[p] * aa;
    point_row.insert(point_row.end(), {du(1), du(2), ddu(1), ddu(2)});
    peak_ay_[p] = std::max(peak_ay_[p], std::abs(ddu(1)));
    sum_ay2_[p] += ddu(1) * ddu(1);
  }
  ++samples_;
  if (!write_row)
    return;
  std::vector<double> row{time, static_cast<double>(iterations)};
  for (int w = 0; w < n; ++w) {
    const std::size_t o = system_.wheelset(w).unknowns().wheelset;
    row.insert(row.end(),
               {u[o], u[o + 1], u[o + 2], u[o + 3], u[o + 4], u[o + 5], v[o + 1], a[o + 1]});
  }
  wheelsets_.write_row(row);
  row.assign(1, time);
  for (int w = 0; w < n; ++w)
    for (int side = 0; side < 2; ++side) {
      const auto f = wheel_forces(states[w], side);
      row.insert(row.end(), {f[0], f[1], f[0] > 0 ? f[1] / f[0] : 0.0,
                             states[w][2 * side + 1].active ? 1.0 : 0.0});
    }
  wheels_.write_row(row);
  points_.write_row(point_row);
}

void VehicleRecorder::finish(double, RunSummary& summary, const std::string& section) {
  wheelsets_.flush();
  wheels_.flush();
  points_.flush();
  {
    CsvWriter file(
        impacts_path_,
        {"wheelset", "wheel", "start_s", "end_s", "peak_flange_N_N", "peak_Y_N", "peak_Y_over_Q"},
        writes_);
    for (const Impact& i : impacts_)
      file.write_row({std::to_string(i.wheelset + 1), kSides[i.side], CsvWriter::format(i.start),
                      CsvWriter::format(i.end), CsvWriter::format(i.peak_flange),
                      CsvWriter::format(i.peak_Y), CsvWriter::format(i.peak_Y_over_Q)});
  }
  double worst_quotient = 0, worst_unloading = 0, worst_Y = 0, worst_mean = 0;
  {
    CsvWriter file(safety_path_,
                   {"wheelset", "wheel", "static_Q_N", "peak_Y_N", "peak_Y_over_Q",
                    "peak_Y_over_Q_sliding_mean", "peak_unloading_dQ_over_Q"},
                   writes_);
    for (int w = 0; w < system_.n_wheelsets(); ++w)
      for (int side = 0; side < 2; ++side) {
        const WheelPeaks& p = peaks_[w][side];
        file.write_row({std::to_string(w + 1), kSides[side],
                        CsvWriter::format(static_loads_[w][side]), CsvWriter::format(p.Y),
                        CsvWriter::format(p.Y_over_Q), CsvWriter::format(p.mean_Y_over_Q),
                        CsvWriter::format(p.unloading)});
        worst_quotient = std::max(worst_quotient, p.Y_over_Q);
        worst_mean = std::max(worst_mean, p.mean_Y_over_Q);
        worst_unloading = std::max(worst_unloading, p.unloading);
        worst_Y = std::max(worst_Y, p.Y);
      }
  }
  {
    CsvWriter file(comfort_path_, {"point", "peak_ay_m_per_s2", "rms_ay_m_per_s2"}, writes_);
    for (std::size_t p = 0; p < point_names_.size(); ++p) {
      const double rms = std::sqrt(sum_ay2_[p] / std::max<std::size_t>(samples_, 1));
      file.write_row({point_names_[p], CsvWriter::format(peak_ay_[p]), CsvWriter::format(rms)});
      summary.add(section, "peak lateral acceleration at " + point_names_[p], peak_ay_[p], "m/s^2");
      summary.add(section, "RMS lateral acceleration at " + point_names_[p], rms, "m/s^2");
    }
  }
  summary.add(section, "contact events", static_cast<double>(n_events_));
  summary.add(section, "flange impacts", static_cast<double>(impacts_.size()));
  summary.add(section, "peak derailment quotient Y/Q", worst_quotient);
  std::ostringstream mean;
  mean << "peak derailment quotient Y/Q, sliding mean over " << window_length_ << " m";
  summary.add(section, mean.str(), worst_mean);
  summary.add(section, "peak wheel unloading dQ/Q", worst_unloading);
  summary.add(section, "peak lateral wheel force", worst_Y, "N");
}

}  // namespace railfe
