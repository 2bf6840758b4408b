#include "physics/common/contact_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/enforcement/penalty_contact_pair.hpp"

#include "framework/base/error.hpp"
#include "framework/mesh/derived_sets.hpp"
#include "framework/mesh/hex8_topology.hpp"

namespace railfe {

namespace {

std::array<GlobalIndex, 4> face_nodes(const Mesh& mesh, const Side& side) {
  const ElementBlock& block = mesh.blocks[mesh.block_of(side.element)];
  const GlobalIndex* nodes = block.element_nodes(side.element - block.first_element);
  std::array<GlobalIndex, 4> face;
  for (int k = 0; k < 4; ++k)
    face[k] = nodes[kHex8FaceNodes[side.face][k]];
  return face;
}

}  // namespace

double face_area(const Mesh& mesh, const std::array<GlobalIndex, 4>& face) {
  const double* x = mesh.coordinates.data();
  return quad_area(x + 3 * face[0], x + 3 * face[1], x + 3 * face[2], x + 3 * face[3]);
}

double quad_area(const double* a, const double* b, const double* c, const double* d) {
  double p[3], q[3];
  for (int k = 0; k < 3; ++k) {
    p[k] = c[k] - a[k];
    q[k] = d[k] - b[k];
  }
  return 0.5 * std::hypot(p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
                          p[0] * q[1] - p[1] * q[0]);
}

ContactSurfaceNodes contact_surface_nodes(const ContactPairSpec& pair, const Mesh& mesh,
                                          const std::string& deck, const std::string& path) {
  ContactSurfaceNodes surfaces;
  const std::string where = path + "/Contact pairs/" + pair.name;
  const SideSet& master = mesh.side_set(pair.master_side_set, deck, where + "/Master side set");
  for (const Side& side : master.sides) {
    surfaces.master_faces.push_back(face_nodes(mesh, side));
    surfaces.master_elements.push_back(side.element);
  }

  // The faces that give the slave nodes their areas.
  std::vector<std::array<GlobalIndex, 4>>& slave_faces = surfaces.slave_faces;
  if (!pair.slave_side_set.empty()) {
    for (const Side& side :
         mesh.side_set(pair.slave_side_set, deck, where + "/Slave side set").sides) {
      slave_faces.push_back(face_nodes(mesh, side));
      surfaces.slave_elements.push_back(side.element);
    }
    for (const auto& face : slave_faces)
      surfaces.slave_nodes.insert(surfaces.slave_nodes.end(), face.begin(), face.end());
    std::sort(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end());
    surfaces.slave_nodes.erase(
        std::unique(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end()),
        surfaces.slave_nodes.end());
  } else {
    surfaces.slave_nodes =
        mesh.node_set(pair.slave_node_set, deck, where + "/Slave node set").nodes;
    std::sort(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end());
    for (const Side& side : exterior_faces(mesh)) {
      const auto face = face_nodes(mesh, side);
      if (std::all_of(face.begin(), face.end(), [&](GlobalIndex node) {
            return std::binary_search(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end(),
                                      node);
          })) {
        slave_faces.push_back(face);
        surfaces.slave_elements.push_back(side.element);
      }
    }
  }
  surfaces.slave_area.assign(surfaces.slave_nodes.size(), 0.0);
  for (const auto& face : slave_faces) {
    const double quarter = 0.25 * face_area(mesh, face);
    for (GlobalIndex node : face) {
      const auto it =
          std::lower_bound(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end(), node);
      surfaces.slave_area[it - surfaces.slave_nodes.begin()] += quarter;
    }
  }

  for (const auto& face : surfaces.master_faces) {
    for (GlobalIndex node : face) {
      if (std::binary_search(surfaces.slave_nodes.begin(), surfaces.slave_nodes.end(), node)) {
        const auto x = mesh.node(node);
        throw_input_error(deck, where,
                          "node " + std::to_string(node + 1) + " at (" + std::to_string(x[0]) +
                              ", " + std::to_string(x[1]) + ", " + std::to_string(x[2]) +
                              ") is both a slave node and a node of a master face",
                          "slave and master surfaces on different bodies (or parts); "
                          "self-contact is not supported");
      }
    }
  }
  return surfaces;
}

std::string start_penetration_problem(const ContactPairSpec& pair,
                                      const ContactSurfaceNodes& surface, const Mesh& mesh,
                                      const std::vector<double>& positions) {
  // The pair over its own nodes, numbered in ascending global order; stiffness and mass do not
  // matter for finding the contact points.
  std::vector<GlobalIndex> nodes = surface.slave_nodes;
  for (const auto& face : surface.master_faces)
    nodes.insert(nodes.end(), face.begin(), face.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto index = [&](GlobalIndex node) {
    return static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin());
  };
  PenaltyPairGeometry geometry;
  geometry.n_surface_nodes = static_cast<int>(nodes.size());
  geometry.mass.assign(nodes.size(), 1.0);
  geometry.slave_area = surface.slave_area;
  for (GlobalIndex node : surface.slave_nodes)
    geometry.slave_nodes.push_back(index(node));
  for (const auto& face : surface.master_faces)
    geometry.master_faces.push_back(
        {index(face[0]), index(face[1]), index(face[2]), index(face[3])});
  geometry.face_stiffness.assign(surface.master_faces.size(), 1.0);
  std::vector<double> x(3 * nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    std::copy_n(&positions[3 * nodes[i]], 3, &x[3 * i]);
  PenaltyPairSettings settings;
  settings.name = pair.name;
  // Faces are caught as deep as the limit allows and then some.
  for (const auto& face : surface.master_faces)
    settings.search_margin = std::max(settings.search_margin, std::sqrt(face_area(mesh, face)));
  PenaltyContactPair located(std::move(geometry), settings);
  located.locate(x.data());
  for (std::size_t s = 0; s < located.slaves().size(); ++s) {
    const SlaveContact& contact = located.slaves()[s];
    if (contact.face < 0)
      continue;
    const double size = std::sqrt(face_area(mesh, surface.master_faces[contact.face]));
    if (!(-contact.gap > pair.penetration_limit * size))
      continue;
    const GlobalIndex node = surface.slave_nodes[s];
    const double* position = &positions[3 * node];
    std::ostringstream problem;
    problem.precision(6);
    problem << "slave node " << node + 1 << " at (" << position[0] << ", " << position[1] << ", "
            << position[2] << ") m starts " << -contact.gap
            << " m inside the master surface, deeper than Initial penetration limit "
            << pair.penetration_limit << " x the face size " << size << " m";
    return problem.str();
  }
  return "";
}

}  // namespace railfe
