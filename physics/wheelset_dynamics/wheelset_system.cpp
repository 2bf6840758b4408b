#include "physics/wheelset_dynamics/wheelset_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railfe {

namespace {

constexpr TrackSide kSides[n_wheelset_contacts] = {TrackSide::right, TrackSide::right,
                                                   TrackSide::left, TrackSide::left};
constexpr bool kFlange[n_wheelset_contacts] = {false, true, false, true};

// The 6 × 6 matrix of two axle boxes at ±d with springs (or dampers) \p k along x, y, z: the
// translations, roll from the vertical ones and yaw from the longitudinal ones.
Eigen::MatrixXd axle_box_matrix(const std::array<double, 3>& k, double d) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n_wheelset_unknowns, n_wheelset_unknowns);
  for (int i = 0; i < 3; ++i)
    m(i, i) = 2 * k[i];
  m(3, 3) = 2 * k[2] * d * d;
  m(5, 5) = 2 * k[0] * d * d;
  return m;
}

}  // namespace

Eigen::MatrixXd WheelsetSystem::mass_matrix(const WheelsetBody& body) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n_wheelset_unknowns, n_wheelset_unknowns);
  m(0, 0) = m(1, 1) = m(2, 2) = body.mass;
  m(3, 3) = body.roll_inertia;
  m(4, 4) = body.spin_inertia;
  m(5, 5) = body.yaw_inertia;
  return m;
}

WheelsetSystem::WheelsetSystem(std::shared_ptr<const WheelRailGeometry> geometry,
                               const WheelRailContactSettings& settings, const WheelsetBody& body,
                               const AxleBoxSuspension& suspension, double speed, double spin)
    : DenseSecondOrderSystem(mass_matrix(body)),
      body_(body),
      suspension_stiffness_(axle_box_matrix(suspension.stiffness, suspension.half_spacing)),
      suspension_damping_(axle_box_matrix(suspension.damping, suspension.half_spacing)),
      rest_(Eigen::VectorXd::Zero(n_wheelset_unknowns)),
      speed_(speed),
      spin_(spin) {
  rest_(5) = suspension.frame_yaw;
  for (int k = 0; k < n_wheelset_contacts; ++k)
    contacts_.emplace_back(geometry, kSides[k], kFlange[k], settings);
}

ContactKinematics WheelsetSystem::kinematics(int index, const double* u, const double* v) const {
  ContactKinematics state;
  for (int i = 0; i < 6; ++i) {
    state.wheelset_u[i] = u[i];
    state.wheelset_v[i] = v[i];
  }
  for (int i = 0; i < 3; ++i) {
    state.node_u[i] = u[6 + 3 * index + i];
    state.node_v[i] = v[6 + 3 * index + i];
  }
  state.speed = rolling_ ? speed_ : 0.0;
  state.spin = rolling_ ? spin_ : 0.0;
  return state;
}

const std::array<ContactState, n_wheelset_contacts>& WheelsetSystem::states_at(const double* u,
                                                                               const double* v) {
  const std::size_t n = n_wheelset_unknowns;
  const bool same = cached_u_.size() == n && std::equal(u, u + n, cached_u_.begin()) &&
                    std::equal(v, v + n, cached_v_.begin());
  if (!same) {
    for (int k = 0; k < n_wheelset_contacts; ++k)
      cached_states_[k] = contacts_[k].evaluate(kinematics(k, u, v));
    cached_u_.assign(u, u + n);
    cached_v_.assign(v, v + n);
  }
  return cached_states_;
}

void WheelsetSystem::internal_force(const double* u, const double* v, double* force) {
  const Eigen::Index n = n_wheelset_unknowns;
  Eigen::Map<const Eigen::VectorXd> uu(u, n), vv(v, n);
  Eigen::Map<Eigen::VectorXd>(force, n) =
      suspension_stiffness_ * (uu - rest_) + suspension_damping_ * vv;
  const auto& states = states_at(u, v);
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    const ContactKinematics state = kinematics(k, u, v);
    const ContactState& c = states[k];
    double wheelset[6], node[3];
    WheelRailContact::internal_forces(c, state, wheelset, node);
    for (int i = 0; i < 6; ++i)
      force[i] += wheelset[i];
    for (int i = 0; i < 3; ++i)
      force[6 + 3 * k + i] += node[i];
  }
}

void WheelsetSystem::external_force(double time, double* force) {
  for (int i = 0; i < n_wheelset_unknowns; ++i)
    force[i] = 0;
  const double weight = body_.mass * body_.gravity + body_.axle_load;
  force[1] = weight * std::sin(body_.cant);
  force[2] = weight * std::cos(body_.cant);
  if (body_.lateral_force)
    force[1] += body_.lateral_force(time);
}

void WheelsetSystem::tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
                             Eigen::MatrixXd& damping) {
  stiffness = suspension_stiffness_;
  damping = suspension_damping_;
  const auto& states = states_at(u, v);
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    const ContactKinematics state = kinematics(k, u, v);
    const ContactState& c = states[k];
    if (!c.active)
      continue;
    double kt[81], ct[81];
    contacts_[k].tangent(state, c, kt, ct);
    // Local unknowns 0..5 are the wheelset's, 6..8 the node's.
    auto global = [k](int i) { return i < 6 ? i : 6 + 3 * k + (i - 6); };
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        stiffness(global(i), global(j)) += kt[i * 9 + j];
        damping(global(i), global(j)) += ct[i * 9 + j];
      }
  }
}

void WheelsetSystem::factor(const double* u, const double* v,
                            const MatrixCoefficients& coefficients) {
  form_matrix(u, v, coefficients);
}

void WheelsetSystem::solve(const double*, double*) {
  throw std::logic_error("WheelsetSystem: A alone may be singular; solve with its constraints");
}

std::array<ContactState, n_wheelset_contacts> WheelsetSystem::contact_states(const double* u,
                                                                             const double* v) {
  return states_at(u, v);
}

RigidRails::RigidRails(std::function<double(double)> lateral,
                       std::function<double(double)> vertical, double start, double speed)
    : lateral_(std::move(lateral)), vertical_(std::move(vertical)), start_(start), speed_(speed) {}

std::array<double, 2> RigidRails::offsets(double time) const {
  const double s = start_ + speed_ * time;
  return {lateral_ ? lateral_(s) : 0.0, vertical_ ? vertical_(s) : 0.0};
}

void RigidRails::rows_at(double time, ConstraintRows& rows) {
  const auto offset = offsets(time);
  for (int k = 0; k < n_wheelset_contacts; ++k)
    for (int i = 0; i < 3; ++i) {
      rows.start_row(i == 0 ? 0.0 : offset[i - 1]);
      rows.add_entry(6 + 3 * k + i, 1.0);
    }
}

void RigidRails::rates(double time, const double*, const double*, std::size_t n_rows,
                       double* velocity, double* acceleration) {
  const double h = 1e-3 / std::max(speed_, 1e-9);
  const auto minus = offsets(time - h), centre = offsets(time), plus = offsets(time + h);
  for (std::size_t row = 0; row < n_rows; ++row) {
    const int i = static_cast<int>(row % 3);
    if (i == 0) {
      velocity[row] = acceleration[row] = 0;
      continue;
    }
    velocity[row] = (plus[i - 1] - minus[i - 1]) / (2 * h);
    acceleration[row] = (plus[i - 1] - 2 * centre[i - 1] + minus[i - 1]) / (h * h);
  }
}

}  // namespace railfe
