#include "contact/geometry/contact_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railfe {

const ContactPoint& RigidContact::active(TrackSide side) const {
  const auto& both = parts[static_cast<int>(side)];
  if (both[1].valid() && (!both[0].valid() || both[1].gap < both[0].gap))
    return both[1];
  return both[0];
}

RigidContact solve_rigid_contact(const WheelRailGeometry& geometry, double lateral, double yaw,
                                 const RigidContact* start, int check_samples) {
  RigidContact state;
  state.lateral = lateral;
  if (start) {
    state.vertical = start->vertical;
    state.roll = start->roll;
  }
  WheelsetPose pose{lateral, state.vertical, state.roll, yaw};
  std::array<std::array<std::array<double, 2>, 2>, 2> from;
  for (int side = 0; side < 2; ++side)
    for (int part = 0; part < 2; ++part) {
      if (start) {
        from[side][part] = {start->parts[side][part].s_wheel, start->parts[side][part].s_rail};
      } else {
        const GapSample s =
            least_gap_sample(geometry, static_cast<TrackSide>(side), part == 1, pose);
        from[side][part] = {s.s_wheel, s.s_rail};
      }
    }
  const double r0 = geometry.wheelset().nominal_radius;
  int restarts = 0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    pose = {lateral, state.vertical, state.roll, yaw};
    double gap[2], jacobian[2][2];
    for (int side = 0; side < 2; ++side) {
      for (int part = 0; part < 2; ++part) {
        ContactPoint& p = state.parts[side][part];
        p = search_contact(geometry, static_cast<TrackSide>(side), part == 1, pose,
                           from[side][part][0], from[side][part][1]);
        from[side][part] = {p.s_wheel, p.s_rail};
      }
      const ContactPoint& a = state.active(static_cast<TrackSide>(side));
      gap[side] = a.gap;
      // Envelope theorem: the least gap moves with the wheel point at the fixed contact.
      jacobian[side][0] = a.normal.z;
      jacobian[side][1] = a.normal.y * -(a.rail_point.z - (state.vertical - r0)) +
                          a.normal.z * (a.rail_point.y - lateral);
    }
    state.iterations = iteration;
    if (!state.active(TrackSide::left).valid() || !state.active(TrackSide::right).valid())
      break;
    if (std::max(std::abs(gap[0]), std::abs(gap[1])) < 1e-12) {
      // A local minimum of each part is closed; where a sample of a part lies lower, the
      // contact has jumped to another minimum (two-point contact): restart there.
      bool jumped = false;
      for (int side = 0; side < 2 && check_samples > 0 && restarts < 4; ++side)
        for (int part = 0; part < 2; ++part) {
          const GapSample s = least_gap_sample(geometry, static_cast<TrackSide>(side), part == 1,
                                               pose, check_samples);
          if (s.gap < state.active(static_cast<TrackSide>(side)).gap - 1e-9) {
            from[side][part] = {s.s_wheel, s.s_rail};
            jumped = true;
          }
        }
      if (!jumped) {
        state.converged = true;
        break;
      }
      ++restarts;
      continue;
    }
    const double det = jacobian[0][0] * jacobian[1][1] - jacobian[0][1] * jacobian[1][0];
    double vertical_step = -(jacobian[1][1] * gap[0] - jacobian[0][1] * gap[1]) / det;
    double roll_step = -(-jacobian[1][0] * gap[0] + jacobian[0][0] * gap[1]) / det;
    // The least gap is only piecewise smooth in the pose (the contact can jump): a step that
    // would move a wheel by more than 1 mm is shortened, so Newton cannot overshoot into a
    // far-off penetration and cycle there.
    const double move = std::max(std::abs(vertical_step), std::abs(roll_step) * r0 * 2);
    if (move > 1e-3) {
      vertical_step *= 1e-3 / move;
      roll_step *= 1e-3 / move;
    }
    state.vertical += vertical_step;
    state.roll += roll_step;
  }
  return state;
}

ContactTable::ContactTable(const WheelRailGeometry& geometry, double max_shift, int count,
                           int check_samples) {
  count = std::max(count, 2);
  first_ = -max_shift;
  step_ = 2 * max_shift / (count - 1);
  rows_.resize(static_cast<std::size_t>(count));
  // Continuation from the last row that closed; a row that does not close from there is tried
  // once more from sampled starts, so one hard row does not spoil the rows beyond it.
  auto solve = [&](int i, const RigidContact* last_closed) {
    RigidContact row =
        solve_rigid_contact(geometry, first_ + step_ * i, 0, last_closed, check_samples);
    if (!row.converged && last_closed) {
      RigidContact fresh =
          solve_rigid_contact(geometry, first_ + step_ * i, 0, nullptr, check_samples);
      if (fresh.converged)
        row = fresh;
    }
    return row;
  };
  const int centre = count / 2;
  rows_[centre] = solve(centre, nullptr);
  for (int direction : {1, -1}) {
    const RigidContact* last_closed = rows_[centre].converged ? &rows_[centre] : nullptr;
    for (int i = centre + direction; i >= 0 && i < count; i += direction) {
      rows_[i] = solve(i, last_closed);
      if (rows_[i].converged)
        last_closed = &rows_[i];
    }
  }
  starts_.resize(rows_.size() * 8);
  for (std::size_t i = 0; i < rows_.size(); ++i)
    for (int side = 0; side < 2; ++side)
      for (int part = 0; part < 2; ++part) {
        starts_[8 * i + 4 * side + 2 * part] = rows_[i].parts[side][part].s_wheel;
        starts_[8 * i + 4 * side + 2 * part + 1] = rows_[i].parts[side][part].s_rail;
      }
}

std::pair<std::size_t, double> ContactTable::bracket(double lateral) const {
  const double position =
      std::clamp((lateral - first_) / step_, 0.0, static_cast<double>(rows_.size() - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(position), rows_.size() - 2);
  return {i, position - static_cast<double>(i)};
}

std::array<double, 2> ContactTable::start(TrackSide side, bool flange, double lateral) const {
  const auto [i, w] = bracket(lateral);
  const double* a = &starts_[8 * i + 4 * static_cast<int>(side) + 2 * (flange ? 1 : 0)];
  const double* b = a + 8;
  return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])};
}

double ContactTable::part_gap(TrackSide side, bool flange, double lateral) const {
  const auto [i, w] = bracket(lateral);
  const int s = static_cast<int>(side), part = flange ? 1 : 0;
  return (1 - w) * rows_[i].parts[s][part].gap + w * rows_[i + 1].parts[s][part].gap;
}

const ContactPoint& ContactTable::part_point(TrackSide side, bool flange, double lateral) const {
  const auto [i, w] = bracket(lateral);
  return rows_[w < 0.5 ? i : i + 1].parts[static_cast<int>(side)][flange ? 1 : 0];
}

double ContactTable::rolling_radius_difference(std::size_t i) const {
  return rows_[i].active(TrackSide::right).rolling_radius -
         rows_[i].active(TrackSide::left).rolling_radius;
}

double ContactTable::flange_contact_shift(TrackSide side) const {
  const bool to_right = side == TrackSide::right;
  const std::size_t centre = rows_.size() / 2;
  for (std::size_t k = 0; k <= centre; ++k) {
    const std::size_t i = to_right ? centre + k : centre - k;
    if (i >= rows_.size())
      break;
    if (rows_[i].active(side).flange)
      return rows_[i].lateral;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double ContactTable::half_contact_distance() const {
  const RigidContact& c = rows_[rows_.size() / 2];
  return (c.active(TrackSide::right).rail_point.y - c.active(TrackSide::left).rail_point.y) / 2;
}

double ContactTable::centred_rolling_radius() const {
  const RigidContact& c = rows_[rows_.size() / 2];
  return (c.active(TrackSide::right).rolling_radius + c.active(TrackSide::left).rolling_radius) / 2;
}

}  // namespace railfe
