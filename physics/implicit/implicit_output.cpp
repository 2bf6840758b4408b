#include "physics/implicit/implicit_output.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/exodus_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "framework/output/history_events.hpp"

namespace railfe {

struct ImplicitRecorder::History {
  const ImplicitHistory* settings = nullptr;
  std::vector<LocalIndex> dofs;  // owned local DOFs averaged
  double count = 0;              // nodes over every rank
  double value = 0;              // the last sample
  double minimum = std::numeric_limits<double>::infinity();
  double maximum = -std::numeric_limits<double>::infinity();
  HistoryEvents events;
};

namespace {

const char* const kQuantityUnits[3][2] = {{"m", "rad"}, {"m/s", "rad/s"}, {"m/s2", "rad/s2"}};
const char* const kQuantityNames[3] = {"displacement", "velocity", "acceleration"};

void check_finite(double value, const std::string& what, double time) {
  if (!std::isfinite(value))
    throw RunError(what + " is not finite (" + std::to_string(value) + ") at t = " +
                   std::to_string(time) + " s: the run diverged; no further rows are written");
}

}  // namespace

ImplicitRecorder::ImplicitRecorder(const ImplicitSettings& settings, const DofMap& dofs,
                                   OutputDirectory& output, const std::string& step_name,
                                   const std::string& title, bool exodus)
    : settings_(settings), dofs_(dofs), root_(dofs.partition().comm().is_root()) {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  std::vector<std::string> columns{"time_s"};
  for (const ImplicitHistory& history : settings.histories) {
    History record;
    record.settings = &history;
    for (GlobalIndex node : mesh.node_set(history.node_set, "", "").nodes) {
      const LocalIndex local = partition.local_node(node);
      if (local >= 0 && local < partition.n_owned_nodes())
        record.dofs.push_back(dofs.local_dof(local, history.component));
    }
    record.count = partition.comm().sum(static_cast<double>(record.dofs.size()));
    histories_.push_back(std::move(record));
    columns.push_back(history.name + "_" +
                      kQuantityUnits[history.quantity][history.component >= 3 ? 1 : 0]);
  }
  history_file_ = std::make_unique<CsvWriter>(output.staging_path(step_name + "_histories.csv"),
                                              columns, root_);
  energy_file_ = std::make_unique<CsvWriter>(
      output.staging_path(step_name + "_energy.csv"),
      std::vector<std::string>{"time_s", "kinetic_J", "strain_J", "stored_J", "external_work_J",
                               "damping_work_J", "numerical_dissipation_J"},
      root_);
  newton_file_ = std::make_unique<CsvWriter>(
      output.staging_path(step_name + "_newton.csv"),
      std::vector<std::string>{"step", "time_s", "dt_s", "substeps", "iterations",
                               "first_residual_N", "last_residual_N"},
      root_);
  measurements_path_ = output.staging_path(step_name + "_measurements.csv");
  if (exodus) {
    std::vector<std::string> names{"displacement_x", "displacement_y", "displacement_z",
                                   "velocity_x",     "velocity_y",     "velocity_z",
                                   "acceleration_x", "acceleration_y", "acceleration_z"};
    if (dofs.is_uniform() && dofs.dofs_per_node() == 6)  // beams: their sections' rotations too
      names.insert(names.end(), {"rotation_x", "rotation_y", "rotation_z"});
    exodus_ = std::make_unique<ExodusWriter>(output.staging_path(step_name + ".exo"), mesh, title,
                                             names, std::vector<std::string>{}, root_);
    exodus_width_ = static_cast<int>(names.size());
  }
}

ImplicitRecorder::~ImplicitRecorder() = default;

void ImplicitRecorder::sample(const ImplicitState& state, bool write_row) {
  const Communicator& comm = dofs_.partition().comm();
  std::vector<double> sums(histories_.size(), 0.0);
  for (std::size_t h = 0; h < histories_.size(); ++h) {
    const double* field = state.u;
    if (histories_[h].settings->quantity == 1)
      field = state.v;
    if (histories_[h].settings->quantity == 2)
      field = state.a;
    for (LocalIndex dof : histories_[h].dofs)
      sums[h] += field[dof];
  }
  comm.sum_in_place(sums);
  std::vector<double> row{state.time};
  for (std::size_t h = 0; h < histories_.size(); ++h) {
    History& history = histories_[h];
    history.value = sums[h] / history.count;
    check_finite(history.value, "history '" + history.settings->name + "'", state.time);
    history.minimum = std::min(history.minimum, history.value);
    history.maximum = std::max(history.maximum, history.value);
    history.events.sample(state.time, history.value, 0.0, history.settings->period_reference);
    row.push_back(history.value);
  }
  if (write_row)
    history_file_->write_row(row);
}

void ImplicitRecorder::write_energy(double time, const ImplicitEnergy& energy) {
  const std::vector<double> row{time,
                                energy.kinetic,
                                energy.strain,
                                energy.kinetic + energy.strain,
                                energy.external_work,
                                energy.damping_work,
                                energy.balance()};
  for (double value : row)
    check_finite(value, "the energy balance", time);
  energy_file_->write_row(row);
}

void ImplicitRecorder::write_newton(long step, double time, double dt, int substeps, int iterations,
                                    const std::vector<double>& residuals) {
  const double first = residuals.empty() ? 0.0 : residuals.front();
  const double last = residuals.empty() ? 0.0 : residuals.back();
  newton_file_->write_row({static_cast<double>(step), time, dt, static_cast<double>(substeps),
                           static_cast<double>(iterations), first, last});
}

void ImplicitRecorder::snapshot(const ImplicitState& state, bool last) {
  if (!exodus_)
    return;
  const bool due = settings_.exodus_interval > 0 && state.time >= next_snapshot_ - 1e-12;
  if (!due && !last && state.time > 0)
    return;
  const MeshPartition& partition = dofs_.partition();
  const LocalIndex n_owned = partition.n_owned_nodes();
  const int width = exodus_width_;
  std::vector<double> owned(static_cast<std::size_t>(width) * n_owned, 0.0);
  const double* fields[3] = {state.u, state.v, state.a};
  for (LocalIndex node = 0; node < n_owned; ++node) {
    for (int f = 0; f < 3; ++f)
      for (int d = 0; d < 3; ++d)
        owned[width * node + 3 * f + d] = fields[f][dofs_.local_dof(node, d)];
    for (int d = 0; 9 + d < width; ++d)
      owned[width * node + 9 + d] = state.u[dofs_.local_dof(node, 3 + d)];
  }
  exodus_->write_step(state.time, gather_node_field(partition, owned, width), {});
  while (settings_.exodus_interval > 0 && next_snapshot_ <= state.time + 1e-12)
    next_snapshot_ += settings_.exodus_interval;
}

void ImplicitRecorder::finish() {
  CsvWriter file(measurements_path_,
                 {"history", "quantity", "minimum", "maximum", "peak_abs", "peak_time_s",
                  "period_s", "upward_crossings"},
                 root_);
  for (const History& history : histories_) {
    file.write_row({history.settings->name, kQuantityNames[history.settings->quantity],
                    CsvWriter::format(history.minimum), CsvWriter::format(history.maximum),
                    CsvWriter::format(std::abs(history.events.peak_value)),
                    CsvWriter::format(history.events.peak_time),
                    CsvWriter::format(history.events.period()),
                    CsvWriter::format(history.events.crossings)});
  }
  history_file_.reset();
  energy_file_.reset();
  newton_file_.reset();
  if (exodus_)
    exodus_->close();
  exodus_.reset();
}

}  // namespace railfe
