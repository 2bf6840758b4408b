#include "framework/mesh/derived_sets.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "framework/base/error.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

std::vector<Side> exterior_faces(const Mesh& mesh) {
  std::map<std::array<GlobalIndex, 4>, std::pair<Side, int>> faces;
  for (const auto& block : mesh.blocks) {
    if (block.type != ElementType::hex8)
      continue;
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int face = 0; face < 6; ++face) {
        std::array<GlobalIndex, 4> key;
        for (int k = 0; k < 4; ++k)
          key[k] = nodes[kHex8FaceNodes[face][k]];
        std::sort(key.begin(), key.end());
        auto [it, inserted] =
            faces.emplace(key, std::make_pair(Side{block.first_element + e, face}, 1));
        if (!inserted)
          ++it->second.second;
      }
    }
  }
  std::vector<Side> result;
  for (const auto& [key, side_count] : faces) {
    if (side_count.second == 1)
      result.push_back(side_count.first);
  }
  std::sort(result.begin(), result.end(), [](const Side& a, const Side& b) {
    return a.element != b.element ? a.element < b.element : a.face < b.face;
  });
  return result;
}

namespace {

// Relative slack so nodes placed exactly on a box face by the generator are inside it.
double box_tolerance(const Mesh& mesh) {
  double extent = 0;
  for (int d = 0; d < 3; ++d) {
    double low = 1e300, high = -1e300;
    for (GlobalIndex n = 0; n < mesh.n_nodes(); ++n) {
      low = std::min(low, mesh.coordinates[3 * n + d]);
      high = std::max(high, mesh.coordinates[3 * n + d]);
    }
    extent = std::max(extent, high - low);
  }
  return 1e-9 * extent;
}

bool inside(const Mesh& mesh, GlobalIndex node, const std::array<double, 6>& box, double slack) {
  for (int d = 0; d < 3; ++d) {
    const double x = mesh.coordinates[3 * node + d];
    if (x < box[2 * d] - slack || x > box[2 * d + 1] + slack)
      return false;
  }
  return true;
}

NodeSet select_nodes(const Mesh& mesh, const DerivedSetSpec& spec, const std::string& deck) {
  std::vector<GlobalIndex> candidates;
  if (spec.within.empty()) {
    candidates.resize(mesh.n_nodes());
    for (GlobalIndex n = 0; n < mesh.n_nodes(); ++n)
      candidates[n] = n;
  } else {
    candidates = mesh.node_set(spec.within, deck, spec.path + "/Within").nodes;
  }
  NodeSet set{spec.name, 0, {}};
  if (spec.box) {
    const double slack = box_tolerance(mesh);
    for (GlobalIndex node : candidates) {
      if (inside(mesh, node, *spec.box, slack))
        set.nodes.push_back(node);
    }
  } else if (spec.cylinder) {
    const auto& c = *spec.cylinder;
    const double length = std::sqrt(c[3] * c[3] + c[4] * c[4] + c[5] * c[5]);
    const double slack = box_tolerance(mesh);
    for (GlobalIndex node : candidates) {
      double r[3], along = 0, squared = 0;
      for (int d = 0; d < 3; ++d) {
        r[d] = mesh.coordinates[3 * node + d] - c[d];
        along += r[d] * c[3 + d] / length;
      }
      for (int d = 0; d < 3; ++d)
        squared += std::pow(r[d] - along * c[3 + d] / length, 2);
      if (std::sqrt(squared) <= c[6] + slack)
        set.nodes.push_back(node);
    }
  } else {
    double best = 1e300;
    GlobalIndex nearest = -1;
    for (GlobalIndex node : candidates) {
      double distance = 0;
      for (int d = 0; d < 3; ++d) {
        distance += std::pow(mesh.coordinates[3 * node + d] - (*spec.point)[d], 2);
      }
      if (distance < best) {
        best = distance;
        nearest = node;
      }
    }
    if (nearest >= 0)
      set.nodes.push_back(nearest);
  }
  return set;
}

SideSet select_sides(const Mesh& mesh, const DerivedSetSpec& spec, const std::string& deck) {
  const std::vector<Side> candidates =
      spec.within.empty() ? exterior_faces(mesh)
                          : mesh.side_set(spec.within, deck, spec.path + "/Within").sides;
  SideSet set{spec.name, 0, {}};
  const double slack = box_tolerance(mesh);
  for (const Side& side : candidates) {
    const auto& block = mesh.blocks[mesh.block_of(side.element)];
    const GlobalIndex* nodes = block.element_nodes(side.element - block.first_element);
    bool all_inside = true;
    for (int k = 0; k < 4 && all_inside; ++k) {
      all_inside = inside(mesh, nodes[kHex8FaceNodes[side.face][k]], *spec.box, slack);
    }
    if (all_inside)
      set.sides.push_back(side);
  }
  return set;
}

}  // namespace

void add_derived_sets(Mesh& mesh, const std::vector<DerivedSetSpec>& specs,
                      const std::string& deck) {
  for (const auto& spec : specs) {
    const bool taken = spec.side_set ? mesh.has_side_set(spec.name) : mesh.has_node_set(spec.name);
    if (taken) {
      throw_input_error(deck, spec.path,
                        std::string("a ") + (spec.side_set ? "side" : "node") + " set called '" +
                            spec.name + "' already exists in the mesh",
                        "a new name");
    }
    if (spec.side_set) {
      if (!spec.box) {
        throw_input_error(deck, spec.path, "a side set needs 'Box'",
                          "Box = {xmin, xmax, ymin, "
                          "ymax, zmin, zmax}");
      }
      SideSet set = select_sides(mesh, spec, deck);
      if (set.sides.empty()) {
        throw_input_error(deck, spec.path + "/Box", "selects no element faces",
                          "a box that contains whole faces of the 'Within' set");
      }
      set.id = static_cast<int>(mesh.side_sets.size()) + 1;
      mesh.side_sets.push_back(std::move(set));
    } else {
      const int given = spec.box.has_value() + spec.point.has_value() + spec.cylinder.has_value();
      if (given != 1) {
        throw_input_error(deck, spec.path, "give exactly one of 'Box', 'Point' and 'Cylinder'",
                          "Box = {xmin, xmax, ymin, ymax, zmin, zmax}, Point = {x, y, z} or "
                          "Cylinder = {x, y, z, ax, ay, az, radius}");
      }
      if (spec.cylinder) {
        const auto& c = *spec.cylinder;
        if (!(c[3] * c[3] + c[4] * c[4] + c[5] * c[5] > 0) || !(c[6] > 0))
          throw_input_error(deck, spec.path + "/Cylinder", "has no axis direction or radius",
                            "{x, y, z, ax, ay, az, radius} with a nonzero direction and a "
                            "positive radius");
      }
      NodeSet set = select_nodes(mesh, spec, deck);
      if (set.nodes.empty()) {
        throw_input_error(deck,
                          spec.path + (spec.box     ? "/Box"
                                       : spec.point ? "/Point"
                                                    : "/Cylinder"),
                          "selects no nodes", "a region that contains nodes of the 'Within' set");
      }
      set.id = static_cast<int>(mesh.node_sets.size()) + 1;
      mesh.node_sets.push_back(std::move(set));
    }
  }
}

}  // namespace railfe
