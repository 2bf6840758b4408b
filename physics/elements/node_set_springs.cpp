#include "physics/elements/node_set_springs.hpp"

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/sparse_entries.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/nearest_nodes.hpp"
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

bool owned(const MeshPartition& partition, GlobalIndex node) {
  const LocalIndex local = partition.local_node(node);
  return local >= 0 && local < partition.n_owned_nodes();
}

}  // namespace

ParameterSpec node_set_spring_parameters() {
  ParameterSpec spring(
      "A node set on springs along the global axes, to the ground or to another node set (each "
      "node to the nearest node of that set), the stiffness shared equally by its nodes (one "
      "spring per node: the explicit module's node-set spring).");
  spring.required_text("Node set", "The nodes.");
  spring.text("To node set", "",
              "The other end: a node set whose nearest node each node is tied to ('' = the "
              "ground). A rail seat on the pad over a sleeper's top, for example.");
  spring.real_array("Stiffness", {0, 0, 0}, "Total stiffness along x, y, z.", "N/m", 3,
                    Range::non_negative());
  return spring;
}

std::vector<NodeSetSpring> read_node_set_springs(const Teuchos::ParameterList& step,
                                                 const MeshPartition& partition,
                                                 const std::string& deck, const std::string& path) {
  std::vector<NodeSetSpring> springs;
  if (!step.isSublist("Springs"))
    return springs;
  const Mesh& mesh = partition.mesh();
  const auto& list = step.sublist("Springs");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const auto& entry = list.sublist(name);
    NodeSetSpring spring;
    spring.name = name;
    spring.node_set = entry.get<std::string>("Node set");
    spring.to_node_set = entry.get<std::string>("To node set");
    const auto k = entry.get<Teuchos::Array<double>>("Stiffness");
    spring.stiffness = {k[0], k[1], k[2]};
    const std::string where = path + "/Springs/" + name;
    for (const auto& [set, label] :
         {std::pair{spring.node_set, "/Node set"}, std::pair{spring.to_node_set, "/To node set"}}) {
      if (set.empty() && std::string(label) == "/To node set")
        continue;
      if (mesh.node_set(set, deck, where + label).nodes.empty())
        throw_input_error(deck, where + label,
                          "names '" + set + "', which is no node set with nodes",
                          "a node set of the mesh");
    }
    if (k[0] == 0 && k[1] == 0 && k[2] == 0)
      throw_input_error(deck, where + "/Stiffness", "is zero along every axis",
                        "a stiffness > 0 along at least one axis");
    if (!spring.to_node_set.empty())
      spring.pairs = nearest_node_pairs(partition, spring.node_set, spring.to_node_set, deck,
                                        where + "/To node set");
    springs.push_back(spring);
  }
  return springs;
}

namespace {

// The ground springs' share on the diagonal, one value per owned DOF.
std::vector<double> ground_spring_diagonal(const std::vector<NodeSetSpring>& springs,
                                           const DofMap& dofs) {
  const MeshPartition& partition = dofs.partition();
  std::vector<double> diagonal(dofs.n_owned_dofs(), 0.0);
  for (const NodeSetSpring& spring : springs) {
    if (!spring.to_node_set.empty())
      continue;
    double share = 0;
    for (LocalIndex node : owned_nodes(partition, spring.node_set, share)) {
      for (int d = 0; d < 3; ++d)
        diagonal[dofs.local_dof(node, d)] += share * spring.stiffness[d];
    }
  }
  return diagonal;
}

// The stiffness of the springs between node sets over the owned DOFs, or null without any.
Teuchos::RCP<TpetraMatrix> paired_spring_stiffness(const std::vector<NodeSetSpring>& springs,
                                                   const DofMap& dofs) {
  const MeshPartition& partition = dofs.partition();
  std::vector<MatrixEntry> entries;
  bool any = false;
  for (const NodeSetSpring& spring : springs) {
    if (spring.to_node_set.empty())
      continue;
    any = true;
    const double share = 1.0 / static_cast<double>(spring.pairs.size());
    for (const auto& [a, b] : spring.pairs) {
      for (int d = 0; d < 3; ++d) {
        const double k = share * spring.stiffness[d];
        if (owned(partition, a)) {
          entries.emplace_back(dofs.global_dof(a, d), dofs.global_dof(a, d), k);
          entries.emplace_back(dofs.global_dof(a, d), dofs.global_dof(b, d), -k);
        }
        if (owned(partition, b)) {
          entries.emplace_back(dofs.global_dof(b, d), dofs.global_dof(b, d), k);
          entries.emplace_back(dofs.global_dof(b, d), dofs.global_dof(a, d), -k);
        }
      }
    }
  }
  if (!any)
    return Teuchos::null;
  return matrix_from_entries(dofs.owned_map(), std::move(entries));
}

}  // namespace

Teuchos::RCP<TpetraMatrix> stiffness_with_springs(FeMatrix& stiffness,
                                                  const std::vector<NodeSetSpring>& springs,
                                                  const DofMap& dofs) {
  if (springs.empty())
    return stiffness.matrix();
  stiffness.add_to_diagonal(ground_spring_diagonal(springs, dofs));
  Teuchos::RCP<TpetraMatrix> K = stiffness.matrix();
  if (const auto paired = paired_spring_stiffness(springs, dofs); !paired.is_null())
    K = Tpetra::MatrixMatrix::add(1.0, false, *K, 1.0, false, *paired);
  return K;
}

std::vector<std::array<double, 3>> node_set_spring_forces(const std::vector<NodeSetSpring>& springs,
                                                          const DofMap& dofs,
                                                          const TpetraVector& u) {
  const MeshPartition& partition = dofs.partition();
  const Communicator& comm = partition.comm();
  const auto values = u.getData();
  auto value = [&](GlobalIndex node, int d) {
    return values[dofs.local_dof(partition.local_node(node), d)];
  };
  std::vector<std::array<double, 3>> forces;
  for (const NodeSetSpring& spring : springs) {
    std::vector<double> force(3, 0.0);
    if (spring.to_node_set.empty()) {
      double share = 0;
      for (LocalIndex node : owned_nodes(partition, spring.node_set, share))
        for (int d = 0; d < 3; ++d)
          force[d] -= share * spring.stiffness[d] * values[dofs.local_dof(node, d)];
    } else {
      // Each pair's stretch u_b − u_a, from the ranks that own either end.
      std::vector<double> stretch(3 * spring.pairs.size(), 0.0);
      for (std::size_t p = 0; p < spring.pairs.size(); ++p) {
        const auto [a, b] = spring.pairs[p];
        for (int d = 0; d < 3; ++d) {
          if (owned(partition, a))
            stretch[3 * p + d] -= value(a, d);
          if (owned(partition, b))
            stretch[3 * p + d] += value(b, d);
        }
      }
      comm.sum_in_place(stretch);
      if (comm.is_root()) {
        const double share = 1.0 / static_cast<double>(spring.pairs.size());
        for (std::size_t p = 0; p < spring.pairs.size(); ++p)
          for (int d = 0; d < 3; ++d)
            force[d] += share * spring.stiffness[d] * stretch[3 * p + d];
      }
    }
    comm.sum_in_place(force);
    forces.push_back({force[0], force[1], force[2]});
  }
  return forces;
}

}  // namespace railfe
