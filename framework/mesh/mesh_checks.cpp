#include "framework/mesh/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/mesh/hex8_shape.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

double hex8_jacobian_quality(const double x[8][3]) {
  static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double longest = 0;
  for (const auto& edge : kEdges) {
    double length = 0;
    for (int d = 0; d < 3; ++d)
      length += std::pow(x[edge[1]][d] - x[edge[0]][d], 2);
    longest = std::max(longest, length);
  }
  if (longest == 0)
    return 0;
  const double half_edge = std::sqrt(longest) / 2;
  const Hex8GaussTable& table = hex8_gauss_table();
  double gradient[3][8];
  double smallest = 1e300;
  for (int q = 0; q < 8; ++q)
    smallest = std::min(smallest, hex8_gradients(x, table.dN[q], gradient));
  return smallest / (half_edge * half_edge * half_edge);
}

namespace {

void check_nodes(const Mesh& mesh) {
  for (GlobalIndex i = 0; i < static_cast<GlobalIndex>(mesh.coordinates.size()); ++i) {
    if (!std::isfinite(mesh.coordinates[i])) {
      throw_input_error(
          mesh.source, "",
          "node " + std::to_string(i / 3 + 1) + " has a coordinate that is not a finite number");
    }
  }
}

void check_connectivity(const Mesh& mesh) {
  const GlobalIndex n_nodes = mesh.n_nodes();
  for (const auto& block : mesh.blocks) {
    const int expected = nodes_per_element(block.type);
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const int count = block.n_element_nodes(e);
      if ((expected > 0 && count != expected) || count == 0) {
        throw_input_error(mesh.source, "block " + block.name,
                          "element " + std::to_string(block.first_element + e + 1) + " has " +
                              std::to_string(count) + " nodes",
                          std::to_string(expected) + " nodes for " + element_type_name(block.type));
      }
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < count; ++a) {
        if (nodes[a] < 0 || nodes[a] >= n_nodes) {
          throw_input_error(mesh.source, "block " + block.name,
                            "element " + std::to_string(block.first_element + e + 1) +
                                " refers to node " + std::to_string(nodes[a] + 1) +
                                ", which does not exist",
                            "node ids 1.." + std::to_string(n_nodes));
        }
      }
    }
  }
}

void check_hex8_shapes(const Mesh& mesh) {
  for (const auto& block : mesh.blocks) {
    if (block.type != ElementType::hex8)
      continue;
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      double x[8][3];
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < 8; ++a) {
        for (int d = 0; d < 3; ++d)
          x[a][d] = mesh.coordinates[3 * nodes[a] + d];
      }
      const double quality = hex8_jacobian_quality(x);
      if (quality > 1e-8)
        continue;
      std::ostringstream problem;
      problem << "element " << block.first_element + e + 1 << " (hex8, nodes";
      for (int a = 0; a < 8; ++a)
        problem << " " << nodes[a] + 1;
      problem << ") is " << (quality < -1e-8 ? "inverted" : "degenerate") << ": Jacobian quality "
              << quality << " at an integration point";
      throw_input_error(mesh.source, "block " + block.name, problem.str(),
                        "positive Jacobians at the integration points (nodes 0-3 counter-"
                        "clockwise seen from nodes 4-7, no collapsed edges or faces)");
    }
  }
}

void check_sets(const Mesh& mesh) {
  const GlobalIndex n_nodes = mesh.n_nodes();
  const GlobalIndex n_elements = mesh.n_elements();
  for (const auto& set : mesh.node_sets) {
    for (GlobalIndex node : set.nodes) {
      if (node < 0 || node >= n_nodes) {
        throw_input_error(mesh.source, "node set " + set.name,
                          "refers to node " + std::to_string(node + 1) + ", which does not exist",
                          "node ids 1.." + std::to_string(n_nodes));
      }
    }
  }
  for (const auto& set : mesh.side_sets) {
    for (const Side& side : set.sides) {
      if (side.element < 0 || side.element >= n_elements) {
        throw_input_error(
            mesh.source, "side set " + set.name,
            "refers to element " + std::to_string(side.element + 1) + ", which does not exist",
            "element ids 1.." + std::to_string(n_elements));
      }
      const auto& block = mesh.blocks[mesh.block_of(side.element)];
      if (block.type != ElementType::hex8 || side.face < 0 || side.face > 5) {
        throw_input_error(mesh.source, "side set " + set.name,
                          "refers to side " + std::to_string(side.face + 1) + " of element " +
                              std::to_string(side.element + 1) + " (" +
                              element_type_name(block.type) + ")",
                          "sides 1-6 of HEX8 elements");
      }
    }
  }
}

}  // namespace

void check_mesh(const Mesh& mesh) {
  if (mesh.n_nodes() == 0 || mesh.n_elements() == 0) {
    throw_input_error(mesh.source, "", "the mesh has no nodes or no elements");
  }
  check_nodes(mesh);
  check_connectivity(mesh);
  check_hex8_shapes(mesh);
  check_sets(mesh);
}

double block_volume(const Mesh& mesh, const ElementBlock& block) {
  if (block.type != ElementType::hex8)
    return 0;
  const Hex8GaussTable& table = hex8_gauss_table();
  double sum = 0;
  double x[8][3], gradient[3][8];
  for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
    for (int a = 0; a < 8; ++a) {
      for (int d = 0; d < 3; ++d)
        x[a][d] = mesh.coordinates[3 * block.element_nodes(e)[a] + d];
    }
    for (int q = 0; q < 8; ++q)
      sum += hex8_gradients(x, table.dN[q], gradient);
  }
  return sum;
}

}  // namespace railfe
