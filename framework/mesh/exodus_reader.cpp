#include <exodusII.h>

#include <algorithm>
#include <cctype>

#include "framework/base/error.hpp"
#include "framework/mesh/exodus_file.hpp"
#include "framework/mesh/mesh_readers.hpp"

namespace railfe {

namespace {

ElementType element_type_from_exodus(std::string name, int nodes, const std::string& path,
                                     const std::string& block) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (name.rfind("HEX", 0) == 0 && nodes == 8)
    return ElementType::hex8;
  if ((name.rfind("BAR", 0) == 0 || name.rfind("BEAM", 0) == 0 || name.rfind("TRUSS", 0) == 0) &&
      nodes == 2) {
    return ElementType::beam2;
  }
  if (name.rfind("SPRING", 0) == 0 && nodes == 2)  // as railfe writes spring2 blocks
    return ElementType::spring2;
  if (name.rfind("SPHERE", 0) == 0 && nodes == 1)
    return ElementType::point_mass;
  throw_input_error(
      path, "block " + block,
      "element type " + name + " with " + std::to_string(nodes) + " nodes is not supported",
      "HEX8, BAR2/BEAM2, SPRING2, SPHERE");
}

std::vector<int64_t> entity_ids(const ExodusFile& file, ex_entity_type type, int64_t count) {
  std::vector<int64_t> ids(count);
  if (count > 0)
    file.check(ex_get_ids(file.id(), type, ids.data()), "reading entity ids");
  return ids;
}

}  // namespace

Mesh read_exodus_mesh(const std::string& path) {
  ExodusFile file(path, ExodusMode::read);
  ex_init_params init{};
  file.check(ex_get_init_ext(file.id(), &init), "reading the header");
  if (init.num_dim != 3) {
    throw_input_error(path, "", "has " + std::to_string(init.num_dim) + " dimensions",
                      "3-D meshes");
  }
  Mesh mesh;
  mesh.source = path;
  const int64_t n_nodes = init.num_nodes;
  std::vector<double> x(n_nodes), y(n_nodes), z(n_nodes);
  file.check(ex_get_coord(file.id(), x.data(), y.data(), z.data()), "reading coordinates");
  mesh.coordinates.resize(3 * n_nodes);
  for (int64_t i = 0; i < n_nodes; ++i) {
    mesh.coordinates[3 * i] = x[i];
    mesh.coordinates[3 * i + 1] = y[i];
    mesh.coordinates[3 * i + 2] = z[i];
  }

  const auto block_ids = entity_ids(file, EX_ELEM_BLOCK, init.num_elem_blk);
  const auto block_names = file.names(EX_ELEM_BLOCK, static_cast<int>(init.num_elem_blk));
  for (std::size_t b = 0; b < block_ids.size(); ++b) {
    char type_name[MAX_STR_LENGTH + 1] = {0};
    int64_t n_entries = 0, n_per_entry = 0, n_edges = 0, n_faces = 0, n_attributes = 0;
    file.check(ex_get_block(file.id(), EX_ELEM_BLOCK, block_ids[b], type_name, &n_entries,
                            &n_per_entry, &n_edges, &n_faces, &n_attributes),
               "reading block parameters");
    ElementBlock block;
    block.id = static_cast<int>(block_ids[b]);
    block.name = block_names[b].empty() ? "block_" + std::to_string(block.id) : block_names[b];
    block.type =
        element_type_from_exodus(type_name, static_cast<int>(n_per_entry), path, block.name);
    std::vector<int64_t> connectivity(n_entries * n_per_entry);
    if (n_entries > 0) {
      file.check(ex_get_conn(file.id(), EX_ELEM_BLOCK, block_ids[b], connectivity.data(), nullptr,
                             nullptr),
                 "reading connectivity of block " + block.name);
    }
    block.connectivity.assign(connectivity.begin(), connectivity.end());
    for (auto& node : block.connectivity)
      node -= 1;  // Exodus numbers from 1
    block.offsets.resize(n_entries + 1);
    for (int64_t e = 0; e <= n_entries; ++e)
      block.offsets[e] = e * n_per_entry;
    mesh.blocks.push_back(std::move(block));
  }
  mesh.number_blocks();

  const auto node_set_ids = entity_ids(file, EX_NODE_SET, init.num_node_sets);
  const auto node_set_names = file.names(EX_NODE_SET, static_cast<int>(init.num_node_sets));
  for (std::size_t s = 0; s < node_set_ids.size(); ++s) {
    int64_t count = 0, n_factors = 0;
    file.check(ex_get_set_param(file.id(), EX_NODE_SET, node_set_ids[s], &count, &n_factors),
               "reading node set parameters");
    std::vector<int64_t> nodes(count);
    if (count > 0) {
      file.check(ex_get_set(file.id(), EX_NODE_SET, node_set_ids[s], nodes.data(), nullptr),
                 "reading node set");
    }
    NodeSet set;
    set.id = static_cast<int>(node_set_ids[s]);
    set.name = node_set_names[s].empty() ? "nodelist_" + std::to_string(set.id) : node_set_names[s];
    for (int64_t node : nodes)
      set.nodes.push_back(node - 1);
    std::sort(set.nodes.begin(), set.nodes.end());
    set.nodes.erase(std::unique(set.nodes.begin(), set.nodes.end()), set.nodes.end());
    mesh.node_sets.push_back(std::move(set));
  }

  const auto side_set_ids = entity_ids(file, EX_SIDE_SET, init.num_side_sets);
  const auto side_set_names = file.names(EX_SIDE_SET, static_cast<int>(init.num_side_sets));
  for (std::size_t s = 0; s < side_set_ids.size(); ++s) {
    int64_t count = 0, n_factors = 0;
    file.check(ex_get_set_param(file.id(), EX_SIDE_SET, side_set_ids[s], &count, &n_factors),
               "reading side set parameters");
    std::vector<int64_t> elements(count), faces(count);
    if (count > 0) {
      file.check(ex_get_set(file.id(), EX_SIDE_SET, side_set_ids[s], elements.data(), faces.data()),
                 "reading side set");
    }
    SideSet set;
    set.id = static_cast<int>(side_set_ids[s]);
    set.name = side_set_names[s].empty() ? "surface_" + std::to_string(set.id) : side_set_names[s];
    for (int64_t i = 0; i < count; ++i) {
      set.sides.push_back({elements[i] - 1, static_cast<int>(faces[i]) - 1});
    }
    mesh.side_sets.push_back(std::move(set));
  }
  return mesh;
}

}  // namespace railfe
