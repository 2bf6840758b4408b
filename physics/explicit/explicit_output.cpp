#include "physics/explicit/explicit_output.hpp"

#include <algorithm>
#include <cmath>

#include "framework/base/error.hpp"
#include "framework/mesh/partition.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/exodus_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "framework/output/output_directory.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/common/contact_tables.hpp"
#include "physics/explicit/contact_output.hpp"
#include "physics/explicit/explicit_solver.hpp"
#include "physics/explicit/nodal_conditions.hpp"

namespace railfe {

namespace {

// Steps before the energy balance is judged against its limit.
constexpr long long kSettlingSteps = 20;

const char* kQuantityUnits[6] = {"m", "m_per_s", "m_per_s2", "rad_per_s", "rad_per_s", "N_m_s"};
const char* kStressNames[6] = {"xx", "yy", "zz", "xy", "yz", "zx"};

int quantity_index(const std::string& quantity) {
  const char* names[6] = {"displacement",          "velocity",
                          "acceleration",          "angular velocity",
                          "body angular velocity", "angular momentum"};
  for (int q = 0; q < 6; ++q)
    if (quantity == names[q])
      return q;
  return 2;
}

double von_mises(const double* s) {
  return std::sqrt(
      0.5 * (std::pow(s[0] - s[1], 2) + std::pow(s[1] - s[2], 2) + std::pow(s[2] - s[0], 2)) +
      3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace

ExplicitRecorder::ExplicitRecorder(const ExplicitSettings& settings, const ExplicitSolver& solver,
                                   const MeshPartition& partition, OutputDirectory& output,
                                   const std::string& step_name, const std::string& title,
                                   bool write_exodus)
    : settings_(settings),
      solver_(solver),
      partition_(partition),
      events_(settings.histories.size()),
      balance_(std::make_unique<EnergyBalance>()),
      root_(partition.comm().is_root()) {
  const Mesh& mesh = partition.mesh();
  const Communicator& comm = partition.comm();
  std::vector<std::string> columns = {"time_s"};
  for (const HistorySpec& history : settings.histories) {
    std::vector<LocalIndex> nodes;
    if (!history.node_set.empty())
      nodes = owned_set_nodes(partition, history.node_set);
    history_counts_.push_back(
        history.node_set.empty()
            ? 1.0
            : static_cast<double>(comm.sum(static_cast<long long>(nodes.size()))));
    history_nodes_.push_back(nodes);
    std::string quantity = history.quantity;
    std::replace(quantity.begin(), quantity.end(), ' ', '_');
    columns.push_back(history.name + "_" + quantity + "_" +
                      std::string(1, "xyz"[history.component]) + "_" +
                      kQuantityUnits[quantity_index(history.quantity)]);
  }
  // Which kernel element holds each element history on this rank.
  const SolidElements& elements = solver.elements();
  for (const ElementHistorySpec& history : settings.element_histories) {
    LocalIndex row = -1;
    for (LocalIndex e = 0; e < elements.n_elements; ++e)
      if (elements.global_element[e] == history.element)
        row = e;
    element_rows_.push_back(row);
    for (const char* component : kStressNames)
      columns.push_back(history.name + "_stress_" + component + "_Pa");
    columns.push_back(history.name + "_von_mises_Pa");
  }
  histories_ = std::make_unique<CsvWriter>(output.staging_path(step_name + "_histories.csv"),
                                           columns, root_);
  energy_ = std::make_unique<CsvWriter>(
      output.staging_path(step_name + "_energy.csv"),
      std::vector<std::string>{"time_s", "step", "time_step_s", "kinetic_J", "internal_J",
                               "hourglass_J", "damping_J", "contact_J", "friction_J",
                               "external_work_J", "energy_error", "hourglass_ratio"},
      root_);
  measurements_path_ = output.staging_path(step_name + "_measurements.csv");
  contact_ = std::make_unique<ContactRecorder>(settings, solver, output, step_name, root_);
  wave_speeds_path_ = output.staging_path(step_name + "_wave_speeds.csv");
  if (write_exodus) {
    std::vector<std::string> nodal_names{"displacement_x", "displacement_y", "displacement_z",
                                         "velocity_x",     "velocity_y",     "velocity_z",
                                         "acceleration_x", "acceleration_y", "acceleration_z"};
    if (!solver.contact().empty())
      for (const std::string& name : contact_nodal_field_names())
        nodal_names.push_back(name);
    exodus_ = std::make_unique<ExodusWriter>(
        output.staging_path(step_name + ".exo"), mesh, title, nodal_names,
        std::vector<std::string>{"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz",
                                 "stress_zx", "von_mises"},
        root_);
  }
}

ExplicitRecorder::~ExplicitRecorder() = default;

const EnergyBalance& ExplicitRecorder::last_balance() const {
  return *balance_;
}

bool ExplicitRecorder::record(bool force_rows) {
  const Communicator& comm = partition_.comm();
  const long long step = solver_.n_steps();
  contact_->record(force_rows);
  if (!settings_.histories.empty()) {
    std::vector<double> sums;
    for (std::size_t h = 0; h < settings_.histories.size(); ++h) {
      const HistorySpec& history = settings_.histories[h];
      if (!history.body.empty()) {
        // Bodies are replicated: rank 0 alone contributes to the sum.
        double value = 0;
        for (const RigidBody& body : solver_.bodies()) {
          if (body.name == history.body && root_) {
            const int q = quantity_index(history.quantity);
            const Eigen::Vector3d body_frame = body.rotation.transpose() * body.angular_velocity;
            const Eigen::Vector3d momentum = body.rotation * (body.inertia * body_frame);
            const Eigen::Vector3d* vectors[6] = {&body.displacement, &body.velocity,
                                                 &body.acceleration, &body.angular_velocity,
                                                 &body_frame,        &momentum};
            value = (*vectors[q])[history.component];
          }
        }
        sums.push_back(value);
        continue;
      }
      sums.push_back(
          solver_.node_sum(history_nodes_[h], quantity_index(history.quantity), history.component)
              .first);
    }
    comm.sum_in_place(sums);
    for (double value : sums)
      if (!std::isfinite(value))
        return false;
    for (std::size_t h = 0; h < sums.size(); ++h) {
      sums[h] /= history_counts_[h];
      events_[h].sample(solver_.time(), sums[h], settings_.histories[h].arrival_level,
                        settings_.histories[h].period_reference);
    }
    if ((force_rows || step % settings_.history_interval == 0) && step != last_history_step_) {
      last_history_step_ = step;
      std::vector<double> row = {solver_.time()};
      row.insert(row.end(), sums.begin(), sums.end());
      const auto stresses = element_stresses();
      row.insert(row.end(), stresses.begin(), stresses.end());
      histories_->write_row(row);
      if (root_)
        history_rows_.push_back(row);
    }
  } else if (!settings_.element_histories.empty() &&
             (force_rows || step % settings_.history_interval == 0) && step != last_history_step_) {
    last_history_step_ = step;
    std::vector<double> row = {solver_.time()};
    const auto stresses = element_stresses();
    row.insert(row.end(), stresses.begin(), stresses.end());
    histories_->write_row(row);
    if (root_)
      history_rows_.push_back(row);
  }
  if ((force_rows || step % settings_.energy_interval == 0) && step != last_energy_step_) {
    last_energy_step_ = step;
    *balance_ = solver_.energy_balance();
    const EnergyBalance& b = *balance_;
    // The first steps after an impulsive start (a velocity jump at t = 0) carry an O(1)
    // relative error on tiny energies; real divergence takes longer to show.
    const bool judged = step >= kSettlingSteps;
    // Blow-up is exponential growth of the energy far past what the loads and the start put in;
    // a stable step only oscillates the measured energy (a bounded error), which must not stop
    // a correct run. The energy dissipated counts with the stored: an instability that dampers
    // (Rayleigh, contact damping, friction) eat as fast as it creates energy never grows the
    // stored energy, yet creates hundreds of times the work of the loads.
    energy_put_in_ =
        std::max(energy_put_in_, std::abs(solver_.initial_energy()) + std::abs(b.external_work));
    const double created =
        b.kinetic + b.internal + b.hourglass + b.contact + b.damping + b.friction;
    growth_ = created / std::max(energy_put_in_, 1e-300);
    // A step above the stable limit (Allow unstable step) has no bounded oscillation to excuse
    // the error: there the error alone fails. Penalty contact beyond its critical step throws
    // nodes off with energy it created instead of growing exponentially.
    beyond_stable_step_ = solver_.last_step() > solver_.stable_step() * (1 + 1e-9);
    if (!std::isfinite(b.kinetic + b.internal + b.hourglass + b.damping + b.contact + b.friction +
                       b.external_work) ||
        (judged && !(std::abs(b.error) <= settings_.energy_error_limit) &&
         (beyond_stable_step_ || !(growth_ <= settings_.energy_growth_limit))))
      return false;
    const std::vector<double> row = {solver_.time(),
                                     static_cast<double>(step),
                                     solver_.last_step(),
                                     b.kinetic,
                                     b.internal,
                                     b.hourglass,
                                     b.damping,
                                     b.contact,
                                     b.friction,
                                     b.external_work,
                                     b.error,
                                     b.hourglass / std::max(b.kinetic + b.internal, 1e-300)};
    energy_->write_row(row);
    if (root_)
      energy_rows_.push_back(row);
    energy_->flush();
    histories_->flush();
  }
  return true;
}

std::vector<double> ExplicitRecorder::element_stresses() const {
  std::vector<double> values;
  for (LocalIndex row : element_rows_) {
    double stress[7] = {0, 0, 0, 0, 0, 0, 0};
    if (row >= 0) {
      element_cauchy_stress(solver_.elements(), row, solver_.displacement().data(), stress);
      stress[6] = von_mises(stress);
    }
    values.insert(values.end(), stress, stress + 7);
  }
  partition_.comm().sum_in_place(values);
  return values;
}

void ExplicitRecorder::snapshot(bool last) {
  if (!exodus_)
    return;
  const double time = solver_.time();
  if (!last && time + 1e-12 * std::max(time, 1e-30) < next_snapshot_)
    return;
  const auto n_owned = static_cast<std::size_t>(partition_.n_owned_nodes());
  const bool contact = !solver_.contact().empty();
  const int width = contact ? 9 + static_cast<int>(contact_nodal_field_names().size()) : 9;
  std::vector<double> nodal_values(width * n_owned, 0.0);
  for (std::size_t node = 0; node < n_owned; ++node) {
    int column = 0;
    for (const auto* field :
         {&solver_.displacement(), &solver_.velocity(), &solver_.acceleration()})
      for (int d = 0; d < 3; ++d)
        nodal_values[width * node + column++] = (*field)[3 * node + d];
  }
  if (contact)
    add_contact_nodal_fields(solver_.contact(), nodal_values, width, 9);
  const auto nodal = gather_node_field(partition_, nodal_values, width);
  const SolidElements& elements = solver_.elements();
  std::vector<double> element_values(7 * static_cast<std::size_t>(partition_.n_local_elements()),
                                     0.0);
  for (LocalIndex e = 0; e < elements.n_elements; ++e) {
    double* s = &element_values[7 * static_cast<std::size_t>(elements.partition_index[e])];
    element_cauchy_stress(elements, e, solver_.displacement().data(), s);
    s[6] = von_mises(s);
  }
  const auto element = gather_element_field(partition_, element_values, 7);
  exodus_->write_step(time, nodal, element);
  next_snapshot_ = settings_.exodus_interval > 0 ? time + settings_.exodus_interval : 1e300;
}

void ExplicitRecorder::finish() {
  CsvWriter measurements(
      measurements_path_,
      {"history", "arrival_time_s", "peak_time_s", "peak_value", "period_s", "cycles"}, root_);
  for (std::size_t h = 0; h < events_.size(); ++h) {
    const HistoryEvents& e = events_[h];
    measurements.write_row(std::vector<std::string>{
        settings_.histories[h].name, CsvWriter::format(e.arrival_time),
        CsvWriter::format(e.peak_time), CsvWriter::format(e.peak_value),
        CsvWriter::format(e.period()), CsvWriter::format(std::max(0.0, e.crossings - 1))});
  }
  CsvWriter waves(wave_speeds_path_,
                  {"wave", "from", "to", "distance_m", "delay_s", "speed_m_per_s"}, root_);
  const Mesh& mesh = partition_.mesh();
  for (const WaveSpeedSpec& wave : settings_.wave_speeds) {
    std::size_t from = 0, to = 0;
    for (std::size_t h = 0; h < settings_.histories.size(); ++h) {
      if (settings_.histories[h].name == wave.from)
        from = h;
      if (settings_.histories[h].name == wave.to)
        to = h;
    }
    // Distance between the centroids of the two node sets.
    double distance2 = 0;
    for (int d = 0; d < 3; ++d) {
      double centre[2] = {0, 0};
      for (int end = 0; end < 2; ++end) {
        const auto& nodes =
            mesh.node_set(settings_.histories[end == 0 ? from : to].node_set, "", "").nodes;
        for (GlobalIndex node : nodes)
          centre[end] += mesh.coordinates[3 * node + d] / static_cast<double>(nodes.size());
      }
      distance2 += std::pow(centre[1] - centre[0], 2);
    }
    const auto event_time = [&](std::size_t h) {
      return wave.peak ? events_[h].peak_time : events_[h].arrival_time;
    };
    const double delay = event_time(to) - event_time(from);
    const bool measured =
        (wave.peak || (events_[from].arrival_time >= 0 && events_[to].arrival_time >= 0)) &&
        delay > 0;
    const double distance = std::sqrt(distance2);
    waves.write_row(std::vector<std::string>{
        wave.name, wave.from, wave.to, CsvWriter::format(distance), CsvWriter::format(delay),
        measured ? CsvWriter::format(distance / delay) : std::string("not measured")});
  }
  if (exodus_)
    exodus_->close();
}

std::vector<double> ExplicitRecorder::state() const {
  std::vector<double> values = {next_snapshot_, energy_put_in_,
                                static_cast<double>(energy_rows_.size()),
                                static_cast<double>(history_rows_.size())};
  for (const auto* rows : {&energy_rows_, &history_rows_})
    for (const auto& row : *rows) {
      values.push_back(static_cast<double>(row.size()));
      values.insert(values.end(), row.begin(), row.end());
    }
  for (const HistoryEvents& e : events_) {
    values.insert(values.end(),
                  {e.previous_time, e.previous_value, e.arrival_time, e.peak_time, e.peak_value,
                   e.first_crossing, e.last_crossing, e.crossings, e.started ? 1.0 : 0.0});
  }
  const std::vector<double> contact = contact_->state();
  values.insert(values.end(), contact.begin(), contact.end());
  return values;
}

void ExplicitRecorder::restore(const std::vector<double>& values) {
  std::size_t k = 0;
  next_snapshot_ = values.at(k++);
  energy_put_in_ = values.at(k++);
  const auto n_energy = static_cast<std::size_t>(values.at(k++));
  const auto n_history = static_cast<std::size_t>(values.at(k++));
  energy_rows_.clear();
  history_rows_.clear();
  for (auto [rows, count] : {std::pair{&energy_rows_, n_energy}, {&history_rows_, n_history}}) {
    for (std::size_t r = 0; r < count; ++r) {
      const auto size = static_cast<std::size_t>(values.at(k++));
      rows->emplace_back(values.begin() + static_cast<std::ptrdiff_t>(k),
                         values.begin() + static_cast<std::ptrdiff_t>(k + size));
      k += size;
    }
  }
  for (HistoryEvents& e : events_) {
    double* fields[8] = {&e.previous_time, &e.previous_value, &e.arrival_time,  &e.peak_time,
                         &e.peak_value,    &e.first_crossing, &e.last_crossing, &e.crossings};
    for (double* field : fields)
      *field = values.at(k++);
    e.started = values.at(k++) != 0;
  }
  contact_->restore(
      std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(k), values.end()));
  for (const auto& row : energy_rows_)
    energy_->write_row(row);
  for (const auto& row : history_rows_)
    histories_->write_row(row);
}

}  // namespace railfe
