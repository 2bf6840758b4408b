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

// Start parameters (wheel, rail) of each side's and part's search.
using Starts = std::array<std::array<std::array<double, 2>, 2>, 2>;

// The patches, residuals and Jacobian of one pose.
struct Evaluation {
  ElasticContact state;
  double jacobian[2][2] = {{0, 0}, {0, 0}};
  Starts starts;
  // Scaled squared residual: the line search's merit.
  double merit = std::numeric_limits<double>::infinity();
};

class Equilibrium {
 public:
  Equilibrium(const WheelRailGeometry& geometry, double lateral, double yaw, double load,
              double modulus, double approach_floor)
      : geometry_(geometry),
        lateral_(lateral),
        yaw_(yaw),
        load_(load),
        modulus_(modulus),
        approach_floor_(approach_floor) {}

  // Searches every part at (vertical, roll) from \p starts and sums the patches' forces.
  Evaluation evaluate(double vertical, double roll, const Starts& starts) const {
    Evaluation e;
    e.starts = starts;
    ElasticContact& state = e.state;
    const WheelsetPose pose{lateral_, vertical, roll, yaw_};
    state.pose = pose;
    const double centre_z = vertical - geometry_.wheelset().nominal_radius;
    state.vertical_residual = load_;
    for (int side = 0; side < 2; ++side)
      for (int part = 0; part < 2; ++part) {
        const TrackSide track_side = static_cast<TrackSide>(side);
        ContactPoint point = search_contact(geometry_, track_side, part == 1, pose,
                                            starts[side][part][0], starts[side][part][1]);
        if (point.status == SearchStatus::not_converged ||
            point.status == SearchStatus::not_a_minimum) {
          const GapSample sample = least_gap_sample(geometry_, track_side, part == 1, pose);
          point =
              search_contact(geometry_, track_side, part == 1, pose, sample.s_wheel, sample.s_rail);
        }
        e.starts[side][part] = {point.s_wheel, point.s_rail};
        ElasticPatch& patch = state.patches[side][part];
        patch.point = point;
        if (!point.valid())
          continue;
        const double arm_y = point.rail_point.y - lateral_, arm_z = point.rail_point.z - centre_z;
        const double gap_rate[2] = {point.normal.z,
                                    -point.normal.y * arm_z + point.normal.z * arm_y};
        if (point.gap < 0) {
          try {
            patch.hertz =
                hertz_from_approach(point.relative_curvature_rolling(),
                                    point.relative_curvature_lateral(), modulus_, -point.gap);
          } catch (const std::invalid_argument&) {
            state.failure = std::string("the ") + patch_name(side, part) +
                            " contact is not Hertzian (relative curvatures A = " +
                            std::to_string(point.relative_curvature_rolling()) +
                            " 1/m, B = " + std::to_string(point.relative_curvature_lateral()) +
                            " 1/m: conformal contact)";
            return e;
          }
          patch.force_y = patch.hertz.load * point.normal.y;
          patch.force_z = patch.hertz.load * point.normal.z;
          state.vertical_residual += patch.force_z;
          state.roll_residual += arm_y * patch.force_z - arm_z * patch.force_y;
          state.lateral_force += patch.force_y;
          e.jacobian[1][0] += patch.force_y;  // the centre moves with the vertical position
        }
        // dN/dδ = 3/2 K δ^{1/2}, δ = -gap; the normal is held fixed (envelope theorem). A patch
        // that has just lifted off keeps a small stiffness, so the Jacobian stays regular.
        if (point.gap < approach_floor_) {
          const double rate = 1.5 * hertz_stiffness(point, modulus_) *
                              std::sqrt(std::max(-point.gap, approach_floor_));
          for (int k = 0; k < 2; ++k) {
            const double force_rate = -rate * gap_rate[k];
            e.jacobian[0][k] += force_rate * point.normal.z;
            e.jacobian[1][k] += force_rate * (arm_y * point.normal.z - arm_z * point.normal.y);
          }
        }
      }
    const double moment_scale = load_ * geometry_.track().gauge;
    e.merit = std::pow(state.vertical_residual / load_, 2) +
              std::pow(state.roll_residual / moment_scale, 2);
    return e;
  }

  // Whether \p e balances the load to the tolerance.
  bool balanced(const Evaluation& e) const {
    return std::abs(e.state.vertical_residual) < 1e-10 * load_ &&
           std::abs(e.state.roll_residual) < 1e-10 * load_ * geometry_.track().gauge;
  }

 private:
  const WheelRailGeometry& geometry_;
  double lateral_, yaw_, load_, modulus_, approach_floor_;
};

}  // namespace

ElasticContact solve_elastic_contact(const WheelRailGeometry& geometry, const RigidContact& rigid,
                                     double yaw, double load, double modulus) {
  // Start below the rigid position by the approach of half the load on the right wheel's rigid
  // contact, so both wheels penetrate and the first Jacobian is regular.
  double start_approach = 1e-5;
  const ContactPoint& right = rigid.active(TrackSide::right);
  if (const double K = hertz_stiffness(right, modulus); K > 0)
    start_approach = std::pow(0.5 * load / K, 2.0 / 3.0);
  double vertical = rigid.vertical + start_approach / std::max(std::abs(right.normal.z), 0.2);
  double roll = rigid.roll;
  Starts starts;
  for (int side = 0; side < 2; ++side)
    for (int part = 0; part < 2; ++part)
      starts[side][part] = {rigid.parts[side][part].s_wheel, rigid.parts[side][part].s_rail};
  const Equilibrium equilibrium(geometry, rigid.lateral, yaw, load, modulus, 1e-3 * start_approach);
  const double half_gauge = geometry.track().gauge / 2;
  Evaluation current = equilibrium.evaluate(vertical, roll, starts);
  int restarts = 0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    current.state.iterations = iteration;
    if (!current.state.failure.empty())
      return current.state;
    if (equilibrium.balanced(current)) {
      // A closed equilibrium on the tracked minima; where a sample of a part lies deeper, the
      // contact has jumped (a new patch): go on from there.
      bool jumped = false;
      for (int side = 0; side < 2 && restarts < 4; ++side)
        for (int part = 0; part < 2; ++part) {
          const ContactPoint& point = current.state.patches[side][part].point;
          const GapSample sample = least_gap_sample(geometry, static_cast<TrackSide>(side),
                                                    part == 1, current.state.pose, 100);
          const double found = point.valid() ? point.gap : std::numeric_limits<double>::max();
          if (sample.gap < 0 && sample.gap < found - 1e-9) {
            current.starts[side][part] = {sample.s_wheel, sample.s_rail};
            jumped = true;
          }
        }
      if (!jumped) {
        current.state.converged = true;
        return current.state;
      }
      ++restarts;
      current = equilibrium.evaluate(vertical, roll, current.starts);
      continue;
    }
    const double(&J)[2][2] = current.jacobian;
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(std::abs(det) > 0) || !std::isfinite(det)) {
      current.state.failure = "the wheelset touches neither rail (singular equilibrium)";
      return current.state;
    }
    const double R[2] = {current.state.vertical_residual, current.state.roll_residual};
    double vertical_step = -(J[1][1] * R[0] - J[0][1] * R[1]) / det;
    double roll_step = -(-J[1][0] * R[0] + J[0][0] * R[1]) / det;
    // A step moves a wheel by 0.1 mm at most (the gap is only piecewise smooth in the pose),
    // and is halved until the residual falls (the Jacobian holds the normals fixed).
    const double move = std::max(std::abs(vertical_step), std::abs(roll_step) * half_gauge);
    double fraction = move > 1e-4 ? 1e-4 / move : 1.0;
    Evaluation trial;
    for (int halving = 0; halving < 20; ++halving, fraction /= 2) {
      trial = equilibrium.evaluate(vertical + fraction * vertical_step, roll + fraction * roll_step,
                                   current.starts);
      if (trial.state.failure.empty() && trial.merit < (1 - 1e-4 * fraction) * current.merit)
        break;
    }
    if (!(trial.merit < current.merit)) {
      current.state.failure =
          "no step reduces the force and moment residuals (the patches change abruptly with "
          "the wheelset's position, as in conformal flange-root contact)";
      for (int side = 0; side < 2; ++side)
        if (!current.state.patches[side][0].loaded() && !current.state.patches[side][1].loaded())
          // A flange normal steeper than atan(e / r0) passes beyond the wheelset centre: its
          // moment would need a pulling force on the other wheel.
          current.state.failure = std::string("the ") + (side ? "right" : "left") +
                                  " wheel lifts off: no roll equilibrium with both wheels "
                                  "loaded at this lateral shift (a flange contact steeper than "
                                  "atan(e / r0) tips the wheelset over)";
      return current.state;
    }
    vertical = trial.state.pose.vertical;
    roll = trial.state.pose.roll;
    current = trial;
  }
  current.state.iterations = 100;
  current.state.failure = "Newton's method did not converge in 100 iterations";
  return current.state;
}

}  // namespace railfe
