#pragma once
/// \file
/// The deck's Mesh section: where the mesh comes from, sets defined from geometry, and how it is
/// split over ranks. Besides the framework's own types (box, exodus, gmsh, revolved), Mesh/Type
/// accepts the names of mesh generators that physics code registers (a wheel from its profile):
/// the framework never names them.

#include <functional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/partition.hpp"

namespace railfe {

/// A mesh generator provided by physics code: Mesh/Type <name>, configured by the Mesh sublist
/// named generator_sublist_name(name) ("wheel" -> "Wheel").
struct MeshGeneratorDescriptor {
  std::string name;     ///< the value of Mesh/Type
  std::string summary;  ///< one line for --describe
  /// The valid parameters of its sublist (validated with the Mesh section, defaults filled in).
  std::function<ParameterSpec()> parameters;
  /// Builds the mesh from the validated sublist; \p deck resolves relative file names and names
  /// the deck in messages (paths "Mesh/<Sublist>/..."). Runs on every rank and must give every
  /// rank the same mesh; throws InputError or RunError.
  std::function<Mesh(const Teuchos::ParameterList& sublist, const Deck& deck)> build;
};

/// The sublist that configures generator \p name: the name with its first letter capitalised.
std::string generator_sublist_name(const std::string& name);

/// Valid parameters of the Mesh section, with a Type and a sublist for each of \p generators.
ParameterSpec mesh_parameters(const std::vector<MeshGeneratorDescriptor>& generators = {});

/// Builds the mesh a validated Mesh section describes: reads or generates it (with \p generators
/// for the types they provide), scales it, adds the deck's node and side sets and checks it.
/// Throws InputError naming the deck and parameter.
Mesh build_mesh(const Teuchos::ParameterList& mesh_section, const Deck& deck,
                const std::vector<MeshGeneratorDescriptor>& generators = {});

/// The partitioning method the Mesh section asks for.
PartitionMethod partition_method(const Teuchos::ParameterList& mesh_section);

}  // namespace railfe
