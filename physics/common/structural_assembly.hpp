#pragma once
/// \file
/// Assembly of the structural elements (beams, spring–dampers, point masses; sections from
/// structural_sections.hpp) into global matrices and load vectors, for every module that solves
/// for displacements and rotations (statics, modal, implicit). Nodes of these elements carry six
/// DOFs u_x, u_y, u_z, θ_x, θ_y, θ_z (checked node by node, so that on a mixed map of
/// DofMap::for_mesh() solids and structural elements share one matrix); DOF indices come only
/// from DofMap::local_dof().
///
/// The add_* functions add into a matrix that is open for assembly (between
/// FeMatrix::begin_assembly() and end_assembly()), so that solids and structural elements go
/// into one matrix; the assemble_* functions open, add and complete it themselves.

#include <array>
#include <string>
#include <vector>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/linear_constraints.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/common/structural_sections.hpp"

namespace railfe {

/// Which matrix of a structural element.
enum class StructuralMatrix { stiffness, mass, damping };

/// The \p kind matrix (row-major, 12 × 12 for two nodes, 6 × 6 for one) of an element of
/// \p n_nodes nodes at \p coordinates (x, y, z each) with \p section (beams: the lumped mass
/// where \p lumped); false when the element adds nothing to this matrix (a spring's mass).
bool structural_element_matrix(StructuralMatrix kind, const StructuralSection& section,
                               const double* const* coordinates, int n_nodes, bool lumped,
                               double* out);

/// Adds the stiffness of every local beam2 and spring2 element, and of every spring to the
/// ground (a spring-damper section on a one-node block), into \p K (open for assembly).
void add_structural_stiffness(FeMatrix& K, const SectionTable& sections);
/// Adds the mass of every local beam2 element and point mass into \p M (open for assembly): each
/// beam's section decides consistent or lumped, unless \p lumped forces the lumped (HRZ) matrix.
void add_structural_mass(FeMatrix& M, const SectionTable& sections, bool lumped = false);
/// Adds the damping of every local spring2 element and spring to the ground into \p C (open for
/// assembly).
void add_structural_damping(FeMatrix& C, const SectionTable& sections);

/// Assembles the structural stiffness alone into \p K (collective): begin, add, end.
void assemble_structural_stiffness(FeMatrix& K, const SectionTable& sections);
/// Assembles the structural mass alone into \p M (collective); see add_structural_mass().
void assemble_structural_mass(FeMatrix& M, const SectionTable& sections, bool lumped = false);
/// Assembles the spring–dampers' damping alone into \p C (collective).
void assemble_structural_damping(FeMatrix& C, const SectionTable& sections);

/// Adds, over the overlapping DOFs of \p dofs, the weight of every local beam and point mass
/// under \p gravity (m/s²) to \p overlap_forces: each element's M ĝ with ĝ the uniform
/// translation by g, which is the consistent load ∫ Nᵀ ρ A g (end moments ± ρ A g L²/12 on a
/// beam with the consistent mass). Sum the overlap into owned DOFs afterwards.
void add_structural_gravity(const SectionTable& sections, const DofMap& dofs,
                            const std::array<double, 3>& gravity, double* overlap_forces);

/// Adds every Nodal force of \p conditions (force, and moment at the nodes with rotations, shared
/// equally by the nodes of its set that carry unknowns) to \p owned_forces (one value per owned DOF
/// of \p dofs), and the structural weight under Gravity; \p owned_forces is overwritten
/// (collective).
void assemble_structural_loads(const SolidConditions& conditions, const SectionTable& sections,
                               const DofMap& dofs, TpetraVector& owned_forces);

/// Prescribes the Displacements of \p conditions (components 0..5: translations and rotations)
/// on the nodes of \p dofs and finalizes \p constraints (collective).
void add_structural_constraints(const SolidConditions& conditions, const DofMap& dofs,
                                LinearConstraints& constraints);

/// Throws InputError naming \p deck and the parameter when \p conditions use what a model of
/// structural elements alone does not have (surface loads, centrifugal loads, ties, probes'
/// stresses are fine): surface and centrifugal loads.
void check_structural_conditions(const SolidConditions& conditions, const std::string& deck,
                                 const std::string& path);

/// Throws InputError naming \p deck and the parameter under \p path (the step's) when a model of
/// solids with structural elements (the mixed map of DofMap::for_mesh()) is asked for what its
/// solid nodes, which carry translations only, cannot give: a Displacement of a rotation or a
/// Nodal force with a Total moment on a node set holding solid nodes. Throws naming the Mesh when
/// a spring or point mass acts on a solid node (tie it with a Solid-beam tie instead).
void check_mixed_model(const SolidConditions& conditions, const Mesh& mesh, const std::string& deck,
                       const std::string& path);

}  // namespace railfe
