#pragma once
/// \file
/// Node and side sets defined in a deck from geometry, so generated or imported meshes can be
/// loaded and probed where a scene needs it without editing the mesh file.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// One set to add. Exactly one of box, point and cylinder is given.
struct DerivedSetSpec {
  std::string name;       ///< name of the new set
  bool side_set = false;  ///< true: a side set; false: a node set
  /// Existing set to select from ("" = all nodes, or all exterior faces for a side set).
  std::string within;
  /// Selects entities whose nodes all lie in [xmin, xmax] × [ymin, ymax] × [zmin, zmax].
  std::optional<std::array<double, 6>> box;
  /// Selects the single node nearest to this point (node sets only).
  std::optional<std::array<double, 3>> point;
  std::string path;  ///< deck path of the definition, for messages
  /// Selects the nodes within a radius of an axis (node sets only): {x, y, z} of a point on the
  /// axis, {ax, ay, az} its direction, and the radius.
  std::optional<std::array<double, 7>> cylinder;
};

/// Adds the sets to \p mesh. Throws InputError (naming \p deck and the set's path) when a set's
/// name is already taken, its 'within' set does not exist, or it selects nothing.
void add_derived_sets(Mesh& mesh, const std::vector<DerivedSetSpec>& specs,
                      const std::string& deck);

/// All faces of hex8 elements not shared with another element.
std::vector<Side> exterior_faces(const Mesh& mesh);

}  // namespace railfe
