#pragma once
/// \file
/// The 3-D two-node beam: Timoshenko bending in two planes (Euler–Bernoulli when the shear areas
/// are infinite), axial stretching and Saint-Venant torsion, linear and small-rotation. Nodes
/// carry u_x, u_y, u_z, θ_x, θ_y, θ_z; matrices and vectors are 12 long, node a first, in global
/// axes unless named local. Local axes from beam_axes() (element_frame.hpp). Conventions and
/// sources: docs/theory.md, "Beam, spring–damper, point mass and rigid link elements".

#include <array>

#include "physics/elements/beam_section.hpp"
#include "physics/elements/element_frame.hpp"

namespace railfe {

/// Material of a beam (SI).
struct BeamMaterial {
  double young = 0;          ///< E (Pa)
  double shear_modulus = 0;  ///< G (Pa); E / (2(1+ν)) for an isotropic material
  double density = 0;        ///< ρ (kg/m³); 0 gives a massless beam
};

/// An isotropic beam material from E (Pa), Poisson's ratio ν and ρ (kg/m³): G = E / (2(1+ν)).
inline BeamMaterial isotropic_beam_material(double young, double poisson, double density) {
  return {young, young / (2 * (1 + poisson)), density};
}

/// How the mass matrix is formed.
enum class BeamMass {
  consistent,  ///< from the Timoshenko interpolation (timoshenko_bending.hpp)
  lumped,      ///< diagonal: HRZ lumping (Hinton, Rock & Zienkiewicz 1976) of the consistent one
};

/// Section resultants at the two ends, on the face whose outward normal is +x (local axes):
/// N (tension positive), V_y, V_z, T, M_y, M_z, at end a then end b.
using BeamSectionForces = std::array<Vector6, 2>;

/// One beam element between two nodes.
class BeamElement {
 public:
  /// A beam from \p a to \p b whose local y axis is the part of \p orientation normal to it.
  /// \p rotary_inertia adds the section's rotary inertia ρ I to the bending mass (the Timoshenko
  /// and Rayleigh beams); without it the bending mass is that of ρA alone. Throws
  /// std::invalid_argument for coincident nodes, a degenerate orientation, a section that
  /// fails check_section(), or E, G not positive or ρ negative.
  BeamElement(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& orientation, const BeamMaterial& material,
              const BeamSection& section, bool rotary_inertia = true);

  /// Length (m).
  double length() const { return length_; }
  /// Local axes (rows x, y, z in global components).
  const Eigen::Matrix3d& axes() const { return axes_; }
  /// Shear deformation parameters φ_y (bending in x–y, uses I_z and A_y) and φ_z (x–z plane).
  std::array<double, 2> shear_parameters() const { return {phi_y_, phi_z_}; }

  /// Stiffness in local axes.
  Matrix12 local_stiffness() const;
  /// Stiffness in global axes (symmetric, positive semi-definite with the six rigid-body modes
  /// as its null space).
  Matrix12 stiffness() const { return to_global<12>(local_stiffness(), axes_); }
  /// Mass in local axes.
  Matrix12 local_mass(BeamMass kind) const;
  /// Mass in global axes. The lumped one is diagonal in local axes; in global axes its
  /// translations stay diagonal (ρAL/2 each), and its rotations form a 3 × 3 block per node
  /// unless the two bending planes carry the same rotary mass or the beam lies along an axis.
  Matrix12 mass(BeamMass kind) const { return to_global<12>(local_mass(kind), axes_); }

  /// Forces and moments the nodes exert on the element (local axes) for nodal displacements
  /// \p u (global): K_local T u. Zero for any rigid-body motion.
  Vector12 end_forces(const Vector12& u) const;
  /// Internal force vector in global axes, K u: the nodal forces that hold \p u.
  Vector12 internal_force(const Vector12& u) const { return stiffness() * u; }
  /// Section resultants at the ends for nodal displacements \p u (global).
  BeamSectionForces section_forces(const Vector12& u) const;

 private:
  double length_ = 0;
  Eigen::Matrix3d axes_;
  BeamMaterial material_;
  BeamSection section_;
  bool rotary_inertia_ = true;
  double phi_y_ = 0, phi_z_ = 0;
};

}  // namespace railfe
