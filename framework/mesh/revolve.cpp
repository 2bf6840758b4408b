#include "framework/mesh/revolve.hpp"
#include "framework/base/constants.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/mesh/revolve_detail.hpp"

namespace railfe {

namespace {

double signed_area(const SectionMesh& section, const std::array<GlobalIndex, 4>& quad) {
  double twice = 0;
  for (int j = 0; j < 4; ++j) {
    const GlobalIndex p = quad[j], q = quad[(j + 1) % 4];
    twice += section.coordinates[2 * p] * section.coordinates[2 * q + 1] -
             section.coordinates[2 * q] * section.coordinates[2 * p + 1];
  }
  return twice / 2;
}

}  // namespace

void check_section(const SectionMesh& section, int n_around) {
  if (n_around < 3) {
    throw_input_error(section.source, "elements around",
                      "asks for " + std::to_string(n_around) + " elements around the axis",
                      "at least 3");
  }
  for (GlobalIndex i = 0; i < section.n_nodes(); ++i) {
    const double r = section.coordinates[2 * i];
    if (!(r > 0)) {
      std::ostringstream problem;
      problem << "section node " << i + 1 << " has r = " << r
              << " m (a = " << section.coordinates[2 * i + 1]
              << " m), on or across the axis of revolution";
      throw_input_error(section.source, "", problem.str(),
                        "r > 0 at every node (a body through the axis needs a small bore)");
    }
  }
  if (section.quad_blocks.size() != section.quads.size())
    throw std::logic_error("railfe: revolve: one block index per quad expected");
}

void check_angles(const std::vector<double>& angles) {
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double next = k + 1 < angles.size() ? angles[k + 1] : angles[0] + 2 * kPi;
    if (!(next > angles[k]) || (k == 0 && angles[0] < 0))
      throw std::logic_error("railfe: revolve: angles must increase within [0, 2π)");
  }
}

// The (r, a) sense decides the hex orientation: see revolve_detail.hpp.
std::vector<std::array<GlobalIndex, 4>> oriented_quads(const SectionMesh& section) {
  auto quads = section.quads;
  for (auto& quad : quads) {
    if (signed_area(section, quad) < 0)
      std::swap(quad[1], quad[3]);
  }
  return quads;
}

std::vector<std::pair<std::size_t, int>> boundary_edges(
    const std::vector<std::array<GlobalIndex, 4>>& quads) {
  std::map<std::pair<GlobalIndex, GlobalIndex>, std::pair<std::pair<std::size_t, int>, int>> seen;
  for (std::size_t q = 0; q < quads.size(); ++q) {
    for (int j = 0; j < 4; ++j) {
      const GlobalIndex p = quads[q][j], s = quads[q][(j + 1) % 4];
      auto [it, inserted] =
          seen.emplace(std::minmax(p, s), std::make_pair(std::make_pair(q, j), 1));
      if (!inserted)
        ++it->second.second;
    }
  }
  std::vector<std::pair<std::size_t, int>> result;
  for (const auto& [edge, use] : seen) {
    if (use.second == 1)
      result.push_back(use.first);
  }
  return result;
}

double SectionMesh::area() const {
  double sum = 0;
  for (const auto& quad : quads)
    sum += std::abs(signed_area(*this, quad));
  return sum;
}

namespace {

// The sweep shared by revolve and extrude: node i of the section at slice k is node
// k · section.n_nodes() + i, placed by \p place; slice k's elements join slice k to slice k + 1
// (to slice 0 after the last when \p closed).
Mesh sweep(const SectionMesh& section, std::size_t n_slices, bool closed,
           const std::function<void(std::size_t, double, double, double*)>& place) {
  const GlobalIndex n_section = section.n_nodes();
  Mesh mesh;
  mesh.source = section.source;
  mesh.coordinates.resize(3 * n_slices * n_section);
  for (std::size_t k = 0; k < n_slices; ++k) {
    for (GlobalIndex i = 0; i < n_section; ++i) {
      place(k, section.coordinates[2 * i], section.coordinates[2 * i + 1],
            &mesh.coordinates[3 * (k * n_section + i)]);
    }
  }
  const std::size_t n_layers = closed ? n_slices : n_slices - 1;

  // Elements block by block, layer by layer; remember where quad q of layer 0 landed.
  const auto quads = oriented_quads(section);
  std::vector<GlobalIndex> first_hex(quads.size());     // global index of quad q's hex at layer 0
  std::vector<GlobalIndex> layer_stride(quads.size());  // quads in q's block
  for (std::size_t b = 0; b < section.blocks.size(); ++b) {
    ElementBlock block;
    block.name = section.blocks[b].name;
    block.id = section.blocks[b].id;
    std::vector<std::size_t> members;
    for (std::size_t q = 0; q < quads.size(); ++q) {
      if (section.quad_blocks[q] == static_cast<int>(b))
        members.push_back(q);
    }
    const GlobalIndex first = mesh.n_elements();
    for (std::size_t m = 0; m < members.size(); ++m) {
      first_hex[members[m]] = first + static_cast<GlobalIndex>(m);
      layer_stride[members[m]] = static_cast<GlobalIndex>(members.size());
    }
    for (std::size_t k = 0; k < n_layers; ++k) {
      const GlobalIndex here = k * n_section, next = ((k + 1) % n_slices) * n_section;
      for (std::size_t q : members) {
        GlobalIndex nodes[8];
        for (int j = 0; j < 4; ++j) {
          nodes[j] = here + quads[q][j];
          nodes[j + 4] = next + quads[q][j];
        }
        block.add_element(nodes, 8);
      }
    }
    if (block.n_elements() > 0)
      mesh.blocks.push_back(std::move(block));
    mesh.number_blocks();
  }

  // Quad edge j (corners j, j + 1) sweeps hex face j in the Exodus numbering.
  const auto edges = boundary_edges(quads);
  for (const auto& group : section.node_sets) {
    NodeSet nodes{group.name, group.id, {}};
    for (std::size_t k = 0; k < n_slices; ++k) {
      for (GlobalIndex i : group.nodes)
        nodes.nodes.push_back(k * n_section + i);
    }
    std::sort(nodes.nodes.begin(), nodes.nodes.end());
    mesh.node_sets.push_back(std::move(nodes));

    SideSet sides{group.name, group.id, {}};
    for (const auto& [q, j] : edges) {
      const GlobalIndex p = quads[q][j], s = quads[q][(j + 1) % 4];
      if (!std::binary_search(group.nodes.begin(), group.nodes.end(), p) ||
          !std::binary_search(group.nodes.begin(), group.nodes.end(), s)) {
        continue;
      }
      for (std::size_t k = 0; k < n_layers; ++k)
        sides.sides.push_back({first_hex[q] + static_cast<GlobalIndex>(k) * layer_stride[q], j});
    }
    if (!sides.sides.empty())
      mesh.side_sets.push_back(std::move(sides));
  }
  if (!closed) {
    // The two end faces: hex face 4 (nodes 0-3) of the first layer, face 5 of the last.
    const int next_id = static_cast<int>(section.node_sets.size()) + 1;
    for (int end = 0; end < 2; ++end) {
      const std::size_t k = end == 0 ? 0 : n_slices - 1;
      NodeSet nodes{end == 0 ? "start_face" : "end_face", next_id + end, {}};
      for (GlobalIndex i = 0; i < n_section; ++i)
        nodes.nodes.push_back(static_cast<GlobalIndex>(k) * n_section + i);
      mesh.node_sets.push_back(nodes);
      SideSet sides{nodes.name, nodes.id, {}};
      const std::size_t layer = end == 0 ? 0 : n_layers - 1;
      for (std::size_t q = 0; q < quads.size(); ++q)
        sides.sides.push_back(
            {first_hex[q] + static_cast<GlobalIndex>(layer) * layer_stride[q], 4 + end});
      mesh.side_sets.push_back(std::move(sides));
    }
  }
  return mesh;
}

}  // namespace

Mesh revolve(const SectionMesh& section, int n_around) {
  std::vector<double> angles(n_around > 0 ? n_around : 0);
  for (int k = 0; k < n_around; ++k)
    angles[k] = 2 * kPi * k / n_around;
  return revolve(section, angles);
}

Mesh revolve(const SectionMesh& section, const std::vector<double>& angles) {
  check_section(section, static_cast<int>(angles.size()));
  check_angles(angles);
  return sweep(section, angles.size(), true, [&](std::size_t k, double r, double a, double* x) {
    x[0] = r * std::cos(angles[k]);
    x[1] = a;
    x[2] = r * std::sin(angles[k]);
  });
}

Mesh extrude(const SectionMesh& section, const std::vector<double>& stations) {
  if (section.quad_blocks.size() != section.quads.size())
    throw std::logic_error("railfe: extrude: one block index per quad expected");
  if (stations.size() < 2)
    throw std::logic_error("railfe: extrude: at least two stations expected");
  for (std::size_t k = 0; k + 1 < stations.size(); ++k) {
    if (!(stations[k + 1] > stations[k]))
      throw std::logic_error("railfe: extrude: stations must increase");
  }
  return sweep(section, stations.size(), false, [&](std::size_t k, double u, double v, double* x) {
    x[0] = stations[k];
    x[1] = u;
    x[2] = v;
  });
}

}  // namespace railfe
