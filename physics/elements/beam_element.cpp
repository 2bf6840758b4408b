#include "physics/elements/beam_element.hpp"

#include <stdexcept>

#include "physics/elements/timoshenko_bending.hpp"

namespace railfe {
namespace {

// Local DOFs (w_a, θ_a, w_b, θ_b) of a bending plane and the sign that makes θ = dw/dx:
// θ_z = du_y/dx, but θ_y = −du_z/dx.
struct BendingPlane {
  int dofs[4];
  double signs[4];
};
constexpr BendingPlane kPlaneXY{{1, 5, 7, 11}, {1, 1, 1, 1}};
constexpr BendingPlane kPlaneXZ{{2, 4, 8, 10}, {1, -1, 1, -1}};

void scatter(const BendingPlane& plane, const Eigen::Matrix4d& block, Matrix12& target) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      target(plane.dofs[i], plane.dofs[j]) += plane.signs[i] * plane.signs[j] * block(i, j);
}

// Adds the two-node bar matrix value · [a, b; b, a] on local DOF \p dof of each node.
void add_bar(int dof, double diagonal, double coupling, Matrix12& target) {
  target(dof, dof) += diagonal;
  target(dof + 6, dof + 6) += diagonal;
  target(dof, dof + 6) += coupling;
  target(dof + 6, dof) += coupling;
}

// HRZ lumping of a bending plane's consistent mass: its diagonal scaled so that the two
// deflections carry the plane's whole translational mass \p total.
Eigen::Matrix4d hrz(const Eigen::Matrix4d& consistent, double total) {
  if (!(total > 0))
    return Eigen::Matrix4d::Zero();  // a massless beam
  const double scale = total / (consistent(0, 0) + consistent(2, 2));
  return Eigen::Matrix4d(scale * consistent.diagonal().asDiagonal());
}

}  // namespace

BeamElement::BeamElement(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& orientation, const BeamMaterial& material,
                         const BeamSection& section, bool rotary_inertia)
    : length_((b - a).norm()),
      axes_(beam_axes(a, b, orientation)),
      material_(material),
      section_(section),
      rotary_inertia_(rotary_inertia) {
  check_section(section);
  if (!(material.young > 0) || !(material.shear_modulus > 0) || !(material.density >= 0))
    throw std::invalid_argument("beam material needs E > 0, G > 0 and a density >= 0");
  phi_y_ = shear_parameter(material.young * section.iz,
                           material.shear_modulus * section.shear_area_y, length_);
  phi_z_ = shear_parameter(material.young * section.iy,
                           material.shear_modulus * section.shear_area_z, length_);
}

Matrix12 BeamElement::local_stiffness() const {
  const double L = length_, E = material_.young, G = material_.shear_modulus;
  Matrix12 k = Matrix12::Zero();
  add_bar(0, E * section_.area / L, -E * section_.area / L, k);
  add_bar(3, G * section_.torsion / L, -G * section_.torsion / L, k);
  scatter(kPlaneXY, timoshenko_bending_stiffness(E * section_.iz, phi_y_, L), k);
  scatter(kPlaneXZ, timoshenko_bending_stiffness(E * section_.iy, phi_z_, L), k);
  return k;
}

Matrix12 BeamElement::local_mass(BeamMass kind) const {
  const double L = length_, rho = material_.density;
  const double line_mass = rho * section_.area * L;
  const double polar = rho * (section_.iy + section_.iz) * L;
  const double rotary = rotary_inertia_ ? rho : 0;
  const Eigen::Matrix4d xy =
      timoshenko_bending_mass(rho * section_.area, rotary * section_.iz, phi_y_, L);
  const Eigen::Matrix4d xz =
      timoshenko_bending_mass(rho * section_.area, rotary * section_.iy, phi_z_, L);
  Matrix12 m = Matrix12::Zero();
  if (kind == BeamMass::consistent) {
    add_bar(0, line_mass / 3, line_mass / 6, m);
    add_bar(3, polar / 3, polar / 6, m);
    scatter(kPlaneXY, xy, m);
    scatter(kPlaneXZ, xz, m);
  } else {
    add_bar(0, line_mass / 2, 0, m);
    add_bar(3, polar / 2, 0, m);
    scatter(kPlaneXY, hrz(xy, line_mass), m);
    scatter(kPlaneXZ, hrz(xz, line_mass), m);
  }
  return m;
}

Vector12 BeamElement::end_forces(const Vector12& u) const {
  return local_stiffness() * to_local<12>(u, axes_);
}

BeamSectionForces BeamElement::section_forces(const Vector12& u) const {
  const Vector12 f = end_forces(u);
  return {Vector6(-f.head<6>()), Vector6(f.tail<6>())};
}

}  // namespace railfe
