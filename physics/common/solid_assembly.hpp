#pragma once
/// \file
/// Assembly of linear elastic solids: stiffness, loads, constraints, stresses. Shared by the
/// modules that work with displacement unknowns (statics now; implicit dynamics and modal
/// analysis next).

#include <string>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/linear_constraints.hpp"
#include "framework/output/progress.hpp"
#include "framework/solvers/linear_solver.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

/// Copies the coordinates of local element \p element of \p block into \p x.
void element_coordinates(const MeshPartition& partition, const LocalBlock& block,
                         LocalIndex element, double x[8][3]);

/// Assembles the stiffness of every local hex8 element into \p K (collective), in the formulation
/// its material chooses (ElasticMaterial::element), or for every element the one-point hex8 with
/// hourglass coefficient \p one_point_kappa when that is ≥ 0 (hex8_one_point.hpp), reporting to
/// \p progress (in local elements) if given.
void assemble_elastic_stiffness(FeMatrix& K, const MaterialTable& materials,
                                Progress* progress = nullptr, double one_point_kappa = -1);

/// Adds the stiffness of every local hex8 element, as assemble_elastic_stiffness() does, into
/// \p K open for assembly (between FeMatrix::begin_assembly() and end_assembly()), so that
/// solids and structural elements go into one matrix on a mixed DOF map.
void add_elastic_stiffness(FeMatrix& K, const MaterialTable& materials,
                           Progress* progress = nullptr, double one_point_kappa = -1);

/// Assembles the mass of every local hex8 element into \p M (collective): consistent, or lumped
/// (row sums) when \p lumped.
void assemble_mass(FeMatrix& M, const MaterialTable& materials, bool lumped);

/// Adds the hex8 mass, as assemble_mass() does, into \p M open for assembly (see
/// add_elastic_stiffness()).
void add_mass(FeMatrix& M, const MaterialTable& materials, bool lumped);

/// Adds gravity, surface loads and nodal forces into \p forces over the owned DOFs of \p dofs,
/// which is overwritten (collective).
void assemble_solid_loads(const SolidConditions& conditions, const MaterialTable& materials,
                          const DofMap& dofs, TpetraVector& forces);

/// Adds every Nodal force of \p conditions to \p owned_forces (one value per owned DOF of
/// \p dofs), shared equally by the nodes of its set that carry unknowns; its Total moment goes
/// to the rotations of the nodes that have them (6-DOF nodes).
void add_nodal_forces(const SolidConditions& conditions, const DofMap& dofs, double* owned_forces);

/// Node pairs (slave, master) of a tie, found by position. Throws InputError naming \p deck and
/// \p path if a slave node has no master within the tolerance.
std::vector<std::pair<GlobalIndex, GlobalIndex>> pair_tied_nodes(const Tie& tie, const Mesh& mesh,
                                                                 const std::string& deck,
                                                                 const std::string& path);

/// Prescribes the Displacements of \p conditions (their components, translations and, on nodes
/// that carry them, rotations) on the owned nodes of \p dofs.
void prescribe_displacements(const SolidConditions& conditions, const DofMap& dofs,
                             LinearConstraints& constraints);

/// Adds the Displacements and the tie pairs (per tie, from pair_tied_nodes) to \p constraints.
void add_solid_constraints(
    const SolidConditions& conditions,
    const std::vector<std::vector<std::pair<GlobalIndex, GlobalIndex>>>& ties, const DofMap& dofs,
    LinearConstraints& constraints);

/// Centre stresses (6 per element: xx, yy, zz, xy, yz, zx) of the local hex8 elements in
/// partition order, from displacements \p u_overlap over the overlapping DOFs of a uniform 3-DOF
/// map (exact for both formulations: the enhanced strains vanish at the centre); other element
/// types get zeros.
std::vector<double> element_stresses(const MeshPartition& partition, const MaterialTable& materials,
                                     const double* u_overlap);

/// What MueLu needs to coarsen elasticity well: node coordinates and the six rigid-body modes
/// (rotations included at 6-DOF nodes; a mixed layout gives MueLu scalar DOFs, see
/// DofMap::solver_dofs_per_node()). \p dofs must outlive the traits (they name DOFs with it).
ProblemTraits elasticity_traits(const DofMap& dofs);

}  // namespace railfe
