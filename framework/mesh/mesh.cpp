#include "framework/mesh/mesh.hpp"

#include <algorithm>

#include "framework/base/error.hpp"

namespace railfe {

int nodes_per_element(ElementType type) {
  switch (type) {
    case ElementType::hex8:
      return 8;
    case ElementType::beam2:
      return 2;
    case ElementType::spring2:
      return 2;
    case ElementType::point_mass:
      return 1;
    case ElementType::rigid_link:
      return 0;
  }
  return 0;
}

std::string element_type_name(ElementType type) {
  switch (type) {
    case ElementType::hex8:
      return "HEX8";
    case ElementType::beam2:
      return "BEAM2";
    case ElementType::spring2:
      return "SPRING2";
    case ElementType::point_mass:
      return "SPHERE";
    case ElementType::rigid_link:
      return "RIGIDLINK";
  }
  return "?";
}

void ElementBlock::add_element(const GlobalIndex* nodes, int count) {
  connectivity.insert(connectivity.end(), nodes, nodes + count);
  offsets.push_back(static_cast<GlobalIndex>(connectivity.size()));
}

GlobalIndex Mesh::n_elements() const {
  GlobalIndex total = 0;
  for (const auto& block : blocks)
    total += block.n_elements();
  return total;
}

int Mesh::block_of(GlobalIndex element) const {
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (element < blocks[b].first_element + blocks[b].n_elements())
      return static_cast<int>(b);
  }
  return -1;
}

void Mesh::number_blocks() {
  GlobalIndex first = 0;
  for (auto& block : blocks) {
    block.first_element = first;
    first += block.n_elements();
  }
}

namespace {

template <typename Set>
std::vector<std::string> set_names(const std::vector<Set>& sets) {
  std::vector<std::string> names;
  for (const auto& set : sets)
    names.push_back(set.name);
  return names;
}

template <typename Set>
const Set& find_set(const std::vector<Set>& sets, const std::string& name, const char* kind,
                    const std::string& deck, const std::string& path, const std::string& mesh) {
  for (const auto& set : sets) {
    if (set.name == name)
      return set;
  }
  const auto names = set_names(sets);
  std::string problem = std::string("unknown ") + kind + " '" + name + "' in mesh '" + mesh + "'";
  const std::string guess = closest_name(name, names);
  if (!guess.empty())
    problem += " (did you mean '" + guess + "'?)";
  throw_input_error(deck, path, problem, quoted_list(names, 40));
}

}  // namespace

const NodeSet& Mesh::node_set(const std::string& name, const std::string& deck,
                              const std::string& path) const {
  return find_set(node_sets, name, "node set", deck, path, source);
}

const SideSet& Mesh::side_set(const std::string& name, const std::string& deck,
                              const std::string& path) const {
  return find_set(side_sets, name, "side set", deck, path, source);
}

int Mesh::block_index(const std::string& name, const std::string& deck,
                      const std::string& path) const {
  const auto& block = find_set(blocks, name, "element block", deck, path, source);
  return static_cast<int>(&block - blocks.data());
}

bool Mesh::has_node_set(const std::string& name) const {
  return std::any_of(node_sets.begin(), node_sets.end(),
                     [&](const NodeSet& set) { return set.name == name; });
}

bool Mesh::has_side_set(const std::string& name) const {
  return std::any_of(side_sets.begin(), side_sets.end(),
                     [&](const SideSet& set) { return set.name == name; });
}

std::vector<std::string> Mesh::block_names() const {
  return set_names(blocks);
}

}  // namespace railfe
