#include "framework/mesh/box_generator.hpp"

#include <algorithm>
#include <cmath>

namespace railfe {

std::vector<double> graded_positions(double start, double length, int n, double grading) {
  std::vector<double> positions(n + 1, start);
  const double ratio = n > 1 ? std::pow(grading, 1.0 / (n - 1)) : 1.0;
  std::vector<double> sizes(n, 1.0);
  double total = 0;
  for (int i = 0; i < n; ++i) {
    sizes[i] = std::pow(ratio, i);
    total += sizes[i];
  }
  double position = start;
  for (int i = 0; i < n; ++i) {
    position += length * sizes[i] / total;
    positions[i + 1] = position;
  }
  positions[n] = start + length;  // exact end despite round-off in the sum
  return positions;
}

Mesh generate_box(const BoxSpec& spec) {
  const int nx = spec.elements[0], ny = spec.elements[1], nz = spec.elements[2];
  std::array<std::vector<double>, 3> axis;
  for (int d = 0; d < 3; ++d) {
    axis[d] = graded_positions(spec.origin[d], spec.lengths[d], spec.elements[d], spec.grading[d]);
  }
  const GlobalIndex px = nx + 1, py = ny + 1, pz = nz + 1;
  auto node_index = [&](GlobalIndex i, GlobalIndex j, GlobalIndex k) {
    return i + px * (j + py * k);
  };

  Mesh mesh;
  mesh.source = "generated box";
  mesh.coordinates.resize(3 * px * py * pz);
  for (GlobalIndex k = 0; k < pz; ++k) {
    for (GlobalIndex j = 0; j < py; ++j) {
      for (GlobalIndex i = 0; i < px; ++i) {
        const GlobalIndex n = node_index(i, j, k);
        mesh.coordinates[3 * n] = axis[0][i];
        mesh.coordinates[3 * n + 1] = axis[1][j];
        mesh.coordinates[3 * n + 2] = axis[2][k];
      }
    }
  }

  ElementBlock block;
  block.name = spec.block_name;
  block.id = 1;
  block.type = ElementType::hex8;
  const GlobalIndex n_elements = static_cast<GlobalIndex>(nx) * ny * nz;
  block.offsets.reserve(n_elements + 1);
  block.connectivity.reserve(8 * n_elements);
  for (GlobalIndex k = 0; k < nz; ++k) {
    for (GlobalIndex j = 0; j < ny; ++j) {
      for (GlobalIndex i = 0; i < nx; ++i) {
        const GlobalIndex nodes[8] = {node_index(i, j, k),
                                      node_index(i + 1, j, k),
                                      node_index(i + 1, j + 1, k),
                                      node_index(i, j + 1, k),
                                      node_index(i, j, k + 1),
                                      node_index(i + 1, j, k + 1),
                                      node_index(i + 1, j + 1, k + 1),
                                      node_index(i, j + 1, k + 1)};
        block.add_element(nodes, 8);
      }
    }
  }
  mesh.blocks.push_back(std::move(block));
  mesh.number_blocks();

  // Faces: (axis, side, Exodus face number) for xmin, xmax, ymin, ymax, zmin, zmax.
  struct Face {
    const char* name;
    int axis;
    bool high;
    int face;
  };
  const Face faces[6] = {{"xmin", 0, false, 3}, {"xmax", 0, true, 1},  {"ymin", 1, false, 0},
                         {"ymax", 1, true, 2},  {"zmin", 2, false, 4}, {"zmax", 2, true, 5}};
  const std::array<GlobalIndex, 3> node_counts{px, py, pz};
  const std::array<int, 3> element_counts{nx, ny, nz};
  int set_id = 1;
  for (const Face& face : faces) {
    NodeSet nodes{face.name, set_id, {}};
    SideSet sides{face.name, set_id, {}};
    ++set_id;
    const int a = face.axis, b = (face.axis + 1) % 3, c = (face.axis + 2) % 3;
    const GlobalIndex fixed_node = face.high ? node_counts[a] - 1 : 0;
    const GlobalIndex fixed_element = face.high ? element_counts[a] - 1 : 0;
    for (GlobalIndex v = 0; v < node_counts[c]; ++v) {
      for (GlobalIndex u = 0; u < node_counts[b]; ++u) {
        std::array<GlobalIndex, 3> ijk{};
        ijk[a] = fixed_node;
        ijk[b] = u;
        ijk[c] = v;
        nodes.nodes.push_back(node_index(ijk[0], ijk[1], ijk[2]));
      }
    }
    for (GlobalIndex v = 0; v < element_counts[c]; ++v) {
      for (GlobalIndex u = 0; u < element_counts[b]; ++u) {
        std::array<GlobalIndex, 3> ijk{};
        ijk[a] = fixed_element;
        ijk[b] = u;
        ijk[c] = v;
        sides.sides.push_back(
            {ijk[0] + nx * (ijk[1] + static_cast<GlobalIndex>(ny) * ijk[2]), face.face});
      }
    }
    std::sort(nodes.nodes.begin(), nodes.nodes.end());
    mesh.node_sets.push_back(std::move(nodes));
    mesh.side_sets.push_back(std::move(sides));
  }
  return mesh;
}

}  // namespace railfe
