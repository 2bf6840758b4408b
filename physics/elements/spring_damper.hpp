#pragma once
/// \file
/// A linear spring–damper with up to six components (three translations, three rotations) in a
/// local frame, between two 6-DOF nodes or from one node to the ground. With d the relative
/// motion of node b against node a (or the node's own motion, to ground) in local axes, the
/// force on node b is −(k d + c ḋ) componentwise, and node a takes the opposite. The element acts
/// on relative displacements only (a "bushing" of zero length, like ANSYS COMBIN14's or
/// Abaqus's SPRING2): between nodes that are apart its translational forces are not balanced in
/// moment unless they act along the line joining the nodes.

#include <array>

#include "physics/elements/element_frame.hpp"

namespace railfe {

/// Properties of a spring–damper (SI: N/m, N m/rad, N s/m, N m s/rad).
struct SpringDamper {
  std::array<double, 6> stiffness{};  ///< k along local x, y, z, then about local x, y, z
  std::array<double, 6> damping{};    ///< c, same order
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< local frame, rows the local axes
};

/// Throws std::invalid_argument for a negative stiffness or damping, or axes that fail
/// check_rotation().
void check_spring_damper(const SpringDamper& spring);

/// The 6 × 6 global matrix Tᵀ diag(\p values) T of one node (T = blockdiag(axes, axes)); with
/// the stiffness it is the stiffness to ground, with the damping the damping to ground.
Matrix6 spring_block(const std::array<double, 6>& values, const Eigen::Matrix3d& axes);

/// The 12 × 12 matrix [B, −B; −B, B] of a two-node element from the one-node \p block.
Matrix12 two_node_matrix(const Matrix6& block);

/// Stiffness of \p spring between two nodes (12 × 12, global).
inline Matrix12 spring_stiffness(const SpringDamper& spring) {
  return two_node_matrix(spring_block(spring.stiffness, spring.axes));
}
/// Damping of \p spring between two nodes (12 × 12, global).
inline Matrix12 spring_damping(const SpringDamper& spring) {
  return two_node_matrix(spring_block(spring.damping, spring.axes));
}

/// Stiffness of \p spring from a node to the ground (6 × 6, global).
inline Matrix6 ground_spring_stiffness(const SpringDamper& spring) {
  return spring_block(spring.stiffness, spring.axes);
}
/// Damping of \p spring from a node to the ground (6 × 6, global).
inline Matrix6 ground_spring_damping(const SpringDamper& spring) {
  return spring_block(spring.damping, spring.axes);
}

/// Local force components k d + c ḋ (the force the spring exerts on node a; node b takes minus
/// it) for relative displacement \p relative_u = motion of b − motion of a and relative
/// velocity \p relative_v (global, 6 each); for a spring to ground, the node's own motion (the
/// force then acts on the node with a minus sign).
Vector6 spring_local_force(const SpringDamper& spring, const Vector6& relative_u,
                           const Vector6& relative_v);

/// Internal force vector (12, global) of a spring between two nodes: K u + C v, the nodal
/// forces that hold displacements \p u and velocities \p v.
Vector12 spring_internal_force(const SpringDamper& spring, const Vector12& u, const Vector12& v);

/// Internal force vector (6, global) of a spring from a node to the ground: K u + C v for the
/// node's displacement \p u and velocity \p v.
Vector6 ground_spring_internal_force(const SpringDamper& spring, const Vector6& u,
                                     const Vector6& v);

/// The force on end a of the translational part of \p spring (components 0–2 of its local
/// frame) when end b has moved by \p stretch relative to a at \p rate: Rᵀ (k∘(R d) + c∘(R ḋ)),
/// R = spring.axes. For springs between point-like ends (the explicit module's bodies and node
/// sets), whose rotations carry no spring.
Eigen::Vector3d spring_translational_force(const SpringDamper& spring,
                                           const Eigen::Vector3d& stretch,
                                           const Eigen::Vector3d& rate);
/// The energy ½ (R d)ᵀ diag(k) (R d) stored by the translational part at \p stretch.
double spring_translational_energy(const SpringDamper& spring, const Eigen::Vector3d& stretch);
/// The power (R ḋ)ᵀ diag(c) (R ḋ) dissipated by the translational part at \p rate.
double spring_translational_power(const SpringDamper& spring, const Eigen::Vector3d& rate);

}  // namespace railfe
