#pragma once
/// \file
/// Rigid links as linear constraints: the nodes a 6-DOF master carries follow its small rigid
/// motion, u_s = u_m + θ_m × (x_s − x_m) and, at 6-DOF slaves, θ_s = θ_m (rigid_link.hpp's
/// equations), eliminated by LinearConstraints' u = T ū. Solid nodes (3 DOFs) follow with their
/// translations only. Links do not chain: a node carried by one link may not carry others.

#include <functional>
#include <string>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/assembly/linear_constraints.hpp"

namespace railfe {

/// A master node and the nodes it carries (global mesh node indices).
struct RigidLink {
  GlobalIndex master = 0;           ///< a node with 6 DOFs
  std::vector<GlobalIndex> slaves;  ///< nodes with 3 or 6 DOFs, master not among them
  std::string name;                 ///< for messages (e.g. "block links, element 3")
};

/// The links of the mesh's rigid_link blocks: each element's first node carries the others.
std::vector<RigidLink> mesh_rigid_links(const Mesh& mesh);

/// The checks add_rigid_links() makes, for a step's check before any DOF map exists:
/// \p node_dofs gives the DOF count of a global mesh node in the map the step will use.
void check_rigid_links(const std::vector<RigidLink>& links,
                       const std::function<int(GlobalIndex)>& node_dofs, const std::string& deck,
                       const std::string& path);

/// Adds the multi-point constraints of \p links to \p constraints (every rank passes the same
/// links; each keeps the equations of the slaves it owns) without finalizing them. Slaves that
/// carry no DOFs (no element uses them) are skipped. Throws InputError naming \p deck, \p path
/// and the nodes when a master has no rotation DOFs, a link carries its own master, a node is
/// carried by two links, or a carried node carries others (chained links).
void add_rigid_links(const std::vector<RigidLink>& links, const DofMap& dofs,
                     LinearConstraints& constraints, const std::string& deck,
                     const std::string& path);

}  // namespace railfe
