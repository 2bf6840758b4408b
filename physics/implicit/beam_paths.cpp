#include "physics/implicit/beam_paths.hpp"

#include <algorithm>
#include <map>

#include "framework/base/error.hpp"

namespace railfe {

std::vector<PathLink> chain_of_blocks(const Mesh& mesh, const std::vector<std::string>& blocks,
                                      const std::string& deck, const std::string& path) {
  if (blocks.empty())
    throw_input_error(deck, path, "names no block", "one or more beam2 blocks");
  struct Element {
    GlobalIndex nodes[2];
    int block;
  };
  std::vector<Element> elements;
  for (const std::string& name : blocks) {
    const int b = mesh.block_index(name, deck, path);
    const ElementBlock& block = mesh.blocks[b];
    if (block.type != ElementType::beam2)
      throw_input_error(deck, path,
                        "names block '" + name + "', whose elements are " +
                            element_type_name(block.type) + ", not beams",
                        "beam2 blocks");
    for (GlobalIndex e = 0; e < block.n_elements(); ++e)
      elements.push_back({{block.element_nodes(e)[0], block.element_nodes(e)[1]}, b});
  }
  std::map<GlobalIndex, std::vector<std::size_t>> at_node;
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (GlobalIndex node : elements[e].nodes)
      at_node[node].push_back(e);
  const std::string blocks_text = "the beams of the blocks named";
  std::vector<GlobalIndex> ends;
  for (const auto& [node, list] : at_node) {
    if (list.size() > 2)
      throw_input_error(deck, path,
                        blocks_text + " branch at node " + std::to_string(node + 1) + " (" +
                            std::to_string(list.size()) + " elements meet there)",
                        "blocks whose beams form one unbranched chain");
    if (list.size() == 1)
      ends.push_back(node);
  }
  if (ends.size() != 2)
    throw_input_error(deck, path,
                      blocks_text + (ends.empty() ? " close a loop" : " fall apart in pieces"),
                      "blocks whose beams form one open chain");
  const auto position = [&](GlobalIndex node) {
    const double* x = &mesh.coordinates[3 * node];
    return std::array<double, 3>{x[0], x[1], x[2]};
  };
  GlobalIndex node = position(ends[0]) <= position(ends[1]) ? ends[0] : ends[1];
  std::vector<PathLink> chain;
  std::vector<char> used(elements.size(), 0);
  std::size_t current = at_node[node].front();
  while (true) {
    used[current] = 1;
    const Element& element = elements[current];
    const GlobalIndex next = element.nodes[0] == node ? element.nodes[1] : element.nodes[0];
    chain.push_back({node, next, element.block});
    node = next;
    const auto& list = at_node[node];
    const auto unused =
        std::find_if(list.begin(), list.end(), [&](std::size_t e) { return !used[e]; });
    if (unused == list.end())
      break;
    current = *unused;
  }
  if (chain.size() != elements.size())
    throw_input_error(deck, path, blocks_text + " fall apart in pieces",
                      "blocks whose beams form one open chain");
  return chain;
}

BeamPath make_beam_path(const Mesh& mesh, const SectionTable& sections,
                        const std::vector<PathLink>& chain,
                        const std::function<long(GlobalIndex, int)>& unknown) {
  std::vector<PathElement> elements;
  elements.reserve(chain.size());
  for (const PathLink& link : chain) {
    PathElement element{make_beam(&mesh.coordinates[3 * link.a], &mesh.coordinates[3 * link.b],
                                  sections.of_block(link.block).beam),
                        {}};
    for (int c = 0; c < 6; ++c) {
      element.unknowns[c] = unknown(link.a, c);
      element.unknowns[6 + c] = unknown(link.b, c);
    }
    elements.push_back(std::move(element));
  }
  return BeamPath(std::move(elements));
}

}  // namespace railfe
