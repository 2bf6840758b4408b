#include "framework/mesh/mesh_parts.hpp"

#include <cmath>
#include <stdexcept>

namespace railfe {

namespace {

// Sine and cosine of an angle in degrees, exact at whole multiples of 90 degrees.
std::pair<double, double> sine_cosine(double degrees) {
  const double quarters = degrees / 90.0;
  if (quarters == std::round(quarters)) {
    const long long turn = static_cast<long long>(std::round(quarters)) % 4;
    static const double sines[4] = {0, 1, 0, -1};
    static const double cosines[4] = {1, 0, -1, 0};
    const int index = static_cast<int>((turn + 4) % 4);
    return {sines[index], cosines[index]};
  }
  const double radians = degrees * M_PI / 180.0;
  return {std::sin(radians), std::cos(radians)};
}

}  // namespace

std::array<std::array<double, 3>, 3> rotation_matrix(const RigidPlacement& placement) {
  const auto& a = placement.axis;
  const double length = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (!(length > 0))
    throw std::invalid_argument("railfe: rotation axis of zero length");
  const std::array<double, 3> k{a[0] / length, a[1] / length, a[2] / length};
  const auto [s, c] = sine_cosine(placement.angle_degrees);
  // Rodrigues: R = c I + s [k]x + (1 - c) k kᵀ.
  std::array<std::array<double, 3>, 3> r{};
  const double cross[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      r[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + (1 - c) * k[i] * k[j];
  }
  return r;
}

void place_mesh(Mesh& mesh, const RigidPlacement& placement) {
  const auto r = rotation_matrix(placement);
  const auto& t = placement.translation;
  for (GlobalIndex n = 0; n < mesh.n_nodes(); ++n) {
    double* x = mesh.coordinates.data() + 3 * n;
    const double p[3] = {x[0], x[1], x[2]};
    for (int i = 0; i < 3; ++i)
      x[i] = r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i];
  }
}

void append_part(Mesh& model, const Mesh& part, const std::string& part_name) {
  const GlobalIndex node_offset = model.n_nodes();
  const GlobalIndex element_offset = model.n_elements();
  const std::string prefix = part_name + ".";
  model.coordinates.insert(model.coordinates.end(), part.coordinates.begin(),
                           part.coordinates.end());
  for (ElementBlock block : part.blocks) {
    block.name = prefix + block.name;
    for (GlobalIndex& node : block.connectivity)
      node += node_offset;
    model.blocks.push_back(std::move(block));
  }
  for (NodeSet set : part.node_sets) {
    set.name = prefix + set.name;
    for (GlobalIndex& node : set.nodes)
      node += node_offset;
    model.node_sets.push_back(std::move(set));
  }
  for (SideSet set : part.side_sets) {
    set.name = prefix + set.name;
    for (Side& side : set.sides)
      side.element += element_offset;
    model.side_sets.push_back(std::move(set));
  }
  model.number_blocks();
  for (std::size_t i = 0; i < model.blocks.size(); ++i)
    model.blocks[i].id = static_cast<int>(i) + 1;
  for (std::size_t i = 0; i < model.node_sets.size(); ++i)
    model.node_sets[i].id = static_cast<int>(i) + 1;
  for (std::size_t i = 0; i < model.side_sets.size(); ++i)
    model.side_sets[i].id = static_cast<int>(i) + 1;
}

Mesh mesh_of_blocks(const Mesh& mesh, const std::vector<int>& keep) {
  Mesh result = mesh;
  std::vector<char> kept(mesh.blocks.size(), 0);
  for (int b : keep)
    kept[b] = 1;
  for (std::size_t b = 0; b < result.blocks.size(); ++b) {
    if (kept[b])
      continue;
    result.blocks[b].offsets = {0};
    result.blocks[b].connectivity.clear();
  }
  result.number_blocks();
  for (SideSet& set : result.side_sets) {
    std::vector<Side> sides;
    for (const Side& side : set.sides) {
      const int b = mesh.block_of(side.element);
      if (kept[b])
        sides.push_back(
            {result.blocks[b].first_element + (side.element - mesh.blocks[b].first_element),
             side.face});
    }
    set.sides = std::move(sides);
  }
  return result;
}

std::vector<char> used_nodes(const Mesh& mesh) {
  std::vector<char> used(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (const ElementBlock& block : mesh.blocks)
    for (GlobalIndex node : block.connectivity)
      used[node] = 1;
  return used;
}

}  // namespace railfe
