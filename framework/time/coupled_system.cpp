#include "framework/time/coupled_system.hpp"

namespace railfe {

CoupledSystem::CoupledSystem(SecondOrderSystem& structure, DenseSecondOrderSystem& vehicle)
    : structure_(structure),
      vehicle_(vehicle),
      n_structure_(structure.n_unknowns()),
      n_vehicle_(vehicle.n_unknowns()) {}

void CoupledSystem::internal_force(const double* u, const double* v, double* force) {
  structure_.internal_force(u, v, force);
  vehicle_.internal_force(u + n_structure_, v + n_structure_, force + n_structure_);
}

void CoupledSystem::external_force(double time, double* force) {
  structure_.external_force(time, force);
  vehicle_.external_force(time, force + n_structure_);
}

void CoupledSystem::apply_mass(const double* x, double* y) {
  structure_.apply_mass(x, y);
  vehicle_.apply_mass(x + n_structure_, y + n_structure_);
}

void CoupledSystem::apply_rayleigh_stiffness(const double* x, double* y) {
  structure_.apply_rayleigh_stiffness(x, y);
  vehicle_.apply_rayleigh_stiffness(x + n_structure_, y + n_structure_);
}

void CoupledSystem::factor(const double* u, const double* v, const MatrixCoefficients& c) {
  const bool same = same_coefficients(structure_coefficients_, c);
  if (!structure_factored_ || !structure_.is_linear() || !same) {
    structure_.factor(u, v, c);
    structure_coefficients_ = c;
    structure_factored_ = true;
    ++structure_factorizations_;
  }
  const bool vehicle_same = same_coefficients(vehicle_coefficients_, c);
  if (vehicle_versions_ == 0 || !vehicle_.is_linear() || !vehicle_same) {
    vehicle_.form_matrix(u + n_structure_, v + n_structure_, c);
    vehicle_coefficients_ = c;
    ++vehicle_versions_;
    vehicle_lu_valid_ = false;
  }
}

void CoupledSystem::solve(const double* rhs, double* x) {
  structure_.solve(rhs, x);
  if (!vehicle_lu_valid_) {
    vehicle_lu_.compute(vehicle_.matrix());
    vehicle_lu_valid_ = true;
  }
  Eigen::Map<Eigen::VectorXd>(x + n_structure_, n_vehicle_) =
      vehicle_lu_.solve(Eigen::Map<const Eigen::VectorXd>(rhs + n_structure_, n_vehicle_));
}

void CoupledSystem::matrix_entries(std::vector<MatrixEntry>& entries) const {
  structure_.matrix_entries(entries);
  const std::size_t first = entries.size();
  vehicle_.matrix_entries(entries);
  for (std::size_t k = first; k < entries.size(); ++k) {
    entries[k].row += n_structure_;
    entries[k].column += n_structure_;
  }
}

double CoupledSystem::dot(const double* x, const double* y) const {
  double sum = structure_.dot(x, y);
  for (std::size_t i = n_structure_; i < n_unknowns(); ++i)
    sum += x[i] * y[i];
  return sum;
}

}  // namespace railfe
