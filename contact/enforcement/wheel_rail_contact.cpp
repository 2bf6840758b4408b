#include "contact/enforcement/wheel_rail_contact.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "contact/laws/creep_table.hpp"
#include "contact/laws/fastsim.hpp"
#include "contact/laws/saturation.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

using Vec3 = std::array<double, 3>;

// out (9 × 9, row-major) = scale · Jᵀ D J for J (3 × 9) and D (3 × 3, row-major).
void sandwich(const double J[3][9], const double* D, double scale, double* out) {
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      double sum = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          sum += J[k][i] * D[k * 3 + l] * J[l][j];
      out[i * 9 + j] = scale * sum;
    }
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The axle's direction after roll θx then yaw θz (WheelRailGeometry::locus()).
Vec3 axle_direction(double roll, double yaw) {
  return {-std::sin(yaw) * std::cos(roll), std::cos(yaw) * std::cos(roll), std::sin(roll)};
}

// Finite-difference steps: far above the search's tolerance (1e-12 in the wheel parameter),
// far below a penetration (~1e-4 m) and a creep velocity (~1e-3 m/s).
constexpr double position_step = 1e-8;
constexpr double velocity_step = 1e-6;

}  // namespace

std::string creep_theory_name(CreepTheory theory) {
  switch (theory) {
    case CreepTheory::table:
      return "table";
    case CreepTheory::linear:
      return "linear";
    case CreepTheory::shen_hedrick_elkins:
      return "shen-hedrick-elkins";
    case CreepTheory::polach:
      return "polach";
    case CreepTheory::fastsim:
      return "fastsim";
  }
  return "?";
}

CreepTheory creep_theory_from_name(const std::string& name) {
  for (CreepTheory theory :
       {CreepTheory::table, CreepTheory::linear, CreepTheory::shen_hedrick_elkins,
        CreepTheory::polach, CreepTheory::fastsim})
    if (creep_theory_name(theory) == name)
      return theory;
  throw std::invalid_argument("unknown creep theory '" + name + "'");
}

WheelRailContact::WheelRailContact(std::shared_ptr<const WheelRailGeometry> geometry,
                                   TrackSide side, bool flange,
                                   const WheelRailContactSettings& settings)
    : geometry_(std::move(geometry)), side_(side), flange_(flange), settings_(settings) {
  search_.use_trust_region = settings.trust_region;
  modulus_ = contact_modulus(settings.wheel, settings.rail);
  // Combined constants of two bodies (Kalker): 2/G = 1/G1 + 1/G2, ν/G = (ν1/G1 + ν2/G2)/2.
  const double g1 = settings.wheel.young / (2 * (1 + settings.wheel.poisson));
  const double g2 = settings.rail.young / (2 * (1 + settings.rail.poisson));
  shear_modulus_ = 2 / (1 / g1 + 1 / g2);
  poisson_ = shear_modulus_ * 0.5 * (settings.wheel.poisson / g1 + settings.rail.poisson / g2);
  if (settings.theory == CreepTheory::table &&
      std::abs(poisson_ - CreepTable::shipped().axes().poisson) > 1e-9)
    throw std::invalid_argument("the creep-force table is made for Poisson's ratio " +
                                std::to_string(CreepTable::shipped().axes().poisson) + ", not " +
                                std::to_string(poisson_));
}

std::string WheelRailContact::name() const {
  return std::string(side_ == TrackSide::left ? "left" : "right") +
         (flange_ ? " flange" : " tread");
}

void WheelRailContact::set_start(double s_wheel, double s_rail) {
  s_wheel_ = s_wheel;
  s_rail_ = s_rail;
  started_ = true;
}

void WheelRailContact::use_table(std::shared_ptr<const ContactTable> table) {
  table_ = std::move(table);
  search_.first = -1e300;
  search_.last = 1e300;
  if (!table_)
    return;
  // The stretch of this part that the rigid wheelset touches over the table's shifts.
  double least = 1e300, most = -1e300;
  for (const RigidContact& row : table_->rows()) {
    const ContactPoint& active = row.active(side_);
    if (row.converged && active.valid() && active.flange == flange_) {
      least = std::min(least, active.s_wheel);
      most = std::max(most, active.s_wheel);
    }
  }
  if (least > most)
    return;  // the table never touches this part: search all of it
  constexpr double margin = 1e-3;
  const auto part = geometry_->part_range(side_, flange_);
  if (part[0] == geometry_->flange_split(side_))
    search_.first = least - margin;  // the root lies at the part's start
  else
    search_.last = most + margin;
}

WheelsetPose WheelRailContact::relative_pose(const ContactKinematics& state) const {
  WheelsetPose pose;
  pose.lateral = state.wheelset_u[1] - state.node_u[1];
  pose.vertical = state.wheelset_u[2] - state.node_u[2];
  pose.roll = state.wheelset_u[3];
  pose.yaw = settings_.yaw_exact ? state.wheelset_u[5] : 0.0;
  return pose;
}

CreepForces WheelRailContact::creep_forces(const HertzContact& hertz, const Creepages& creep,
                                           double speed) const {
  const double mu = settings_.friction, G = shear_modulus_;
  try {
    if (settings_.theory == CreepTheory::table)
      return CreepTable::shipped().forces(hertz.a, hertz.b, G, poisson_, hertz.load, mu, creep);
    const KalkerCoefficients c = KalkerTable::shipped().at(hertz.a, hertz.b, poisson_);
    switch (settings_.theory) {
      case CreepTheory::linear:
        return kalker_linear(c, G, hertz.a, hertz.b, creep);
      case CreepTheory::shen_hedrick_elkins:
        return shen_hedrick_elkins(kalker_linear(c, G, hertz.a, hertz.b, creep), hertz.load, mu);
      case CreepTheory::polach: {
        PolachParameters parameters;
        parameters.friction = mu;
        parameters.rolling_speed = speed;
        CreepForces forces = polach(c, G, hertz.a, hertz.b, hertz.load, creep, parameters);
        forces.Mz = 0;  // Polach's model gives no spin moment
        return forces;
      }
      case CreepTheory::fastsim: {
        FastsimSettings fast;
        fast.cells_x = fast.strips = settings_.fastsim_cells;
        fast.fields = false;
        return fastsim(c, G, hertz.a, hertz.b, hertz.load, mu, creep, fast).forces;
      }
      default:
        break;
    }
  } catch (const std::invalid_argument& error) {
    std::ostringstream message;
    message << name() << ": the " << creep_theory_name(settings_.theory)
            << " creep theory cannot take this contact (a = " << hertz.a << " m, b = " << hertz.b
            << " m, a/b = " << hertz.a / hertz.b << ", N = " << hertz.load
            << " N): " << error.what();
    throw RunError(message.str());
  }
  return {};
}

bool WheelRailContact::offline() const {
  if (settings_.offline_table && !table_)
    throw std::logic_error("WheelRailContact: the offline-table model needs use_table()");
  return settings_.offline_table;
}

ContactPoint WheelRailContact::offline_point(const WheelsetPose& pose) const {
  // Beyond the table's shifts (a wheel climbing its flange past every rigid pose of the pair)
  // the point stays the table's last (start() clamps): continuous at the table's end, where a
  // switch to the online search would jump (TS 20 m: Newton stalled there at 0.978 s), and near
  // the truth on a steep flange, whose contact point hardly moves on the wheel until its tip.
  const auto start = table_->start(side_, flange_, pose.lateral);
  return contact_at(*geometry_, side_, flange_, pose, start[0], start[1]);
}

ContactState WheelRailContact::evaluate(const ContactKinematics& state) {
  const WheelsetPose pose = relative_pose(state);
  if (table_ && flange_) {
    // A flange this far from its rail at the rigid contact of this lateral position cannot
    // touch it: the elastic approach at the tread, the roll and the yaw of a running wheelset
    // close tenths of a millimetre of it. No search, the table's point (half the flange
    // searches of a vehicle's Newton iteration).
    const double gap = table_->part_gap(side_, true, pose.lateral);
    if (gap > kFarFlangeGap) {
      ContactPoint point = table_->part_point(side_, true, pose.lateral);
      point.gap = gap;
      ++far_flanges_;
      return forces_at(state, point, nullptr);
    }
  }
  if (offline()) {
    ++offline_points_;
    return forces_at(state, offline_point(pose), nullptr);
  }
  if (!started_) {
    const GapSample sample = least_gap_sample(*geometry_, side_, flange_, pose, 200, search_);
    set_start(sample.s_wheel, sample.s_rail);
  }
  ContactPoint point = search_contact(*geometry_, side_, flange_, pose, s_wheel_, s_rail_, search_);
  if (point.status == SearchStatus::not_converged || point.status == SearchStatus::not_a_minimum) {
    const GapSample sample = least_gap_sample(*geometry_, side_, flange_, pose, 200, search_);
    point =
        search_contact(*geometry_, side_, flange_, pose, sample.s_wheel, sample.s_rail, search_);
  }
  if (point.status == SearchStatus::not_converged) {
    std::ostringstream message;
    message << "the contact search of the " << name() << " failed (wheelset lateral "
            << pose.lateral << " m, vertical " << pose.vertical << " m, roll " << pose.roll
            << " rad relative to the rail) after " << point.iterations << " iterations";
    throw RunError(message.str());
  }
  if (table_) {
    const auto start = table_->start(side_, flange_, pose.lateral);
    if (std::abs(start[0] - s_wheel_) > 1e-3) {
      const ContactPoint other =
          search_contact(*geometry_, side_, flange_, pose, start[0], start[1], search_);
      const bool better = other.status == SearchStatus::converged &&
                          (point.status != SearchStatus::converged || other.gap < point.gap);
      if (better) {
        point = other;
        ++table_jumps_;
      }
    }
  }
  // A penetration at the narrowed stretch's edge (not the part's own end, where the other part
  // takes over) is a contact pinned there: it must not pass unseen.
  const bool at_edge = std::abs(point.s_wheel - search_.first) < 1e-12 ||
                       std::abs(point.s_wheel - search_.last) < 1e-12;
  if (point.status == SearchStatus::part_boundary && point.gap < 0 && at_edge) {
    point.status = SearchStatus::converged;
    ++edge_contacts_;
  }
  if (point.status == SearchStatus::converged)
    set_start(point.s_wheel, point.s_rail);
  return forces_at(state, point, nullptr);
}

ContactState WheelRailContact::forces_at(const ContactKinematics& state, const ContactPoint& point,
                                         const HertzContact* shape) const {
  const WheelsetPose pose = relative_pose(state);
  ContactState result;
  result.point = point;
  result.active = point.status == SearchStatus::converged && point.gap < 0;
  const Vec3 n{0, point.normal.y, point.normal.z};
  const Vec3 t{0, point.normal.z, -point.normal.y};  // n × x
  const double r0 = geometry_->wheelset().nominal_radius;
  // The wheel's point: the rail point moved back along the normal by the gap.
  result.position = {point.x, point.rail_point.y + point.gap * n[1] - pose.lateral,
                     point.rail_point.z + point.gap * n[2] - (pose.vertical - r0)};
  if (!result.active)
    return result;
  double A = point.relative_curvature_rolling(), B = point.relative_curvature_lateral();
  const double limit = settings_.curvature_ratio_limit;
  if (limit > 0 && std::max(A, B) > 0) {
    const double least = std::max(A, B) / limit;
    result.conformal = A < least || B < least;
    A = std::max(A, least);
    B = std::max(B, least);
  }
  if (!(A > 0 && B > 0)) {
    std::ostringstream message;
    message << name() << ": the profiles are not Hertzian at the contact point (relative "
            << "curvatures A = " << A << " 1/m, B = " << B << " 1/m; wheel parameter "
            << point.s_wheel << "); Hertz does not apply (a curvature ratio limit would raise "
            << "the smaller one)";
    throw RunError(message.str());
  }
  if (shape && shape->approach > 0) {
    // Hertz's ellipse keeps its shape for nearby curvatures: N = K δ^{3/2}, a and b ∝ δ^{1/2}.
    const double approach = -point.gap, ratio = std::sqrt(approach / shape->approach);
    result.hertz = *shape;
    result.hertz.approach = approach;
    result.hertz.load = shape->stiffness * approach * ratio * std::sqrt(shape->approach);
    result.hertz.a = shape->a * ratio;
    result.hertz.b = shape->b * ratio;
    result.hertz.pressure = shape->pressure * ratio;
  } else {
    result.hertz = hertz_from_approach(A, B, modulus_, -point.gap);
  }
  Vec3 force{result.hertz.load * n[0], result.hertz.load * n[1], result.hertz.load * n[2]};
  Vec3 moment{};
  if (state.speed > 0) {
    const auto& u = state.wheelset_u;
    const auto& v = state.wheelset_v;
    const Vec3 axle = axle_direction(u[3], u[5]);
    const double spin = state.spin + v[4];
    const Vec3 omega{spin * axle[0] + v[3], spin * axle[1], spin * axle[2] + v[5]};
    const Vec3 swept = cross(omega, result.position);
    const Vec3 slip{state.speed + v[0] + swept[0] - state.node_v[0],
                    v[1] + swept[1] - state.node_v[1], v[2] + swept[2] - state.node_v[2]};
    result.creepage = {slip[0] / state.speed, dot(slip, t) / state.speed,
                       dot(omega, n) / state.speed};
    result.creep = creep_forces(result.hertz, result.creepage, state.speed);
    for (int i = 0; i < 3; ++i) {
      force[i] += result.creep.Fx * (i == 0 ? 1.0 : 0.0) + result.creep.Fy * t[i];
      moment[i] = result.creep.Mz * n[i];
    }
  }
  result.force = force;
  const Vec3 lever = cross(result.position, force);
  for (int i = 0; i < 3; ++i)
    result.moment[i] = moment[i] + lever[i];
  return result;
}

void WheelRailContact::internal_forces(const ContactState& state, const ContactKinematics& at,
                                       double* wheelset, double* node) {
  // Generalized forces are the moment's components along the rotations' rates: θx about x,
  // θy about the axle (the spin), θz about z (docs/theory.md).
  const Vec3 axle = axle_direction(at.wheelset_u[3], at.wheelset_u[5]);
  for (int i = 0; i < 3; ++i) {
    wheelset[i] = -state.force[i];
    node[i] = state.force[i];
  }
  wheelset[3] = -state.moment[0];
  wheelset[4] = -dot(state.moment, axle);
  wheelset[5] = -state.moment[2];
}

void WheelRailContact::tangent(const ContactKinematics& state, const ContactState& at,
                               double* stiffness, double* damping) const {
  double base[9], shifted[9];
  internal_forces(at, state, base, base + 6);
  // The velocities act through the creepages alone, which are linear in them: the damping
  // comes from the creep theory's derivatives (creep_damping_matrix()), or is the seed's.
  const bool rolling = at.active && state.speed > 0;
  for (int pass = 0; pass < (rolling ? 1 : 2); ++pass) {
    double* matrix = pass == 0 ? stiffness : damping;
    for (int j = 0; j < 9; ++j) {
      if (pass == 0 && (j == 0 || j == 6 || j == 4)) {
        // Along the track nothing changes with position (a straight, uniform rail), nor with
        // the spin angle (a wheel of revolution).
        for (int i = 0; i < 9; ++i)
          matrix[i * 9 + j] = 0;
        continue;
      }
      if (pass == 0 && (j == 7 || j == 8)) {
        // The forces see the node's y and z only through the wheelset's pose relative to it
        // (relative_pose()): those columns are the wheelset's, negated.
        for (int i = 0; i < 9; ++i)
          matrix[i * 9 + j] = -matrix[i * 9 + (j - 6)];
        continue;
      }
      ContactKinematics moved = state;
      double step = pass == 0 ? position_step : velocity_step;
      if (pass == 0)
        (j < 6 ? moved.wheelset_u[j] : moved.node_u[j - 6]) += step;
      else
        (j < 6 ? moved.wheelset_v[j] : moved.node_v[j - 6]) += step;
      ContactPoint point = at.point;
      const WheelsetPose moved_pose = relative_pose(moved);
      if (pass == 0 && offline()) {
        // The derivative of the offline model is that of its own point, not of a search.
        point = offline_point(moved_pose);
      } else if (pass == 0) {
        // A moved position needs its own contact point, searched from the one at the base.
        const double s_wheel = at.point.s_wheel, s_rail = at.point.s_rail;
        point = search_contact(*geometry_, side_, flange_, moved_pose, s_wheel, s_rail, search_);
        // The derivative is that of this contact: a search that fails or lands on another
        // minimum (a step of 1e-8 cannot move the point by 0.1 mm) keeps the base point.
        if (point.status != SearchStatus::converged || std::abs(point.s_wheel - s_wheel) > 1e-4)
          point = at.point;
      }
      const ContactState other = forces_at(moved, point, &at.hertz);
      internal_forces(other, moved, shifted, shifted + 6);
      for (int i = 0; i < 9; ++i)
        matrix[i * 9 + j] = (shifted[i] - base[i]) / step;
    }
  }
  if (rolling) {
    if (settings_.kalker_damping)
      kalker_damping_matrix(state, at, damping);
    else
      creep_damping_matrix(state, at, damping);
  }
}

void WheelRailContact::creepage_rates(const ContactKinematics& state, const ContactState& at,
                                      double J[3][9]) {
  const Vec3 n{0, at.point.normal.y, at.point.normal.z};
  const Vec3 t{0, at.point.normal.z, -at.point.normal.y};
  const Vec3 x{1, 0, 0}, ez{0, 0, 1};
  const Vec3 axle = axle_direction(state.wheelset_u[3], state.wheelset_u[5]);
  const Vec3& r = at.position;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 9; ++i)
      J[k][i] = 0;
  const Vec3 directions[2] = {x, t};
  const Vec3 swept[3] = {cross(x, r), cross(axle, r), cross(ez, r)};
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < 3; ++i) {
      J[row][i] = directions[row][i];
      J[row][6 + i] = -directions[row][i];
      J[row][3 + i] = dot(swept[i], directions[row]);
    }
  }
  J[2][3] = dot(x, n);
  J[2][4] = dot(axle, n);
  J[2][5] = dot(ez, n);
}

void WheelRailContact::creep_damping_matrix(const ContactKinematics& state, const ContactState& at,
                                            double* damping) const {
  double J[3][9];
  creepage_rates(state, at, J);
  // ∂F/∂c by forward differences; steps of 1e-7 in the creepages (ξ, η ~ 1e-3, φ ~ 0.1 1/m).
  const double steps[3] = {1e-7, 1e-7, 1e-6};
  double dF[3][3];
  for (int l = 0; l < 3; ++l) {
    Creepages moved = at.creepage;
    (l == 0 ? moved.longitudinal : l == 1 ? moved.lateral : moved.spin) += steps[l];
    const CreepForces f = creep_forces(at.hertz, moved, state.speed);
    dF[0][l] = (f.Fx - at.creep.Fx) / steps[l];
    dF[1][l] = (f.Fy - at.creep.Fy) / steps[l];
    dF[2][l] = (f.Mz - at.creep.Mz) / steps[l];
  }
  // f_int = −Jᵀ F and c = J v / V: ∂f_int/∂v = −Jᵀ (∂F/∂c) J / V.
  const double D[9] = {dF[0][0], dF[0][1], dF[0][2], dF[1][0], dF[1][1],
                       dF[1][2], dF[2][0], dF[2][1], dF[2][2]};
  sandwich(J, D, -1 / state.speed, damping);
}

void WheelRailContact::kalker_damping_matrix(const ContactKinematics& state, const ContactState& at,
                                             double* damping) const {
  double J[3][9];
  creepage_rates(state, at, J);
  const KalkerCoefficients c = KalkerTable::shipped().at(at.hertz.a, at.hertz.b, poisson_);
  const auto D = kalker_damping(c, shear_modulus_, at.hertz.a, at.hertz.b, state.speed);
  // f_int = −Jᵀ F and F = −D J v (+ constants), so C = Jᵀ D J.
  sandwich(J, D.data(), 1.0, damping);
}

}  // namespace railfe
