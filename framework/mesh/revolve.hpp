#pragma once
/// \file
/// Hex8 meshes swept from a quadrilateral mesh of a cross-section: bodies of revolution (wheels,
/// rings, axles) revolved about the global y axis, and prismatic bodies (rails) extruded along
/// x. Railfe's axes are x along the track, y lateral and z up, so a wheel turns about y: the
/// section point (r, a) at angle θ lands at (x, y, z) = (r cos θ, a, r sin θ). A revolved mesh
/// with equal slices is cyclic-symmetric: every slice is the same.

#include <array>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// Name and Exodus id of one region of a section; it becomes an element block.
struct SectionBlock {
  std::string name;  ///< block name used in decks
  int id = 0;        ///< Exodus block id
};

/// A planar quadrilateral mesh of a cross-section in (r, a): distance from the axis and position
/// along it. Node sets are named groups of section nodes (the curve of a bore, of a tread...).
struct SectionMesh {
  std::string source;                             ///< where it came from, for messages
  std::vector<double> coordinates;                ///< r, a of node i at 2i, 2i + 1 (m)
  std::vector<std::array<GlobalIndex, 4>> quads;  ///< corners, in order around, either sense
  std::vector<int> quad_blocks;                   ///< index into blocks of each quad
  std::vector<SectionBlock> blocks;               ///< the regions
  std::vector<NodeSet> node_sets;                 ///< named groups of section nodes

  /// Number of section nodes.
  GlobalIndex n_nodes() const { return static_cast<GlobalIndex>(coordinates.size() / 2); }
  /// Area of the section (sum of the quads' areas; straight edges).
  double area() const;
};

/// Revolves \p section through 360° in \p n_around equal slices and merges the seam, giving
/// exactly n_around × section.n_nodes() nodes: node i of the section at slice k (θ = 2πk /
/// n_around) is node k · section.n_nodes() + i. Each quad gives one hex per slice, its nodes
/// ordered so the Jacobian is positive (quads may come in either sense); blocks keep the
/// section's names and ids, with elements numbered slice by slice. Every section node set
/// becomes the node set of all its revolved nodes, and, where two of its nodes bound a section
/// edge on the boundary, also a side set of the same name covering those revolved faces.
/// Each slice spans a chord rather than an arc, so for any section the volume is n sin(2π/n)/2π
/// of the exact body's (1 − (2π/n)²/6 to leading order). Throws InputError naming section.source
/// when a node has r ≤ 0 or \p n_around < 3.
Mesh revolve(const SectionMesh& section, int n_around);

/// revolve() with slices between the given angles (radians, increasing, the first in [0, 2π) and
/// the last below the first + 2π), so a body can be refined over an arc: slice k spans
/// angles[k] to angles[k + 1] (the last closes to angles[0]). Throws InputError as revolve().
Mesh revolve(const SectionMesh& section, const std::vector<double>& angles);

/// revolve() with slices that coarsen towards the axis, so that a body refined over an arc at
/// its rim does not carry the arc's slices, ever thinner, down to its bore. Section node i
/// exists only at the angles of its level \p node_level[i]: level 0 has every angle, level l > 0
/// the angle indices \p coarser_slices[l − 1] (increasing, from index 0, a subset of level
/// l − 1's, each of its slices spanning one or three of level l − 1's). A quad whose nodes share
/// a level is revolved through that level's slices. A transition quad has two adjacent nodes at
/// level l − 1 and two at level l: where its slice spans three finer ones it becomes four hexes,
/// the 3-to-1 template of the (radial, circumferential) plane swept across the quad, with new
/// nodes half way along its two edges that join the levels, at the finer angles in between.
/// Node sets hold the revolved nodes of their section nodes; side sets as revolve(). Throws
/// InputError as revolve(); std::logic_error for levels that do not fit these rules or a side
/// set along a transition quad.
Mesh revolve(const SectionMesh& section, const std::vector<double>& angles,
             const std::vector<int>& node_level,
             const std::vector<std::vector<std::size_t>>& coarser_slices);

/// The section swept along x: section point (u, v) at station k goes to (stations[k], u, v), so
/// a section drawn with u lateral and v up gives a prismatic body along the track. Stations
/// increase. Blocks, node sets and side sets as revolve(), plus the node and side sets
/// "start_face" (x = stations.front()) and "end_face" (x = stations.back()).
Mesh extrude(const SectionMesh& section, const std::vector<double>& stations);

}  // namespace railfe
