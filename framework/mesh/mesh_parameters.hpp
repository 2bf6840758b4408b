#pragma once
/// \file
/// The deck's Mesh section: where the mesh comes from, sets defined from geometry, and how it is
/// split over ranks.

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

/// Valid parameters of the Mesh section.
ParameterSpec mesh_parameters();

/// Builds the mesh a validated Mesh section describes: reads or generates it, scales it, adds the
/// deck's node and side sets and checks it. Throws InputError naming the deck and parameter.
Mesh build_mesh(const Teuchos::ParameterList& mesh_section, const Deck& deck);

/// The partitioning method the Mesh section asks for.
PartitionMethod partition_method(const Teuchos::ParameterList& mesh_section);

}  // namespace railfe
