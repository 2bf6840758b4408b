#include "framework/time/dense_system.hpp"

#include <limits>

#include "framework/base/error.hpp"

namespace railfe {

using Vector = Eigen::Map<Eigen::VectorXd>;
using ConstVector = Eigen::Map<const Eigen::VectorXd>;

DenseSecondOrderSystem::DenseSecondOrderSystem(Eigen::MatrixXd mass) : mass_(std::move(mass)) {}

void DenseSecondOrderSystem::apply_mass(const double* x, double* y) {
  Vector(y, mass_.rows()) = mass_ * ConstVector(x, mass_.rows());
}

void DenseSecondOrderSystem::apply_rayleigh_stiffness(const double* x, double* y) {
  if (rayleigh_.rows() != mass_.rows())
    SecondOrderSystem::apply_rayleigh_stiffness(x, y);
  Vector(y, mass_.rows()) = rayleigh_ * ConstVector(x, mass_.rows());
}

void DenseSecondOrderSystem::form_matrix(const double* u, const double* v,
                                         const MatrixCoefficients& c) {
  const Eigen::Index n = mass_.rows();
  tangent_stiffness_.setZero(n, n);
  tangent_damping_.setZero(n, n);
  tangent(u, v, tangent_stiffness_, tangent_damping_);
  matrix_ = c.mass * mass_ + c.damping * tangent_damping_ + c.stiffness * tangent_stiffness_;
  if (c.rayleigh_stiffness != 0)
    matrix_ += c.rayleigh_stiffness * rayleigh_;
}

void DenseSecondOrderSystem::factor(const double* u, const double* v, const MatrixCoefficients& c) {
  form_matrix(u, v, c);
  lu_.compute(matrix_);
  if (!(lu_.rcond() > std::numeric_limits<double>::epsilon()))
    throw RunError("the effective matrix of the time step is singular");
}

void DenseSecondOrderSystem::solve(const double* rhs, double* x) {
  Vector(x, mass_.rows()) = lu_.solve(ConstVector(rhs, mass_.rows()));
}

void DenseSecondOrderSystem::matrix_entries(std::vector<MatrixEntry>& entries) const {
  for (Eigen::Index j = 0; j < matrix_.cols(); ++j)
    for (Eigen::Index i = 0; i < matrix_.rows(); ++i)
      if (matrix_(i, j) != 0)
        entries.push_back(
            {static_cast<std::size_t>(i), static_cast<std::size_t>(j), matrix_(i, j)});
}

LinearDenseSystem::LinearDenseSystem(Eigen::MatrixXd mass, Eigen::MatrixXd damping,
                                     Eigen::MatrixXd stiffness,
                                     std::function<void(double, double*)> load)
    : DenseSecondOrderSystem(std::move(mass)),
      damping_(std::move(damping)),
      stiffness_(std::move(stiffness)),
      load_(std::move(load)) {
  set_rayleigh_stiffness(stiffness_);
}

void LinearDenseSystem::internal_force(const double* u, const double* v, double* force) {
  const Eigen::Index n = stiffness_.rows();
  Vector(force, n) = stiffness_ * ConstVector(u, n) + damping_ * ConstVector(v, n);
}

void LinearDenseSystem::external_force(double time, double* force) {
  if (load_)
    load_(time, force);
  else
    Vector(force, stiffness_.rows()).setZero();
}

void LinearDenseSystem::tangent(const double*, const double*, Eigen::MatrixXd& stiffness,
                                Eigen::MatrixXd& damping) {
  stiffness = stiffness_;
  damping = damping_;
}

}  // namespace railfe
