#pragma once
/// \file
/// The mesh as read or generated: nodes, element blocks, node sets and side sets, numbered from
/// 0 across the whole model. Every rank holds this description (about 100 bytes per element);
/// fields and matrices are distributed (see MeshPartition).

#include <array>
#include <string>
#include <vector>

#include "framework/base/types.hpp"

namespace railfe {

/// Element shapes a block can hold. Solids first; the rest are the discrete parts scenes need.
enum class ElementType {
  hex8,        ///< trilinear hexahedron, Exodus node order
  beam2,       ///< two-node beam or bar
  spring2,     ///< two-node spring-damper
  point_mass,  ///< one-node mass
  rigid_link   ///< a reference node followed by the nodes it carries (any count)
};

/// Nodes per element of \p type, or 0 where the count varies per element (rigid_link).
int nodes_per_element(ElementType type);
/// Name of \p type as railfe and Exodus files write it ("HEX8", "BEAM2", ...).
std::string element_type_name(ElementType type);

/// Elements of one type and one material region.
struct ElementBlock {
  std::string name;  ///< name used in decks
  int id = 0;        ///< Exodus block id
  ElementType type = ElementType::hex8;
  GlobalIndex first_element = 0;  ///< global index of this block's element 0
  std::vector<GlobalIndex> offsets{
      0};  ///< element e's nodes are connectivity[offsets[e]..offsets[e+1])
  std::vector<GlobalIndex> connectivity;  ///< global node indices

  /// Number of elements in the block.
  GlobalIndex n_elements() const { return static_cast<GlobalIndex>(offsets.size()) - 1; }
  /// Number of nodes of element \p e (block-local index).
  int n_element_nodes(GlobalIndex e) const { return static_cast<int>(offsets[e + 1] - offsets[e]); }
  /// Pointer to the nodes of element \p e (block-local index).
  const GlobalIndex* element_nodes(GlobalIndex e) const { return connectivity.data() + offsets[e]; }
  /// Appends an element with \p nodes.
  void add_element(const GlobalIndex* nodes, int count);
};

/// A named set of nodes (sorted, unique).
struct NodeSet {
  std::string name;                ///< name used in decks
  int id = 0;                      ///< Exodus set id
  std::vector<GlobalIndex> nodes;  ///< global node indices
};

/// One face of one element: the element's global index and its face number (0-based, Exodus
/// side order).
struct Side {
  GlobalIndex element = 0;  ///< global element index
  int face = 0;             ///< 0-based face number
};

/// A named set of element faces.
struct SideSet {
  std::string name;         ///< name used in decks
  int id = 0;               ///< Exodus set id
  std::vector<Side> sides;  ///< the faces
};

/// Nodes, blocks and sets of a whole model.
class Mesh {
 public:
  std::string source;                ///< where it came from, for messages
  std::vector<double> coordinates;   ///< x, y, z of node i at 3i .. 3i+2 (m)
  std::vector<ElementBlock> blocks;  ///< element blocks in global element order
  std::vector<NodeSet> node_sets;    ///< node sets
  std::vector<SideSet> side_sets;    ///< side sets

  /// Number of nodes.
  GlobalIndex n_nodes() const { return static_cast<GlobalIndex>(coordinates.size() / 3); }
  /// Number of elements over all blocks.
  GlobalIndex n_elements() const;
  /// Coordinates of node \p node.
  std::array<double, 3> node(GlobalIndex node) const {
    return {coordinates[3 * node], coordinates[3 * node + 1], coordinates[3 * node + 2]};
  }
  /// Index of the block holding global element \p element.
  int block_of(GlobalIndex element) const;
  /// Recomputes every block's first_element from the block order.
  void number_blocks();

  /// The node set called \p name; throws InputError naming \p deck and \p path (the parameter
  /// that referred to it) and listing the sets that exist.
  const NodeSet& node_set(const std::string& name, const std::string& deck,
                          const std::string& path) const;
  /// The side set called \p name; throws InputError like node_set().
  const SideSet& side_set(const std::string& name, const std::string& deck,
                          const std::string& path) const;
  /// Index of the block called \p name; throws InputError like node_set().
  int block_index(const std::string& name, const std::string& deck, const std::string& path) const;
  /// Whether a node set called \p name exists.
  bool has_node_set(const std::string& name) const;
  /// Whether a side set called \p name exists.
  bool has_side_set(const std::string& name) const;
  /// Names of all blocks.
  std::vector<std::string> block_names() const;
};

}  // namespace railfe
