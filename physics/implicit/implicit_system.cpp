#include "physics/implicit/implicit_system.hpp"

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>

#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/resources.hpp"

namespace railfe {

ImplicitSystem::ImplicitSystem(const DofMap& dofs, LinearModelMatrices matrices,
                               const std::vector<LocalIndex>& fixed, Expression load_scale,
                               std::unique_ptr<LinearSolver> solver, ProblemTraits traits)
    : dofs_(dofs),
      n_(static_cast<std::size_t>(dofs.n_owned_dofs())),
      matrices_(std::move(matrices)),
      fixed_(fixed),
      load_scale_(std::move(load_scale)),
      solver_(std::move(solver)),
      traits_(std::move(traits)),
      x_(Teuchos::rcp(new TpetraVector(dofs.owned_map()))),
      y_(Teuchos::rcp(new TpetraVector(dofs.owned_map()))) {}

void ImplicitSystem::mask(double* y) const {
  for (LocalIndex dof : fixed_)
    y[dof] = 0.0;
}

void ImplicitSystem::apply(const TpetraMatrix& matrix, const double* x, double* y) {
  {
    auto data = x_->getDataNonConst();
    std::copy_n(x, n_, data.getRawPtr());
  }
  matrix.apply(*x_, *y_);
  const auto data = y_->getData();
  std::copy_n(data.getRawPtr(), n_, y);
  mask(y);
}

void ImplicitSystem::internal_force(const double* u, const double* v, double* force) {
  apply(*matrices_.stiffness, u, force);
  if (!matrices_.damping.is_null()) {
    damping_force_.resize(n_);
    apply(*matrices_.damping, v, damping_force_.data());
    for (std::size_t i = 0; i < n_; ++i)
      force[i] += damping_force_[i];
  }
}

void ImplicitSystem::external_force(double time, double* force) {
  const double scale = load_scale_(0, 0, 0, time);
  const auto load = matrices_.load->getData();
  for (std::size_t i = 0; i < n_; ++i)
    force[i] = scale * load[i];
  if (time_load_)
    time_load_(time, force);
  mask(force);
}

void ImplicitSystem::apply_mass(const double* x, double* y) {
  apply(*matrices_.mass, x, y);
}

void ImplicitSystem::apply_rayleigh_stiffness(const double* x, double* y) {
  apply(*matrices_.stiffness, x, y);
}

void ImplicitSystem::factor(const double*, const double*, const MatrixCoefficients& c) {
  Stopwatch clock;
  effective_ =
      Tpetra::MatrixMatrix::add(c.mass, false, *matrices_.mass, c.stiffness + c.rayleigh_stiffness,
                                false, *matrices_.stiffness);
  if (!matrices_.damping.is_null() && c.damping != 0.0)
    effective_ =
        Tpetra::MatrixMatrix::add(1.0, false, *effective_, c.damping, false, *matrices_.damping);
  // Symmetric elimination of the fixed DOFs (value 0): rows and columns zeroed, diagonal kept.
  LinearConstraints constraints(dofs_, "");
  for (LocalIndex dof : fixed_)
    constraints.prescribe(dofs_.owned_map()->getGlobalElement(dof), 0.0);
  constraints.finalize();
  TpetraVector unused(dofs_.owned_map());
  effective_ = constraints.apply(effective_, unused);
  solver_->setup(effective_, traits_);
  factor_seconds_ += clock.seconds();
}

void ImplicitSystem::solve(const double* rhs, double* x) {
  Stopwatch clock;
  TpetraVector b(dofs_.owned_map());
  {
    auto data = b.getDataNonConst();
    std::copy_n(rhs, n_, data.getRawPtr());
    mask(data.getRawPtr());
  }
  TpetraVector solution(dofs_.owned_map());
  last_solve_ = solver_->solve(b, solution);
  const auto data = solution.getData();
  std::copy_n(data.getRawPtr(), n_, x);
  solve_seconds_ += clock.seconds();
}

double ImplicitSystem::dot(const double* x, const double* y) const {
  double sum = 0;
  for (std::size_t i = 0; i < n_; ++i)
    sum += x[i] * y[i];
  return dofs_.partition().comm().sum(sum);
}

double ImplicitSystem::kinetic_energy(const double* v) {
  std::vector<double> mv(n_);
  apply_mass(v, mv.data());
  return 0.5 * dot(v, mv.data());
}

double ImplicitSystem::strain_energy(const double* u) {
  std::vector<double> ku(n_);
  apply(*matrices_.stiffness, u, ku.data());
  return 0.5 * dot(u, ku.data());
}

}  // namespace railfe
