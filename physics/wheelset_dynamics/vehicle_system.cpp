#include "physics/wheelset_dynamics/vehicle_system.hpp"

#include <stdexcept>
#include <string>

namespace railfe {

Eigen::MatrixXd VehicleSystem::padded(const Eigen::MatrixXd& matrix, Eigen::Index n) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  out.topLeftCorner(matrix.rows(), matrix.cols()) = matrix;
  return out;
}

VehicleSystem::VehicleSystem(const DenseStructuralModel& model,
                             const std::vector<GlobalIndex>& wheelset_nodes,
                             std::shared_ptr<const WheelRailGeometry> geometry,
                             const WheelRailContactSettings& settings, double speed,
                             Eigen::VectorXd weight)
    : DenseSecondOrderSystem(padded(
          model.mass(), model.n_unknowns() + 3 * n_wheelset_contacts *
                                                 static_cast<Eigen::Index>(wheelset_nodes.size()))),
      n_model_(model.n_unknowns()),
      stiffness_(padded(model.stiffness(), mass().rows())),
      damping_(padded(model.damping(), mass().rows())),
      weight_(Eigen::VectorXd::Zero(mass().rows())) {
  weight_.head(n_model_) = weight;
  for (std::size_t w = 0; w < wheelset_nodes.size(); ++w) {
    const Eigen::Index first = model.unknown_of(wheelset_nodes[w]);
    if (first < 0)
      throw std::invalid_argument(
          "VehicleSystem: wheelset node " + std::to_string(wheelset_nodes[w] + 1) +
          " is carried by a rigid link; a wheelset needs a node of its own");
    const WheelsetUnknowns unknowns{
        static_cast<std::size_t>(first),
        static_cast<std::size_t>(n_model_) + 3 * n_wheelset_contacts * w};
    wheelsets_.emplace_back(geometry, settings, unknowns, speed, 0.0);
  }
}

void VehicleSystem::internal_force(const double* u, const double* v, double* force) {
  const Eigen::Index n = mass().rows();
  Eigen::Map<const Eigen::VectorXd> uu(u, n_model_), vv(v, n_model_);
  Eigen::Map<Eigen::VectorXd> f(force, n);
  f.head(n_model_).noalias() = stiffness_.topLeftCorner(n_model_, n_model_) * uu;
  f.head(n_model_).noalias() += damping_.topLeftCorner(n_model_, n_model_) * vv;
  f.tail(n - n_model_).setZero();
  for (auto& wheelset : wheelsets_)
    wheelset.add_forces(u, v, force);
}

void VehicleSystem::external_force(double, double* force) {
  Eigen::Map<Eigen::VectorXd>(force, weight_.size()) = weight_;
}

void VehicleSystem::tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
                            Eigen::MatrixXd& damping) {
  stiffness = stiffness_;
  damping = damping_;
  for (auto& wheelset : wheelsets_)
    wheelset.add_tangent(u, v, stiffness, damping);
}

void VehicleSystem::form_matrix(const double* u, const double* v, const MatrixCoefficients& c) {
  if (!same_coefficients(c, structural_coefficients_)) {
    structural_ = c.mass * mass() + c.damping * damping_ + c.stiffness * stiffness_;
    structural_coefficients_ = c;
  }
  Eigen::MatrixXd& a = matrix_to_form();
  a = structural_;
  for (auto& wheelset : wheelsets_)
    wheelset.add_tangent_matrix(u, v, c.stiffness, c.damping, a);
}

void VehicleSystem::factor(const double* u, const double* v,
                           const MatrixCoefficients& coefficients) {
  form_matrix(u, v, coefficients);
}

void VehicleSystem::solve(const double*, double*) {
  throw std::logic_error("VehicleSystem: A alone may be singular; solve with its constraints");
}

}  // namespace railfe
