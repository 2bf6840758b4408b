#include "physics/statics/contact_linearization.hpp"

#include <Tpetra_Vector.hpp>

#include <array>
#include <utility>
#include <vector>

#include "contact/search/quad_projection.hpp"
#include "framework/assembly/sparse_entries.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/common/contact_pairs.hpp"

namespace railfe {

ContactLinearization linearize_contact(const ContactPairs& contact, const DofMap& dofs) {
  const auto map = dofs.owned_map();
  const Mesh& mesh = dofs.partition().mesh();
  ContactLinearization result;
  result.force = Teuchos::rcp(new TpetraVector(map));
  std::vector<MatrixEntry> entries;
  for (const PenaltyContactPair& pair : contact.pairs()) {
    const PenaltyPairGeometry& geometry = pair.geometry();
    for (std::size_t s = 0; s < pair.slaves().size(); ++s) {
      const SlaveContact& slave = pair.slaves()[s];
      if (slave.face < 0)
        continue;
      ++result.active;
      const auto& face = geometry.master_faces[slave.face];
      const std::array<double, 4> shape = quad_shape_functions(slave.xi, slave.eta);
      const std::array<GlobalIndex, 5> nodes = {
          contact.surface_node(geometry.slave_nodes[s]), contact.surface_node(face[0]),
          contact.surface_node(face[1]), contact.surface_node(face[2]),
          contact.surface_node(face[3])};
      const std::array<double, 5> weight = {1, -shape[0], -shape[1], -shape[2], -shape[3]};
      const double k = pair.stiffness(s, slave.face);
      const auto& n = slave.normal;
      double reference_gap = 0;
      for (int a = 0; a < 5; ++a)
        for (int d = 0; d < 3; ++d)
          reference_gap += weight[a] * n[d] * mesh.coordinates[3 * nodes[a] + d];
      for (int a = 0; a < 5; ++a) {
        for (int d = 0; d < 3; ++d) {
          const GlobalIndex row = dofs.global_dof(nodes[a], d);
          if (!map->isNodeGlobalElement(row))
            continue;
          result.force->sumIntoGlobalValue(row, -k * reference_gap * weight[a] * n[d]);
          for (int b = 0; b < 5; ++b)
            for (int e = 0; e < 3; ++e)
              entries.emplace_back(row, dofs.global_dof(nodes[b], e),
                                   k * weight[a] * n[d] * weight[b] * n[e]);
        }
      }
    }
  }

  result.stiffness = matrix_from_entries(map, std::move(entries));
  return result;
}

}  // namespace railfe
