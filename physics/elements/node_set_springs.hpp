#pragma once
/// \file
/// Springs on node sets in a statics or modal step, as the explicit module's node-set springs
/// are, so that a statics preload, the modes and the explicit run see the same supports: a
/// node set on springs to the ground (a sleeper on ballast), or tied to another node set (a rail
/// seat on the pad over a sleeper), each node of the set to the nearest node of the other
/// (framework/mesh/nearest_nodes.hpp). The stiffness is the set's total, shared equally by its
/// nodes (one spring per node).

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/parameter_spec.hpp"

namespace railfe {

/// One node set on springs to the ground or to another node set.
struct NodeSetSpring {
  std::string name;                 ///< its deck name
  std::string node_set;             ///< the nodes
  std::string to_node_set;          ///< the other end's nodes, or "" for the ground
  std::array<double, 3> stiffness;  ///< total along x, y, z (N/m), shared by the nodes
  /// With another end: each node (that elements use) and its partner, global indices.
  std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;
};

/// Valid parameters of one Springs sublist of a statics or modal step.
ParameterSpec node_set_spring_parameters();

/// Reads the step's Springs; throws InputError naming \p deck and the parameter for an unknown
/// or empty node set, two sets that share a node, or a spring with no stiffness.
std::vector<NodeSetSpring> read_node_set_springs(const Teuchos::ParameterList& step,
                                                 const MeshPartition& partition,
                                                 const std::string& deck, const std::string& path);

class FeMatrix;

/// The assembled \p stiffness with the springs added: the ground springs on its diagonal (in
/// place), and the springs between node sets, which couple nodes no element joins, as a matrix
/// added to it (the result; \p stiffness's own matrix where there are none).
Teuchos::RCP<TpetraMatrix> stiffness_with_springs(FeMatrix& stiffness,
                                                  const std::vector<NodeSetSpring>& springs,
                                                  const DofMap& dofs);

/// The force each spring exerts on its node set at displacement \p u (N, summed over ranks): on
/// the structure for a ground spring, on the first set for a spring between sets (the other
/// set takes the opposite, so these are internal forces).
std::vector<std::array<double, 3>> node_set_spring_forces(const std::vector<NodeSetSpring>& springs,
                                                          const DofMap& dofs,
                                                          const TpetraVector& u);

}  // namespace railfe
