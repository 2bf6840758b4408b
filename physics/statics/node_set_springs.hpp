#pragma once
/// \file
/// Spring supports of a statics step: a node set tied to the ground by springs along the global
/// axes, the total stiffness shared equally by its nodes (one spring per node), as the explicit
/// module's node-set springs to 'ground' are, so that a statics preload and the explicit run
/// that starts from it see the same supports (a rail on its pads, a sleeper on ballast).

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/assembly/dof_map.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"

namespace railfe {

/// One node set on springs to the ground.
struct GroundSpring {
  std::string name;                 ///< its deck name
  std::string node_set;             ///< the nodes
  std::array<double, 3> stiffness;  ///< total along x, y, z (N/m), shared by the nodes
};

/// Valid parameters of one Springs sublist of a statics step.
ParameterSpec ground_spring_parameters();

/// Reads the step's Springs; throws InputError naming \p deck and the parameter for an unknown
/// or empty node set, or a spring with no stiffness.
std::vector<GroundSpring> read_ground_springs(const Teuchos::ParameterList& step, const Mesh& mesh,
                                              const std::string& deck, const std::string& path);

/// Each spring's share on the diagonal, one value per owned DOF (for FeMatrix::add_to_diagonal).
std::vector<double> ground_spring_diagonal(const std::vector<GroundSpring>& springs,
                                           const DofMap& dofs);

/// The force each spring exerts on the structure at displacement \p u (N, summed over ranks).
std::vector<std::array<double, 3>> ground_spring_forces(const std::vector<GroundSpring>& springs,
                                                        const DofMap& dofs, const TpetraVector& u);

}  // namespace railfe
