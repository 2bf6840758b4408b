#include "physics/common/rigid_links.hpp"

#include <map>

#include "framework/base/error.hpp"
#include "physics/elements/rigid_link.hpp"

namespace railfe {

namespace {

std::string node_name(GlobalIndex node) {
  return "node " + std::to_string(node + 1);
}

}  // namespace

void check_rigid_links(const std::vector<RigidLink>& links,
                       const std::function<int(GlobalIndex)>& node_dofs, const std::string& deck,
                       const std::string& path) {
  std::map<GlobalIndex, const RigidLink*> master_of, carrier_of;
  for (const auto& link : links)
    master_of.emplace(link.master, &link);
  for (const auto& link : links) {
    if (node_dofs(link.master) != 6) {
      throw_input_error(deck, path,
                        link.name + ": master " + node_name(link.master) +
                            " has no rotation DOFs (a solid node, or a node no element uses)",
                        "a master that belongs to a beam, spring, point mass or rigid link only");
    }
    for (GlobalIndex slave : link.slaves) {
      if (slave == link.master) {
        throw_input_error(deck, path, link.name + ": " + node_name(slave) + " carries itself",
                          "slaves other than the master");
      }
      const auto carrier = carrier_of.emplace(slave, &link);
      if (!carrier.second && carrier.first->second != &link) {
        throw_input_error(deck, path,
                          node_name(slave) + " is carried by two rigid links (" +
                              carrier.first->second->name + " and " + link.name + ")",
                          "each node carried by one link");
      }
      const auto master = master_of.find(slave);
      if (master != master_of.end()) {
        throw_input_error(deck, path,
                          link.name + " carries " + node_name(slave) + ", the master of " +
                              master->second->name + ": rigid links do not chain",
                          "make the outer master carry every node directly");
      }
    }
  }
}

std::vector<RigidLink> mesh_rigid_links(const Mesh& mesh) {
  std::vector<RigidLink> links;
  for (const auto& block : mesh.blocks) {
    if (block.type != ElementType::rigid_link)
      continue;
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      RigidLink link;
      link.master = nodes[0];
      link.slaves.assign(nodes + 1, nodes + block.n_element_nodes(e));
      link.name = "block '" + block.name + "' element " + std::to_string(e + 1);
      links.push_back(std::move(link));
    }
  }
  return links;
}

void add_rigid_links(const std::vector<RigidLink>& links, const DofMap& dofs,
                     LinearConstraints& constraints, const std::string& deck,
                     const std::string& path) {
  check_rigid_links(
      links, [&](GlobalIndex node) { return dofs.dofs_of_global_node(node); }, deck, path);
  const Mesh& mesh = dofs.partition().mesh();
  const auto& owners = dofs.partition().node_ranks();
  const int rank = dofs.partition().comm().rank();
  for (const auto& link : links) {
    const auto master = mesh.node(link.master);
    for (GlobalIndex slave : link.slaves) {
      if (owners[slave] != rank)  // not ours, or no DOFs at all
        continue;
      const auto x = mesh.node(slave);
      const Eigen::Vector3d offset(x[0] - master[0], x[1] - master[1], x[2] - master[2]);
      for (const auto& equation : rigid_link_equations(offset, dofs.dofs_of_global_node(slave))) {
        MultipointConstraint constraint;
        constraint.slave = dofs.global_dof(slave, equation.slave_component);
        for (const auto& [component, coefficient] : equation.masters)
          constraint.masters.emplace_back(dofs.global_dof(link.master, component), coefficient);
        constraints.add_multipoint(constraint);
      }
    }
  }
}

}  // namespace railfe
