#pragma once
/// \file
/// Models of several parts: each part is a mesh in its own coordinates, placed by a rigid motion
/// and appended to the model under names prefixed by the part (Abaqus' instance.set
/// convention). Parts share no nodes: coincident nodes of two parts stay distinct, so parts
/// interact only through what the deck adds (ties, contact).

#include <array>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// A rigid placement x -> R x + t: the rotation R turns by angle_degrees about axis (through
/// the origin, right-hand rule) and comes first; the translation t follows.
struct RigidPlacement {
  std::array<double, 3> axis{0, 0, 1};  ///< rotation axis (any length > 0)
  double angle_degrees = 0;             ///< rotation angle (degrees)
  std::array<double, 3> translation{};  ///< translation after the rotation (m)
};

/// The rotation matrix of \p placement, row-major. Angles that are whole multiples of 90
/// degrees give exact sines and cosines, so quarter and half turns leave no round-off in
/// coordinates that should coincide. Throws std::invalid_argument for an axis of zero length
/// (the deck reader refuses it first, naming the parameter).
std::array<std::array<double, 3>, 3> rotation_matrix(const RigidPlacement& placement);

/// Moves every node of \p mesh by \p placement. A rotation keeps every element's orientation
/// (its determinant is +1), so volumes and face normals move with the nodes.
void place_mesh(Mesh& mesh, const RigidPlacement& placement);

/// Appends \p part to \p model: its nodes and elements numbered after the model's, its blocks,
/// node sets and side sets renamed "<part_name>.<name>", and the Exodus ids of all blocks and
/// sets renumbered 1, 2, ... in model order so they are unique over the model.
void append_part(Mesh& model, const Mesh& part, const std::string& part_name);

/// The model of \p mesh reduced to the blocks \p keep (indices into Mesh::blocks): the other
/// blocks stay, with no elements, so block indices (and the material of each) are unchanged;
/// nodes and node sets stay as they are (a node no kept element uses carries no unknowns in a
/// MeshPartition of the result); side sets keep the faces of kept elements, renumbered.
Mesh mesh_of_blocks(const Mesh& mesh, const std::vector<int>& keep);

/// Whether some element of \p mesh uses each node (by global node index).
std::vector<char> used_nodes(const Mesh& mesh);

}  // namespace railfe
