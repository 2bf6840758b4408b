#include "physics/common/contact_tables.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/common/contact_pairs.hpp"

namespace railfe {

namespace {

using Vector = std::array<double, 3>;

double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

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

const std::vector<std::string>& contact_history_columns() {
  static const std::vector<std::string> columns = {
      "time_s",         "normal_force_N",    "tangential_1_N",    "tangential_2_N",  "force_x_N",
      "force_y_N",      "force_z_N",         "friction_bound_N",  "contact_area_m2", "active_nodes",
      "slipping_nodes", "max_penetration_m", "frictional_work_J", "stored_energy_J"};
  return columns;
}

std::vector<double> contact_history_row(double time, const PenaltyContactPair& pair) {
  const PenaltyPairTotals& totals = pair.totals();
  const auto frame = contact_frame(pair);
  return {time,
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
}

const std::vector<std::string>& contact_patch_columns() {
  static const std::vector<std::string> columns = {"time_s",
                                                   "node",
                                                   "x_m",
                                                   "y_m",
                                                   "z_m",
                                                   "s1_m",
                                                   "s2_m",
                                                   "pressure_Pa",
                                                   "shear_1_Pa",
                                                   "shear_2_Pa",
                                                   "slip_velocity_1_m/s",
                                                   "slip_velocity_2_m/s",
                                                   "slipping",
                                                   "gap_m",
                                                   "area_m2"};
  return columns;
}

std::vector<std::vector<double>> contact_patch_rows(double time, const PenaltyContactPair& pair,
                                                    const ContactPairs& contact) {
  std::vector<std::vector<double>> rows;
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
    rows.push_back({time, node, slave.point[0], slave.point[1], slave.point[2],
                    dot(offset, frame[1]), dot(offset, frame[2]), slave.normal_force / area,
                    dot(slave.tangential_force, frame[1]) / area,
                    dot(slave.tangential_force, frame[2]) / area,
                    dot(slave.slip_velocity, frame[1]), dot(slave.slip_velocity, frame[2]),
                    slave.slipping ? 1.0 : 0.0, slave.gap, area});
  }
  return rows;
}

const std::vector<std::string>& contact_nodal_field_names() {
  static const std::vector<std::string> names = {
      "contact_pressure",        "contact_shear_x",         "contact_shear_y",
      "contact_shear_z",         "contact_slip_velocity_x", "contact_slip_velocity_y",
      "contact_slip_velocity_z", "contact_status"};
  return names;
}

void add_contact_nodal_fields(const ContactPairs& contact, std::vector<double>& values, int width,
                              int offset) {
  for (const PenaltyContactPair& pair : contact.pairs()) {
    const auto& geometry = pair.geometry();
    for (std::size_t s = 0; s < pair.slaves().size(); ++s) {
      const SlaveContact& slave = pair.slaves()[s];
      const LocalIndex node = contact.owned_node(geometry.slave_nodes[s]);
      if (slave.face < 0 || node < 0)
        continue;
      double* row = &values[static_cast<std::size_t>(node) * width + offset];
      const double area = geometry.slave_area[s];
      row[0] += slave.normal_force / area;
      for (int d = 0; d < 3; ++d) {
        row[1 + d] += slave.tangential_force[d] / area;
        row[4 + d] += slave.slip_velocity[d];
      }
      row[7] = std::max(row[7], slave.slipping ? 2.0 : 1.0);
    }
  }
}

}  // namespace railfe
