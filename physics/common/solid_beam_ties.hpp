#pragma once
/// \file
/// Solid–beam ties: a beam end node carries the solid nodes of a face as a rigid link, so the
/// face translates and rotates with the beam end (u_i = u_b + θ_b × (x_i − x_b)) and the beam
/// end takes the face's forces and moments. The deck form is a step's "Solid-beam ties" list
/// (add_solid_beam_tie_parameters()); a step adds the links before it finalizes its constraints.

#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "physics/common/rigid_links.hpp"

namespace railfe {

/// One tie as the deck gives it.
struct SolidBeamTie {
  std::string name;       ///< its name in the deck
  std::string beam_set;   ///< a node set of one node: the beam end (6 DOFs)
  std::string solid_set;  ///< the solid nodes that follow it (typically a face)
};

/// Adds "Solid-beam ties" (named sublists of Beam node set, Solid node set) to \p spec.
void add_solid_beam_tie_parameters(ParameterSpec& spec);

/// The ties of a validated step list \p step (its "Solid-beam ties", possibly empty).
std::vector<SolidBeamTie> read_solid_beam_ties(const Teuchos::ParameterList& step);

/// The rigid links of \p ties over \p mesh. Throws InputError naming \p deck and the parameter
/// under \p path (the step's path) when a set is missing, a beam set does not hold exactly one
/// node, or the solid set holds the beam node.
std::vector<RigidLink> solid_beam_links(const std::vector<SolidBeamTie>& ties, const Mesh& mesh,
                                        const std::string& deck, const std::string& path);

/// The rigid links a step applies, checked before any DOF map exists (see check_rigid_links()):
/// the mesh's rigid_link blocks, then the Solid-beam ties of validated step list \p step, and
/// where their errors point ("Mesh", or the ties under the step's \p path). \p structural: the
/// step uses DofMap::for_mesh()'s counts (a model with beams, springs or point masses); else
/// every node carries 3 DOFs. Throws InputError naming \p deck as solid_beam_links() and
/// check_rigid_links() do.
std::pair<std::vector<RigidLink>, std::string> step_rigid_links(const Teuchos::ParameterList& step,
                                                                const Mesh& mesh, bool structural,
                                                                const std::string& deck,
                                                                const std::string& path);

/// The rigid link that ties solid nodes \p solid_nodes to beam node \p beam_node (the library
/// form, for code that builds models without a deck).
RigidLink solid_beam_link(GlobalIndex beam_node, std::vector<GlobalIndex> solid_nodes,
                          const std::string& name);

}  // namespace railfe
