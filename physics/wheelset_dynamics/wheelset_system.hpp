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

#include "framework/time/constraint_set.hpp"
#include "framework/time/dense_system.hpp"
#include "physics/wheelset_dynamics/wheelset_contacts.hpp"

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
  std::array<ContactState, n_wheelset_contacts> contact_states(const double* u, const double* v) {
    return contacts_.states(u, v);
  }
  /// Contact point \p index.
  WheelRailContact& contact(int index) { return contacts_.contact(index); }
  /// Rolling speed V (m/s).
  double speed() const { return contacts_.speed(); }
  /// Sets the nominal spin Ω about the axle (rad/s).
  void set_spin(double spin) { contacts_.set_spin(spin); }
  /// Switches the creep forces off (\p rolling false: the static balance) or on.
  void set_rolling(bool rolling) { contacts_.set_rolling(rolling); }

 private:
  static Eigen::MatrixXd mass_matrix(const WheelsetBody& body);

  WheelsetBody body_;
  Eigen::MatrixXd suspension_stiffness_, suspension_damping_;
  Eigen::VectorXd rest_;  // the unknowns at which the springs are unstrained
  WheelsetContacts contacts_;
};

/// One wheelset on RigidRails: where it runs and where its internal nodes are.
struct RailedWheelset {
  double position = 0;    ///< its distance ahead of the reference point s = start + V t (m)
  std::size_t nodes = 6;  ///< first unknown of its internal nodes (12, in contact order)
};

/// The rails as rigid lines with irregularities: each internal node's (x, y, z) equals the rail's
/// offset (0, lateral(s), vertical(s)) under its wheelset, s = start + position + V t.
class RigidRails : public ConstraintSet {
 public:
  /// Offsets of the running surfaces against s (either may be empty: zero); lateral to the
  /// right, vertical down; the rows of \p wheelsets in turn (default: one wheelset at the
  /// reference point, nodes from unknown 6 on).
  RigidRails(std::function<double(double)> lateral, std::function<double(double)> vertical,
             double start, double speed,
             std::vector<RailedWheelset> wheelsets = {RailedWheelset{}});
  /// Three rows per internal node.
  void rows_at(double time, ConstraintRows& rows) override;
  /// ġ and g̈ by central differences over ±1 mm of s.
  void rates(double time, const double* u, const double* v, std::size_t n_rows, double* velocity,
             double* acceleration) override;
  /// Lateral and vertical offsets at \p time, \p position ahead of the reference point.
  std::array<double, 2> offsets(double time, double position = 0) const;

 private:
  std::function<double(double)> lateral_, vertical_;
  double start_, speed_;
  std::vector<RailedWheelset> wheelsets_;
};

}  // namespace railfe
