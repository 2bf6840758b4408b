#include "framework/mesh/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

double hex8_scaled_corner_jacobian(const double x[8][3]) {
  // Each corner's three edges, in the order that gives a positive determinant for a valid hex.
  static constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                             {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  double longest = 0;
  double smallest = 1e300;
  for (int corner = 0; corner < 8; ++corner) {
    double e[3][3];
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d) e[k][d] = x[kCornerEdges[corner][k]][d] - x[corner][d];
      longest = std::max(longest, e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2]);
    }
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    smallest = std::min(smallest, det);
  }
  longest = std::sqrt(longest);
  if (longest == 0) return 0;
  return smallest / (longest * longest * longest);
}

namespace {

void check_nodes(const Mesh& mesh) {
  for (GlobalIndex i = 0; i < static_cast<GlobalIndex>(mesh.coordinates.size()); ++i) {
    if (!std::isfinite(mesh.coordinates[i])) {
      throw_input_error(mesh.source, "", "node " + std::to_string(i / 3 + 1) +
                                             " has a coordinate that is not a finite number");
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
        throw_input_error(mesh.source, "block '" + block.name + "'",
                          "element " + std::to_string(block.first_element + e + 1) + " has " +
                              std::to_string(count) + " nodes",
                          std::to_string(expected) + " nodes for " +
                              element_type_name(block.type));
      }
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < count; ++a) {
        if (nodes[a] < 0 || nodes[a] >= n_nodes) {
          throw_input_error(mesh.source, "block '" + block.name + "'",
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
    if (block.type != ElementType::hex8) continue;
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      double x[8][3];
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < 8; ++a) {
        for (int d = 0; d < 3; ++d) x[a][d] = mesh.coordinates[3 * nodes[a] + d];
      }
      const double quality = hex8_scaled_corner_jacobian(x);
      if (quality > 1e-10) continue;
      std::ostringstream problem;
      problem << "element " << block.first_element + e + 1 << " (hex8, nodes";
      for (int a = 0; a < 8; ++a) problem << " " << nodes[a] + 1;
      problem << ") is " << (quality < -1e-10 ? "inverted" : "degenerate")
              << ": scaled corner Jacobian " << quality;
      throw_input_error(mesh.source, "block '" + block.name + "'", problem.str(),
                        "positive corner Jacobians (nodes 0-3 counter-clockwise seen from "
                        "nodes 4-7, no collapsed edges or faces)");
    }
  }
}

void check_sets(const Mesh& mesh) {
  const GlobalIndex n_nodes = mesh.n_nodes();
  const GlobalIndex n_elements = mesh.n_elements();
  for (const auto& set : mesh.node_sets) {
    for (GlobalIndex node : set.nodes) {
      if (node < 0 || node >= n_nodes) {
        throw_input_error(mesh.source, "node set '" + set.name + "'",
                          "refers to node " + std::to_string(node + 1) + ", which does not exist",
                          "node ids 1.." + std::to_string(n_nodes));
      }
    }
  }
  for (const auto& set : mesh.side_sets) {
    for (const Side& side : set.sides) {
      if (side.element < 0 || side.element >= n_elements) {
        throw_input_error(mesh.source, "side set '" + set.name + "'",
                          "refers to element " + std::to_string(side.element + 1) +
                              ", which does not exist",
                          "element ids 1.." + std::to_string(n_elements));
      }
      const auto& block = mesh.blocks[mesh.block_of(side.element)];
      if (block.type != ElementType::hex8 || side.face < 0 || side.face > 5) {
        throw_input_error(mesh.source, "side set '" + set.name + "'",
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

}  // namespace railfe
