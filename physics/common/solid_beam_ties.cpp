#include "physics/common/solid_beam_ties.hpp"

#include <algorithm>

#include "framework/base/error.hpp"

namespace railfe {

void add_solid_beam_tie_parameters(ParameterSpec& spec) {
  ParameterSpec tie(
      "Ties a beam end to solid nodes: the solid nodes follow the beam node's rigid motion "
      "u + theta x (x_i - x_b) (a rigid link with the solid nodes carried), and the beam end "
      "takes their forces and moments. The beam node needs rotation DOFs: it must belong to a "
      "beam, spring, point mass or rigid link and to no solid element.");
  tie.required_text("Beam node set", "A node set of exactly one node: the beam end.");
  tie.required_text("Solid node set", "The solid nodes it carries (a face of the solid).");
  spec.named_sublists("Solid-beam ties", tie,
                      "Beam ends tied rigidly to solid faces (multi-point constraints).");
}

std::vector<SolidBeamTie> read_solid_beam_ties(const Teuchos::ParameterList& step) {
  std::vector<SolidBeamTie> ties;
  if (!step.isSublist("Solid-beam ties"))
    return ties;
  const Teuchos::ParameterList& list = step.sublist("Solid-beam ties");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Teuchos::ParameterList& tie = list.sublist(list.name(it));
    ties.push_back({list.name(it), tie.get<std::string>("Beam node set"),
                    tie.get<std::string>("Solid node set")});
  }
  return ties;
}

std::vector<RigidLink> solid_beam_links(const std::vector<SolidBeamTie>& ties, const Mesh& mesh,
                                        const std::string& deck, const std::string& path) {
  std::vector<RigidLink> links;
  for (const auto& tie : ties) {
    const std::string where = path + "/Solid-beam ties/" + tie.name;
    const NodeSet& beam = mesh.node_set(tie.beam_set, deck, where + "/Beam node set");
    const NodeSet& solid = mesh.node_set(tie.solid_set, deck, where + "/Solid node set");
    if (beam.nodes.size() != 1) {
      throw_input_error(
          deck, where + "/Beam node set",
          "node set '" + tie.beam_set + "' holds " + std::to_string(beam.nodes.size()) + " nodes",
          "a node set of exactly one node");
    }
    if (std::binary_search(solid.nodes.begin(), solid.nodes.end(), beam.nodes[0])) {
      throw_input_error(deck, where + "/Solid node set",
                        "node set '" + tie.solid_set + "' holds the beam node " +
                            std::to_string(beam.nodes[0] + 1),
                        "solid nodes apart from the beam node");
    }
    links.push_back(
        solid_beam_link(beam.nodes[0], solid.nodes, "Solid-beam tie '" + tie.name + "'"));
  }
  return links;
}

std::pair<std::vector<RigidLink>, std::string> step_rigid_links(const Teuchos::ParameterList& step,
                                                                const Mesh& mesh, bool structural,
                                                                const std::string& deck,
                                                                const std::string& path) {
  std::vector<RigidLink> links = mesh_rigid_links(mesh);
  const auto ties = solid_beam_links(read_solid_beam_ties(step), mesh, deck, path);
  links.insert(links.end(), ties.begin(), ties.end());
  const std::string where = ties.empty() ? "Mesh" : path + "/Solid-beam ties";
  const std::vector<int> node_dofs = DofMap::mesh_node_dofs(mesh);
  check_rigid_links(
      links, [&](GlobalIndex node) { return structural ? node_dofs[node] : 3; }, deck, where);
  return {links, where};
}

RigidLink solid_beam_link(GlobalIndex beam_node, std::vector<GlobalIndex> solid_nodes,
                          const std::string& name) {
  RigidLink link;
  link.master = beam_node;
  link.slaves = std::move(solid_nodes);
  link.name = name;
  return link;
}

}  // namespace railfe
