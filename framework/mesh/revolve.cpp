#include "framework/mesh/revolve.hpp"
#include "framework/base/constants.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "framework/base/error.hpp"

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

// Quads counter-clockwise in (r, a): seen from increasing θ, so nodes 0-3 (slice k) and 4-7
// (slice k + 1) follow the hex8 convention.
std::vector<std::array<GlobalIndex, 4>> oriented_quads(const SectionMesh& section) {
  auto quads = section.quads;
  for (auto& quad : quads) {
    if (signed_area(section, quad) < 0)
      std::swap(quad[1], quad[3]);
  }
  return quads;
}

// Boundary edges of the section: (quad, local edge j from corner j to corner j + 1).
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

}  // namespace

double SectionMesh::area() const {
  double sum = 0;
  for (const auto& quad : quads)
    sum += std::abs(signed_area(*this, quad));
  return sum;
}

Mesh revolve(const SectionMesh& section, int n_around) {
  check_section(section, n_around);
  const GlobalIndex n_section = section.n_nodes();
  Mesh mesh;
  mesh.source = section.source;
  mesh.coordinates.resize(3 * static_cast<std::size_t>(n_around) * n_section);
  for (int k = 0; k < n_around; ++k) {
    const double theta = 2 * kPi * k / n_around;
    for (GlobalIndex i = 0; i < n_section; ++i) {
      const double r = section.coordinates[2 * i];
      double* x = &mesh.coordinates[3 * (k * n_section + i)];
      x[0] = r * std::cos(theta);
      x[1] = section.coordinates[2 * i + 1];
      x[2] = r * std::sin(theta);
    }
  }

  // Elements block by block, slice by slice; remember where quad q of slice 0 landed.
  const auto quads = oriented_quads(section);
  std::vector<GlobalIndex> first_hex(quads.size());     // global index of quad q's hex at slice 0
  std::vector<GlobalIndex> slice_stride(quads.size());  // quads in q's block
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
      slice_stride[members[m]] = static_cast<GlobalIndex>(members.size());
    }
    for (int k = 0; k < n_around; ++k) {
      const GlobalIndex here = k * n_section, next = ((k + 1) % n_around) * n_section;
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
    for (int k = 0; k < n_around; ++k) {
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
      for (int k = 0; k < n_around; ++k)
        sides.sides.push_back({first_hex[q] + k * slice_stride[q], j});
    }
    if (!sides.sides.empty())
      mesh.side_sets.push_back(std::move(sides));
  }
  return mesh;
}

}  // namespace railfe
