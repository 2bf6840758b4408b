#include "physics/explicit/contact_output.hpp"

#include <cmath>

#include "framework/output/csv_writer.hpp"
#include "framework/output/output_directory.hpp"
#include "physics/explicit/explicit_contact.hpp"
#include "physics/explicit/explicit_settings.hpp"
#include "physics/explicit/explicit_solver.hpp"

namespace railfe {

namespace {

using Vector = std::array<double, 3>;

double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The contact frame of a pair: n, t1, t2 (see the file comment).
std::array<Vector, 3> contact_frame(const PenaltyContactPair& pair) {
  Vector n = pair.totals().normal;
  Vector t1 = pair.settings().longitudinal;
  const double along = dot(t1, n);
  for (int d = 0; d < 3; ++d)
    t1[d] -= along * n[d];
  const double length = std::sqrt(dot(t1, t1));
  for (double& value : t1)
    value /= length;
  const Vector t2 = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                     n[0] * t1[1] - n[1] * t1[0]};
  return {n, t1, t2};
}

const std::vector<std::string> kHistoryColumns = {
    "time_s",         "normal_force_N",    "tangential_1_N",    "tangential_2_N",  "force_x_N",
    "force_y_N",      "force_z_N",         "friction_bound_N",  "contact_area_m2", "active_nodes",
    "slipping_nodes", "max_penetration_m", "frictional_work_J", "stored_energy_J"};

}  // namespace

ContactRecorder::ContactRecorder(const ExplicitSettings& settings, const ExplicitSolver& solver,
                                 OutputDirectory& output, const std::string& step_name, bool root)
    : settings_(settings), solver_(solver), output_(output), step_name_(step_name), root_(root) {
  for (const ContactPairSpec& pair : settings.contact_pairs) {
    histories_.push_back(std::make_unique<CsvWriter>(
        output.staging_path(step_name + "_contact_" + pair.name + ".csv"), kHistoryColumns, root_));
    // Registered now so that no other step can claim the names, written when their time comes.
    for (std::size_t k = 0; k < pair.patch_times.size(); ++k)
      output.staging_path(step_name + "_contact_" + pair.name + "_patch_" + std::to_string(k + 1) +
                          ".csv");
  }
  rows_.resize(settings.contact_pairs.size());
  next_patch_.assign(settings.contact_pairs.size(), 0);
}

ContactRecorder::~ContactRecorder() = default;

void ContactRecorder::record(bool force_row) {
  const ExplicitContact& contact = solver_.contact();
  const long long step = solver_.n_steps();
  const bool due = (force_row || step % settings_.history_interval == 0) && step != last_step_;
  for (std::size_t p = 0; p < contact.pairs().size(); ++p) {
    const PenaltyContactPair& pair = contact.pairs()[p];
    const auto& patch_times = settings_.contact_pairs[p].patch_times;
    // A patch is written at the first step that reaches its time.
    while (next_patch_[p] < patch_times.size() &&
           solver_.time() >= patch_times[next_patch_[p]] * (1 - 1e-12)) {
      write_patch(p, next_patch_[p]);
      ++next_patch_[p];
    }
    if (!due)
      continue;
    const PenaltyPairTotals& totals = pair.totals();
    const auto frame = contact_frame(pair);
    const std::vector<double> row = {solver_.time(),
                                     totals.normal_force,
                                     dot(totals.force, frame[1]),
                                     dot(totals.force, frame[2]),
                                     totals.force[0],
                                     totals.force[1],
                                     totals.force[2],
                                     totals.friction_bound,
                                     totals.area,
                                     static_cast<double>(totals.active),
                                     static_cast<double>(totals.slipping),
                                     totals.max_penetration,
                                     totals.frictional_work,
                                     totals.stored_energy};
    histories_[p]->write_row(row);
    if (root_)
      rows_[p].push_back(row);
  }
  if (due) {
    last_step_ = step;
    for (auto& history : histories_)
      history->flush();
  }
}

void ContactRecorder::write_patch(std::size_t p, std::size_t index) {
  const ExplicitContact& contact = solver_.contact();
  const PenaltyContactPair& pair = contact.pairs()[p];
  const std::string name = step_name_ + "_contact_" + pair.settings().name + "_patch_" +
                           std::to_string(index + 1) + ".csv";
  CsvWriter patch(
      output_.staging_path(name),
      {"time_s", "node", "x_m", "y_m", "z_m", "s1_m", "s2_m", "pressure_Pa", "shear_1_Pa",
       "shear_2_Pa", "slip_velocity_1_m/s", "slip_velocity_2_m/s", "slipping", "gap_m"},
      root_);
  const auto frame = contact_frame(pair);
  // Positions in the contact plane about the force-weighted centre of the patch.
  Vector centre{};
  double weight = 0;
  for (const SlaveContact& slave : pair.slaves()) {
    if (slave.face < 0)
      continue;
    for (int d = 0; d < 3; ++d)
      centre[d] += slave.normal_force * slave.point[d];
    weight += slave.normal_force;
  }
  if (weight > 0)
    for (double& value : centre)
      value /= weight;
  const auto& geometry = pair.geometry();
  for (std::size_t s = 0; s < pair.slaves().size(); ++s) {
    const SlaveContact& slave = pair.slaves()[s];
    if (slave.face < 0)
      continue;
    const double area = geometry.slave_area[s];
    Vector offset;
    for (int d = 0; d < 3; ++d)
      offset[d] = slave.point[d] - centre[d];
    const double node = static_cast<double>(contact.surface_node(geometry.slave_nodes[s]) + 1);
    patch.write_row(std::vector<double>{
        solver_.time(), node, slave.point[0], slave.point[1], slave.point[2], dot(offset, frame[1]),
        dot(offset, frame[2]), slave.normal_force / area,
        dot(slave.tangential_force, frame[1]) / area, dot(slave.tangential_force, frame[2]) / area,
        dot(slave.slip_velocity, frame[1]), dot(slave.slip_velocity, frame[2]),
        slave.slipping ? 1.0 : 0.0, slave.gap});
  }
}

std::vector<std::string> ContactRecorder::untouched_pairs() const {
  std::vector<std::string> names;
  const ExplicitContact& contact = solver_.contact();
  for (std::size_t p = 0; p < contact.pairs().size(); ++p)
    if (!contact.ever_touched(p))
      names.push_back(contact.pairs()[p].settings().name);
  return names;
}

std::vector<double> ContactRecorder::state() const {
  std::vector<double> values;
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    values.push_back(static_cast<double>(next_patch_[p]));
    values.push_back(static_cast<double>(rows_[p].size()));
    for (const auto& row : rows_[p])
      values.insert(values.end(), row.begin(), row.end());
  }
  return values;
}

void ContactRecorder::restore(const std::vector<double>& values) {
  std::size_t k = 0;
  const std::size_t width = kHistoryColumns.size();
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    next_patch_[p] = static_cast<std::size_t>(values.at(k++));
    const auto count = static_cast<std::size_t>(values.at(k++));
    rows_[p].clear();
    for (std::size_t r = 0; r < count; ++r) {
      rows_[p].emplace_back(values.begin() + static_cast<std::ptrdiff_t>(k),
                            values.begin() + static_cast<std::ptrdiff_t>(k + width));
      k += width;
    }
    for (const auto& row : rows_[p])
      histories_[p]->write_row(row);
  }
}

}  // namespace railfe
