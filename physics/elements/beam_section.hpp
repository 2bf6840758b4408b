#pragma once
/// \file
/// Cross-section properties of beams, and the common shapes computed from their dimensions.
/// Section axes: y and z are the beam's local y and z (docs/theory.md, "Beam, spring–damper,
/// point mass and rigid link elements"); Iy = ∫ z² dA bends the beam in its x–z plane. Shear
/// areas are κ A with Cowper's (1966) coefficients, which depend on Poisson's ratio.

namespace railfe {

/// Properties of a beam cross-section (SI).
struct BeamSection {
  double area = 0;          ///< A (m²)
  double iy = 0;            ///< Iy = ∫ z² dA (m⁴), bending in the local x–z plane
  double iz = 0;            ///< Iz = ∫ y² dA (m⁴), bending in the local x–y plane
  double torsion = 0;       ///< Saint-Venant torsion constant J (m⁴)
  double shear_area_y = 0;  ///< Ay = κy A (m²), shear along local y; +∞: no shear deformation
  double shear_area_z = 0;  ///< Az = κz A (m²), shear along local z; +∞: no shear deformation
};

/// The same section without shear deformation (infinite shear areas): the Euler–Bernoulli limit.
BeamSection euler_bernoulli(BeamSection section);

/// Throws std::invalid_argument unless A, Iy, Iz, J and both shear areas are positive (shear
/// areas may be +∞).
void check_section(const BeamSection& section);

/// Solid rectangle \p width (along y) × \p height (along z). J from
/// rectangle_torsion_constant(); κ = 10(1+ν)/(12+11ν) along both axes (Cowper).
BeamSection rectangle_section(double width, double height, double poisson);

/// Solid circle of \p diameter: J = π d⁴/32, κ = 6(1+ν)/(7+6ν) (Cowper).
BeamSection circle_section(double diameter, double poisson);

/// Circular tube of \p outer_diameter and \p wall thickness (< radius): J = 2 I (exact for a
/// circular tube); κ = 6(1+ν)(1+m²)² / ((7+6ν)(1+m²)² + (20+12ν)m²), m = inner/outer radius
/// (Cowper).
BeamSection tube_section(double outer_diameter, double wall, double poisson);

/// Doubly symmetric I-section: overall \p depth (along z, the web), \p flange_width (along y),
/// thicknesses \p flange_thickness and \p web_thickness, no fillets. A and I exact for the three
/// rectangles; J = (2 b t_f³ + (d − t_f) t_w³)/3 (thin-walled open section on centre lines, no
/// fillets: AISC Design Guide 9, Seaburg & Carter 1997); Az (along the web) = κ A with Cowper's
/// thin-walled I coefficient (m = 2 b t_f/(h t_w), n = b/h, h = d − t_f); Ay (along the flanges)
/// as the two flanges' rectangles, 2 κ_rect b t_f, the web's share neglected.
BeamSection i_section(double depth, double flange_width, double flange_thickness,
                      double web_thickness, double poisson);

/// Torsion constant of a solid rectangle with sides \p a and \p b (any order, m⁴): Roark's
/// K = p q³ (16/3 − 3.36 (q/p)(1 − q⁴/(12 p⁴))), p ≥ q the half-sides (Young & Budynas, Roark's
/// Formulas for Stress and Strain, 7th ed., Table 10.7 case 4).
double rectangle_torsion_constant(double a, double b);

}  // namespace railfe
