#pragma once
/// \file
/// Rotation of a rigid body over one explicit step, on its spatial angular momentum L. A step is
/// kick–drift–kick (the rotational twin of the central difference): L += ½Δt M, a free rotation
/// over Δt, L += ½Δt M. The free rotation of an unconstrained body is the implicit midpoint rule
/// on the body-frame Euler equations with the orientation advanced by the Cayley map (Austin,
/// Krishnaprasad & Wang, J. Comput. Phys. 107 (1993) 105–117): it conserves L exactly and the
/// kinetic energy to the tolerance of its 3 × 3 Newton solve, keeps R orthonormal, and is second
/// order. A body with rotations locked about spatial axes turns only about the free ones; its
/// free rotation is a symmetric midpoint iteration (exact for a hinge, two axes locked).

#include <array>

#include <Eigen/Dense>

namespace railfe {

/// The rotational inertia of one rigid body and the spatial rotations it may not make.
class RigidRotation {
 public:
  /// \p inertia: about the reference point in the reference orientation (symmetric, positive
  /// definite about every free axis); \p locked: spatial x, y, z rotations held at zero.
  RigidRotation(const Eigen::Matrix3d& inertia, const std::array<bool, 3>& locked);

  /// Angular velocity (spatial) of momentum \p momentum at orientation \p rotation: I_s⁻¹ L with
  /// I_s = R I Rᵀ, solved on the free axes only (zero about locked ones).
  Eigen::Vector3d angular_velocity(const Eigen::Matrix3d& rotation,
                                   const Eigen::Vector3d& momentum) const;
  /// Angular acceleration (spatial) under moment \p moment: I_s ω̇ = M − ω × I_s ω on the free
  /// axes (the locked axes' reaction takes the rest).
  Eigen::Vector3d angular_acceleration(const Eigen::Matrix3d& rotation,
                                       const Eigen::Vector3d& angular_velocity,
                                       const Eigen::Vector3d& moment) const;
  /// Spatial angular momentum I_s ω.
  Eigen::Vector3d momentum(const Eigen::Matrix3d& rotation,
                           const Eigen::Vector3d& angular_velocity) const;
  /// Kick: adds \p impulse (N m s) to \p momentum on the free axes.
  void kick(const Eigen::Vector3d& impulse, Eigen::Vector3d& momentum) const;
  /// Free rotation over \p dt: turns \p rotation with \p momentum (whose free components it
  /// conserves exactly) and re-orthonormalises it. Throws RunError if the solve fails (a step
  /// far beyond the rotation's time scale).
  void drift(double dt, const Eigen::Vector3d& momentum, Eigen::Matrix3d& rotation) const;
  /// Kinetic energy ½ ω·I_s ω of \p angular_velocity at \p rotation (J).
  double kinetic_energy(const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& angular_velocity) const;

 private:
  // Solves (Pᵀ A P) x = Pᵀ b on the free axes P and returns P x.
  Eigen::Vector3d solve_free(const Eigen::Matrix3d& matrix, const Eigen::Vector3d& rhs) const;
  void free_drift(double dt, const Eigen::Vector3d& momentum, Eigen::Matrix3d& rotation) const;
  void constrained_drift(double dt, const Eigen::Vector3d& momentum,
                         Eigen::Matrix3d& rotation) const;

  Eigen::Matrix3d inertia_, inverse_inertia_;
  std::array<bool, 3> locked_;
  int n_free_ = 3;
};

/// The rotation by |w| about w (exp of the skew matrix of w, Rodrigues).
Eigen::Matrix3d rotation_of(const Eigen::Vector3d& w);

/// The nearest rotation to a nearly orthonormal \p matrix (one Newton step of the polar
/// decomposition: error squared).
Eigen::Matrix3d orthonormalised(const Eigen::Matrix3d& matrix);

}  // namespace railfe
