#include "physics/statics/ground_springs.hpp"

#include "framework/base/error.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

namespace {

// Owned nodes of \p set and the share of the set's stiffness each takes: one over the set's
// nodes on all ranks (those attached to elements), as the explicit module's node-set springs.
std::vector<LocalIndex> owned_nodes(const MeshPartition& partition, const std::string& set,
                                    double& share) {
  std::vector<LocalIndex> nodes = owned_set_nodes(partition, set);
  share = 1.0 / static_cast<double>(partition.comm().sum(static_cast<long long>(nodes.size())));
  return nodes;
}

}  // namespace

ParameterSpec ground_spring_parameters() {
  ParameterSpec spring(
      "A node set on springs to the ground along the global axes, the stiffness shared equally "
      "by its nodes (one spring per node: the explicit module's node-set spring to 'ground').");
  spring.required_text("Node set", "The nodes.");
  spring.real_array("Stiffness", {0, 0, 0}, "Total stiffness along x, y, z.", "N/m", 3,
                    Range::non_negative());
  return spring;
}

std::vector<GroundSpring> read_ground_springs(const Teuchos::ParameterList& step, const Mesh& mesh,
                                              const std::string& deck, const std::string& path) {
  std::vector<GroundSpring> springs;
  if (!step.isSublist("Springs"))
    return springs;
  const auto& list = step.sublist("Springs");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const auto& entry = list.sublist(name);
    GroundSpring spring;
    spring.name = name;
    spring.node_set = entry.get<std::string>("Node set");
    const auto k = entry.get<Teuchos::Array<double>>("Stiffness");
    spring.stiffness = {k[0], k[1], k[2]};
    const std::string where = path + "/Springs/" + name;
    if (mesh.node_set(spring.node_set, deck, where + "/Node set").nodes.empty()) {
      throw_input_error(deck, where + "/Node set",
                        "names '" + spring.node_set + "', which is no node set with nodes",
                        "a node set of the mesh");
    }
    if (k[0] == 0 && k[1] == 0 && k[2] == 0)
      throw_input_error(deck, where + "/Stiffness", "is zero along every axis",
                        "a stiffness > 0 along at least one axis");
    springs.push_back(spring);
  }
  return springs;
}

std::vector<double> ground_spring_diagonal(const std::vector<GroundSpring>& springs,
                                           const DofMap& dofs) {
  const MeshPartition& partition = dofs.partition();
  std::vector<double> diagonal(dofs.n_owned_dofs(), 0.0);
  for (const GroundSpring& spring : springs) {
    double share = 0;
    for (LocalIndex node : owned_nodes(partition, spring.node_set, share)) {
      for (int d = 0; d < 3; ++d)
        diagonal[dofs.local_dof(node, d)] += share * spring.stiffness[d];
    }
  }
  return diagonal;
}

std::vector<std::array<double, 3>> ground_spring_forces(const std::vector<GroundSpring>& springs,
                                                        const DofMap& dofs, const TpetraVector& u) {
  const MeshPartition& partition = dofs.partition();
  const auto values = u.getData();
  std::vector<std::array<double, 3>> forces;
  for (const GroundSpring& spring : springs) {
    double share = 0;
    std::array<double, 3> force{0, 0, 0};
    for (LocalIndex node : owned_nodes(partition, spring.node_set, share)) {
      for (int d = 0; d < 3; ++d)
        force[d] -= share * spring.stiffness[d] * values[dofs.local_dof(node, d)];
    }
    for (double& f : force)
      f = partition.comm().sum(f);
    forces.push_back(force);
  }
  return forces;
}

}  // namespace railfe
