#pragma once
/// \file
/// Paths along beams for what travels on a structure (moving loads, moving contacts): the beam2
/// elements of named blocks joined end to end into one unbranched chain, measured by arc length
/// from the chain end with the smallest (x, y, z).

#include <functional>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/implicit/moving_contact.hpp"

namespace railfe {

/// One element of a chain: its nodes in travel order and its block.
struct PathLink {
  GlobalIndex a = 0;  ///< the node where the element is entered
  GlobalIndex b = 0;  ///< the node where it is left
  int block = 0;      ///< index into Mesh::blocks
};

/// The beam2 elements of \p blocks as one chain in travel order. Throws InputError naming
/// \p deck and \p path (the parameter listing the blocks) for a block that is missing or not
/// beam2, and for elements that branch, close a loop or fall apart in pieces.
std::vector<PathLink> chain_of_blocks(const Mesh& mesh, const std::vector<std::string>& blocks,
                                      const std::string& deck, const std::string& path);

/// The BeamPath of \p chain, each element made from its block's section in \p sections, with
/// \p unknown(node, component) giving the unknown of each DOF (−1: none on this rank, or fixed).
BeamPath make_beam_path(const Mesh& mesh, const SectionTable& sections,
                        const std::vector<PathLink>& chain,
                        const std::function<long(GlobalIndex, int)>& unknown);

}  // namespace railfe
