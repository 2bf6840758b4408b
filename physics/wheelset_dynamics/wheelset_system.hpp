#pragma once
/// \file
/// A rigid wheelset on suspension springs to a frame that runs along the track at speed V, in
/// contact with two rails through four WheelRailContact points (tread and flange of each wheel),
/// each with its internal node: M a + f_int(u, v) = f_ext for 6 + 4 × 3 unknowns. The internal
/// nodes have no mass; RigidRails ties them to the rails, so the multipliers are the contact
/// forces (docs/theory.md, "The wheel–rail contact element").

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "contact/enforcement/wheel_rail_contact.hpp"
#include "framework/time/constraint_set.hpp"
#include "framework/time/dense_system.hpp"

namespace railfe {

/// Mass, inertia and loads of the wheelset.
struct WheelsetBody {
  double mass = 1500;         ///< m (kg)
  double roll_inertia = 800;  ///< about x (kg m²)
  double spin_inertia = 100;  ///< about the axle (kg m²)
  double yaw_inertia = 800;   ///< about z (kg m²)
  double axle_load = 0;       ///< vertical force on the axle boxes besides its weight (N, down)
  double gravity = 9.81;      ///< g (m/s²)
  /// Cant of the track (rad, positive with the left rail raised): the weight and the axle
  /// load, vertical in the world, have a share sin(cant) along the track's y.
  double cant = 0;
  /// Lateral force on the centre (N, to the right) against time; empty: none.
  std::function<double(double)> lateral_force;
};

/// The springs and dampers of each of the two axle boxes to the running frame.
struct AxleBoxSuspension {
  std::array<double, 3> stiffness{};  ///< along x, y, z (N/m)
  std::array<double, 3> damping{};    ///< along x, y, z (N s/m)
  double half_spacing = 1.0;          ///< lateral distance of each box from the centre (m)
  double frame_yaw = 0;  ///< yaw at which the springs are unstrained: an angle of attack (rad)
};

/// Index of the contact points: right tread, right flange, left tread, left flange.
constexpr int n_wheelset_contacts = 4;
/// Unknowns: the wheelset's 6, then 3 per contact point's internal node.
constexpr int n_wheelset_unknowns = 6 + 3 * n_wheelset_contacts;

/// The wheelset's equations (see the file comment).
class WheelsetSystem : public DenseSecondOrderSystem {
 public:
  /// The wheelset \p body on \p suspension, rolling at \p speed with nominal spin \p spin, on
  /// the profiles of \p geometry with contact \p settings.
  WheelsetSystem(std::shared_ptr<const WheelRailGeometry> geometry,
                 const WheelRailContactSettings& settings, const WheelsetBody& body,
                 const AxleBoxSuspension& suspension, double speed, double spin);

  /// Suspension forces plus the contacts' internal forces (each contact searched anew).
  void internal_force(const double* u, const double* v, double* force) override;
  /// Weight and axle load, down, and the lateral force.
  void external_force(double time, double* force) override;
  /// Suspension matrices plus each active contact's tangent.
  void tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
               Eigen::MatrixXd& damping) override;
  /// Forms A only: it is singular where an internal node carries no force, and the saddle-point
  /// solver factors it bordered by the constraints.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  /// Not available (A alone may be singular): throws std::logic_error.
  void solve(const double* rhs, double* x) override;

  /// The contact points' states at (u, v) (a search for each).
  std::array<ContactState, n_wheelset_contacts> contact_states(const double* u, const double* v);
  /// Contact point \p index.
  WheelRailContact& contact(int index) { return contacts_[index]; }
  /// Rolling speed V (m/s).
  double speed() const { return speed_; }
  /// Sets the nominal spin Ω about the axle (rad/s).
  void set_spin(double spin) {
    spin_ = spin;
    cached_u_.clear();
  }
  /// Switches the creep forces off (\p rolling false: the static balance) or on.
  void set_rolling(bool rolling) {
    rolling_ = rolling;
    cached_u_.clear();
  }

 private:
  ContactKinematics kinematics(int index, const double* u, const double* v) const;
  /// The contact states at (u, v): those of the last evaluation when (u, v) are the same and
  /// neither spin nor rolling changed since (Newton asks for forces and tangent at one iterate),
  /// else searched anew.
  const std::array<ContactState, n_wheelset_contacts>& states_at(const double* u, const double* v);
  static Eigen::MatrixXd mass_matrix(const WheelsetBody& body);

  WheelsetBody body_;
  Eigen::MatrixXd suspension_stiffness_, suspension_damping_;
  Eigen::VectorXd rest_;  // the unknowns at which the springs are unstrained
  std::vector<WheelRailContact> contacts_;
  double speed_, spin_;
  bool rolling_ = true;
  std::vector<double> cached_u_, cached_v_;  // the iterate of cached_states_
  std::array<ContactState, n_wheelset_contacts> cached_states_;
};

/// The rails as rigid lines with irregularities: each internal node's (x, y, z) equals the rail's
/// offset (0, lateral(s), vertical(s)) under the wheelset, s = start + V t.
class RigidRails : public ConstraintSet {
 public:
  /// Offsets of the running surfaces against s (either may be empty: zero); lateral to the
  /// right, vertical down.
  RigidRails(std::function<double(double)> lateral, std::function<double(double)> vertical,
             double start, double speed);
  /// Three rows per internal node.
  void rows_at(double time, ConstraintRows& rows) override;
  /// ġ and g̈ by central differences over ±1 mm of s.
  void rates(double time, const double* u, const double* v, std::size_t n_rows, double* velocity,
             double* acceleration) override;
  /// Lateral and vertical offsets at \p time.
  std::array<double, 2> offsets(double time) const;

 private:
  std::function<double(double)> lateral_, vertical_;
  double start_, speed_;
};

}  // namespace railfe
