#include "contact/geometry/elastic_wheelset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railfe {

namespace {

const char* patch_name(int side, int part) {
  static const char* names[2][2] = {{"left tread", "left flange"}, {"right tread", "right flange"}};
  return names[side][part];
}

// Hertz's stiffness K (N = K δ^{3/2}) of a point's relative curvatures; 0 when they are not both
// positive (no Hertzian contact there).
double hertz_stiffness(const ContactPoint& point, double modulus) {
  const double A = point.relative_curvature_rolling(), B = point.relative_curvature_lateral();
  if (!(A > 0 && B > 0))
    return 0;
  return hertz_contact(A, B, modulus, 1.0).stiffness;
}

}  // namespace

ElasticContact solve_elastic_contact(const WheelRailGeometry& geometry, const RigidContact& rigid,
                                     double yaw, double load, double modulus) {
  ElasticContact state;
  const double r0 = geometry.wheelset().nominal_radius;
  const double lateral = rigid.lateral;
  // Start below the rigid position by the approach of half the load on a rigid tread contact,
  // so both wheels penetrate and Newton's Jacobian is not singular at the first step.
  double start_approach = 1e-5;
  const ContactPoint& right = rigid.active(TrackSide::right);
  if (const double K = hertz_stiffness(right, modulus); K > 0)
    start_approach = std::pow(0.5 * load / K, 2.0 / 3.0);
  double vertical = rigid.vertical + start_approach / std::max(std::abs(right.normal.z), 0.2);
  double roll = rigid.roll;
  std::array<std::array<std::array<double, 2>, 2>, 2> from;
  for (int side = 0; side < 2; ++side)
    for (int part = 0; part < 2; ++part)
      from[side][part] = {rigid.parts[side][part].s_wheel, rigid.parts[side][part].s_rail};
  // The Jacobian keeps a small stiffness for a patch that has just lifted off, so it cannot turn
  // singular; the residual uses the true law.
  const double approach_floor = 1e-3 * start_approach;
  int restarts = 0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    state.iterations = iteration;
    const WheelsetPose pose{lateral, vertical, roll, yaw};
    state.pose = pose;
    const double centre_z = vertical - r0;
    double residual[2] = {load, 0}, jacobian[2][2] = {{0, 0}, {0, 0}};
    state.lateral_force = 0;
    for (int side = 0; side < 2; ++side)
      for (int part = 0; part < 2; ++part) {
        const TrackSide track_side = static_cast<TrackSide>(side);
        ContactPoint point = search_contact(geometry, track_side, part == 1, pose,
                                            from[side][part][0], from[side][part][1]);
        if (point.status == SearchStatus::not_converged ||
            point.status == SearchStatus::not_a_minimum) {
          const GapSample sample = least_gap_sample(geometry, track_side, part == 1, pose);
          point =
              search_contact(geometry, track_side, part == 1, pose, sample.s_wheel, sample.s_rail);
        }
        from[side][part] = {point.s_wheel, point.s_rail};
        ElasticPatch& patch = state.patches[side][part];
        patch = ElasticPatch{};
        patch.point = point;
        if (!point.valid())
          continue;
        const double arm_y = point.rail_point.y - lateral, arm_z = point.rail_point.z - centre_z;
        const double gap_rate[2] = {point.normal.z,
                                    -point.normal.y * arm_z + point.normal.z * arm_y};
        if (point.gap < 0) {
          try {
            patch.hertz =
                hertz_from_approach(point.relative_curvature_rolling(),
                                    point.relative_curvature_lateral(), modulus, -point.gap);
          } catch (const std::invalid_argument&) {
            state.failure = std::string("the ") + patch_name(side, part) +
                            " contact is not Hertzian (relative curvatures A = " +
                            std::to_string(point.relative_curvature_rolling()) +
                            " 1/m, B = " + std::to_string(point.relative_curvature_lateral()) +
                            " 1/m: conformal contact)";
            return state;
          }
          patch.force_y = patch.hertz.load * point.normal.y;
          patch.force_z = patch.hertz.load * point.normal.z;
          residual[0] += patch.force_z;
          residual[1] += arm_y * patch.force_z - arm_z * patch.force_y;
          state.lateral_force += patch.force_y;
          jacobian[1][0] += patch.force_y;  // the centre moves with the vertical position
        }
        // dN/dδ = 3/2 K δ^{1/2}, δ = -gap; the normal is held fixed (envelope theorem).
        if (point.gap < approach_floor) {
          const double K = hertz_stiffness(point, modulus);
          const double rate = 1.5 * K * std::sqrt(std::max(-point.gap, approach_floor));
          for (int k = 0; k < 2; ++k) {
            const double force_rate = -rate * gap_rate[k];
            jacobian[0][k] += force_rate * point.normal.z;
            jacobian[1][k] += force_rate * (arm_y * point.normal.z - arm_z * point.normal.y);
          }
        }
      }
    state.vertical_residual = residual[0];
    state.roll_residual = residual[1];
    const double gauge = geometry.track().gauge;
    if (std::abs(residual[0]) < 1e-10 * load && std::abs(residual[1]) < 1e-10 * load * gauge) {
      // A closed equilibrium on the tracked minima; where a sample of a part lies lower, the
      // contact has jumped (a new patch): go on from there.
      bool jumped = false;
      for (int side = 0; side < 2 && restarts < 4; ++side)
        for (int part = 0; part < 2; ++part) {
          const ContactPoint& point = state.patches[side][part].point;
          const GapSample sample =
              least_gap_sample(geometry, static_cast<TrackSide>(side), part == 1, pose, 100);
          const double found = point.valid() ? point.gap : std::numeric_limits<double>::max();
          if (sample.gap < 0 && sample.gap < found - 1e-9) {
            from[side][part] = {sample.s_wheel, sample.s_rail};
            jumped = true;
          }
        }
      if (!jumped) {
        state.converged = true;
        return state;
      }
      ++restarts;
      continue;
    }
    const double det = jacobian[0][0] * jacobian[1][1] - jacobian[0][1] * jacobian[1][0];
    if (!(std::abs(det) > 0) || !std::isfinite(det)) {
      state.failure = "the wheelset touches neither rail (singular equilibrium)";
      return state;
    }
    double vertical_step = -(jacobian[1][1] * residual[0] - jacobian[0][1] * residual[1]) / det;
    double roll_step = -(-jacobian[1][0] * residual[0] + jacobian[0][0] * residual[1]) / det;
    // Each step moves a wheel by 0.1 mm at most: the gap is only piecewise smooth in the pose.
    const double move = std::max(std::abs(vertical_step), std::abs(roll_step) * gauge / 2);
    if (move > 1e-4) {
      vertical_step *= 1e-4 / move;
      roll_step *= 1e-4 / move;
    }
    vertical += vertical_step;
    roll += roll_step;
  }
  state.failure = "Newton's method did not converge in 100 iterations";
  return state;
}

}  // namespace railfe
