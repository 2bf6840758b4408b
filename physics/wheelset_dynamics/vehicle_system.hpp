#pragma once
/// \file
/// A vehicle on its wheels: a DenseStructuralModel (car body, bogies, wheelsets and their
/// suspensions, linear) whose wheelset nodes each carry the four contact points of
/// WheelsetContacts. Unknowns: the model's, then twelve per wheelset for the contacts' internal
/// nodes (massless; rails tie them, so the multipliers are the contact forces). The wheelset
/// nodes' six motions are the contact element's (x, y, z, θx, θy, θz) in track axes (x forward,
/// y right, z down), as the vehicle mesh generator lays them out.

#include <memory>
#include <vector>

#include "framework/time/dense_system.hpp"
#include "physics/common/dense_structural_model.hpp"
#include "physics/wheelset_dynamics/wheelset_contacts.hpp"

namespace railfe {

/// The vehicle's equations (see the file comment).
class VehicleSystem : public DenseSecondOrderSystem {
 public:
  /// The vehicle \p model with a wheelset at each free node of \p wheelset_nodes (front to
  /// rear), on the profiles of \p geometry with contact \p settings, rolling at \p speed, under
  /// the loads \p weight (the model's length; gravity_load() of the model).
  VehicleSystem(const DenseStructuralModel& model, const std::vector<GlobalIndex>& wheelset_nodes,
                std::shared_ptr<const WheelRailGeometry> geometry,
                const WheelRailContactSettings& settings, double speed, Eigen::VectorXd weight);

  /// K u + C v of the model plus the contacts' internal forces.
  void internal_force(const double* u, const double* v, double* force) override;
  /// The weight.
  void external_force(double time, double* force) override;
  /// The model's K and C plus each active contact's tangent.
  void tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
               Eigen::MatrixXd& damping) override;
  /// A = c_m M + c_c C + c_k K of the model (kept while the coefficients hold) plus each active
  /// contact's share: a 90-row A in a third of the generic form's time.
  void form_matrix(const double* u, const double* v,
                   const MatrixCoefficients& coefficients) override;
  /// Forms A only (the internal nodes make A alone singular where a contact is open; the
  /// saddle-point solver eliminates them).
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  /// Not available: throws std::logic_error.
  void solve(const double* rhs, double* x) override;

  /// Number of wheelsets.
  int n_wheelsets() const { return static_cast<int>(wheelsets_.size()); }
  /// The contacts of wheelset \p index (front to rear); their unknowns() say where its motions
  /// and internal nodes are.
  WheelsetContacts& wheelset(int index) { return wheelsets_[index]; }
  /// Number of the model's unknowns (the internal nodes follow).
  Eigen::Index n_model_unknowns() const { return n_model_; }

 private:
  static Eigen::MatrixXd padded(const Eigen::MatrixXd& matrix, Eigen::Index n);

  Eigen::Index n_model_;
  Eigen::MatrixXd stiffness_, damping_;  // the model's, padded with the internal nodes' zeros
  Eigen::VectorXd weight_;
  Eigen::MatrixXd structural_;  // c_m M + c_c C + c_k K of the model, padded
  MatrixCoefficients structural_coefficients_{-1, -1, -1, -1};
  std::vector<WheelsetContacts> wheelsets_;
};

}  // namespace railfe
