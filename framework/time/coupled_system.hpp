#pragma once
/// \file
/// A structure and a vehicle side by side: one SecondOrderSystem whose unknowns are the
/// structure's followed by the vehicle's, with no matrix coupling between them (the direct
/// method couples them through constraint equations only, constraint_set.hpp). A linear structure
/// is factored once per set of coefficients; the small dense vehicle is re-formed every call.

#include <Eigen/Dense>

#include "framework/time/dense_system.hpp"
#include "framework/time/second_order_system.hpp"

namespace railfe {

/// Structure (any SecondOrderSystem, e.g. a Tpetra one) + vehicle (dense).
class CoupledSystem : public SecondOrderSystem {
 public:
  /// The pair; neither is owned and both must outlive this object.
  CoupledSystem(SecondOrderSystem& structure, DenseSecondOrderSystem& vehicle);

  /// n_structure() + the vehicle's unknowns.
  std::size_t n_unknowns() const override { return n_structure_ + n_vehicle_; }
  /// Whether both parts are linear.
  bool is_linear() const override { return structure_.is_linear() && vehicle_.is_linear(); }
  /// Both parts' f_int.
  void internal_force(const double* u, const double* v, double* force) override;
  /// Both parts' f_ext.
  void external_force(double time, double* force) override;
  /// Both parts' M x.
  void apply_mass(const double* x, double* y) override;
  /// Both parts' K_R x.
  void apply_rayleigh_stiffness(const double* x, double* y) override;
  /// Factors the structure when it is nonlinear, not yet factored or factored with other
  /// coefficients; forms the vehicle's matrix (DenseSecondOrderSystem::form_matrix()) on the
  /// same terms.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  /// Block-diagonal solve (the vehicle's matrix LU-factored on first use after factor()).
  void solve(const double* rhs, double* x) override;
  /// The structure's entries, then the vehicle's shifted by n_structure().
  void matrix_entries(std::vector<MatrixEntry>& entries) const override;
  /// The structure's dot product plus the vehicle's.
  double dot(const double* x, const double* y) const override;

  /// Number of structure unknowns (the first ones).
  std::size_t n_structure() const { return n_structure_; }
  /// The structure.
  SecondOrderSystem& structure() { return structure_; }
  /// The vehicle.
  DenseSecondOrderSystem& vehicle() { return vehicle_; }
  /// Number of structure factorizations so far (changes whenever the structure's A does).
  std::size_t structure_factorizations() const { return structure_factorizations_; }
  /// Number of times the vehicle's matrix was formed (changes whenever A_v does).
  std::size_t vehicle_versions() const { return vehicle_versions_; }

 private:
  SecondOrderSystem& structure_;
  DenseSecondOrderSystem& vehicle_;
  std::size_t n_structure_, n_vehicle_;
  std::size_t structure_factorizations_ = 0;
  bool structure_factored_ = false;
  MatrixCoefficients structure_coefficients_, vehicle_coefficients_;
  std::size_t vehicle_versions_ = 0;
  bool vehicle_lu_valid_ = false;
  Eigen::PartialPivLU<Eigen::MatrixXd> vehicle_lu_;
};

}  // namespace railfe
