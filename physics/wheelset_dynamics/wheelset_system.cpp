#include "physics/wheelset_dynamics/wheelset_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railfe {

namespace {

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
      contacts_(std::move(geometry), settings, WheelsetUnknowns{0, 6}, speed, spin) {
  rest_(5) = suspension.frame_yaw;
}

void WheelsetSystem::internal_force(const double* u, const double* v, double* force) {
  const Eigen::Index n = n_wheelset_unknowns;
  Eigen::Map<const Eigen::VectorXd> uu(u, n), vv(v, n);
  Eigen::Map<Eigen::VectorXd>(force, n) =
      suspension_stiffness_ * (uu - rest_) + suspension_damping_ * vv;
  contacts_.add_forces(u, v, force);
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
  contacts_.add_tangent(u, v, stiffness, damping);
}

void WheelsetSystem::factor(const double* u, const double* v,
                            const MatrixCoefficients& coefficients) {
  form_matrix(u, v, coefficients);
}

void WheelsetSystem::solve(const double*, double*) {
  throw std::logic_error("WheelsetSystem: A alone may be singular; solve with its constraints");
}

RigidRails::RigidRails(std::function<double(double)> lateral,
                       std::function<double(double)> vertical, double start, double speed,
                       std::vector<RailedWheelset> wheelsets)
    : lateral_(std::move(lateral)),
      vertical_(std::move(vertical)),
      start_(start),
      speed_(speed),
      wheelsets_(std::move(wheelsets)) {}

std::array<double, 2> RigidRails::offsets(double time, double position) const {
  const double s = start_ + position + speed_ * time;
  return {lateral_ ? lateral_(s) : 0.0, vertical_ ? vertical_(s) : 0.0};
}

void RigidRails::rows_at(double time, ConstraintRows& rows) {
  for (const RailedWheelset& wheelset : wheelsets_) {
    const auto offset = offsets(time, wheelset.position);
    for (int k = 0; k < n_wheelset_contacts; ++k)
      for (int i = 0; i < 3; ++i) {
        rows.start_row(i == 0 ? 0.0 : offset[i - 1]);
        rows.add_entry(wheelset.nodes + 3 * k + i, 1.0);
      }
  }
}

void RigidRails::rates(double time, const double*, const double*, std::size_t n_rows,
                       double* velocity, double* acceleration) {
  const double h = 1e-3 / std::max(speed_, 1e-9);
  const std::size_t per_wheelset = 3 * n_wheelset_contacts;
  for (std::size_t w = 0; w < wheelsets_.size(); ++w) {
    const double at = wheelsets_[w].position;
    const auto minus = offsets(time - h, at), centre = offsets(time, at),
               plus = offsets(time + h, at);
    for (std::size_t row = w * per_wheelset; row < std::min(n_rows, (w + 1) * per_wheelset);
         ++row) {
      const int i = static_cast<int>(row % 3);
      if (i == 0) {
        velocity[row] = acceleration[row] = 0;
        continue;
      }
      velocity[row] = (plus[i - 1] - minus[i - 1]) / (2 * h);
      acceleration[row] = (plus[i - 1] - 2 * centre[i - 1] + minus[i - 1]) / (h * h);
    }
  }
}

}  // namespace railfe
