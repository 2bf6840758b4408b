#pragma once
/// \file
/// The four potential contact points of one rigid wheelset (tread and flange of each wheel),
/// each a WheelRailContact with its internal node, as both the single wheelset and the vehicle
/// use them: forces and tangents added at the unknowns where a system keeps the wheelset's six
/// motions and the nodes' twelve, the searches done once per iterate.

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <vector>

#include "contact/enforcement/wheel_rail_contact.hpp"

namespace railfe {

/// Index of the contact points: right tread, right flange, left tread, left flange.
constexpr int n_wheelset_contacts = 4;

/// Names of the contact points in outputs, in their index order.
extern const char* const wheelset_contact_names[n_wheelset_contacts];

/// Vertical (Q, up on the wheel) and lateral (Y, towards the track centre on the wheel) force
/// of wheel \p side (0 right, 1 left), summed over its tread and flange in \p states.
std::array<double, 2> wheel_forces(const std::array<ContactState, n_wheelset_contacts>& states,
                                   int side);

/// Where a system keeps one wheelset's unknowns: its six motions (x, y, z, θx, θy, θz) from
/// \p wheelset on, the internal nodes' (x, y, z per contact point, in contact order) from
/// \p nodes on.
struct WheelsetUnknowns {
  std::size_t wheelset = 0;  ///< first of the wheelset's six
  std::size_t nodes = 6;     ///< first of the nodes' twelve
};

/// The contacts of one wheelset (see the file comment).
class WheelsetContacts {
 public:
  /// Contacts on the profiles of \p geometry with \p settings, for a wheelset whose unknowns
  /// are at \p unknowns, rolling at \p speed with nominal spin \p spin.
  WheelsetContacts(std::shared_ptr<const WheelRailGeometry> geometry,
                   const WheelRailContactSettings& settings, WheelsetUnknowns unknowns,
                   double speed, double spin);

  /// The states at the system's (u, v): those of the last evaluation when this wheelset's
  /// unknowns are the same and neither spin nor rolling changed since (Newton asks for forces
  /// and tangent at one iterate), else each point searched anew.
  const std::array<ContactState, n_wheelset_contacts>& states(const double* u, const double* v);
  /// Adds the contacts' internal forces at (u, v) into the system's \p force.
  void add_forces(const double* u, const double* v, double* force);
  /// Adds each active contact's tangent (∂f/∂u, ∂f/∂v) at (u, v) into the system's matrices.
  void add_tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
                   Eigen::MatrixXd& damping);
  /// Adds \p stiffness_scale ∂f/∂u + \p damping_scale ∂f/∂v of each active contact at (u, v)
  /// into \p matrix (a time step's A).
  void add_tangent_matrix(const double* u, const double* v, double stiffness_scale,
                          double damping_scale, Eigen::MatrixXd& matrix);
  /// Contact point \p index.
  WheelRailContact& contact(int index) { return contacts_[index]; }
  /// Where the wheelset's unknowns are.
  const WheelsetUnknowns& unknowns() const { return unknowns_; }
  /// Rolling speed V (m/s).
  double speed() const { return speed_; }
  /// Sets the nominal spin Ω about the axle (rad/s).
  void set_spin(double spin);
  /// Switches the creep forces off (\p rolling false: a static balance) or on.
  void set_rolling(bool rolling);

 private:
  ContactKinematics kinematics(int index, const double* u, const double* v) const;
  /// Calls \p add(row, column, ∂f/∂u entry, ∂f/∂v entry) for every entry of every active
  /// contact's tangent at (u, v), rows and columns the system's.
  template <class Add>
  void for_each_tangent_entry(const double* u, const double* v, Add&& add);
  bool same_iterate(const double* u, const double* v) const;

  WheelsetUnknowns unknowns_;
  std::vector<WheelRailContact> contacts_;
  double speed_, spin_;
  bool rolling_ = true;
  bool cached_ = false;
  std::array<double, 36> iterate_;  // the iterate of states_: u, v of wheelset and nodes
  std::array<ContactState, n_wheelset_contacts> states_;
};

}  // namespace railfe
