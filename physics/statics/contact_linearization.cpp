#include "physics/statics/contact_linearization.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "contact/search/quad_projection.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/common/contact_pairs.hpp"

namespace railfe {

ContactLinearization linearize_contact(const ContactPairs& contact, const DofMap& dofs) {
  const auto map = dofs.owned_map();
  const Mesh& mesh = dofs.partition().mesh();
  ContactLinearization result;
  result.force = Teuchos::rcp(new TpetraVector(map));
  std::vector<std::tuple<GlobalIndex, GlobalIndex, double>> entries;
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
      const double k = geometry.face_stiffness[slave.face];
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

  // Merge duplicate entries, then build the matrix with exact row lengths.
  std::sort(entries.begin(), entries.end(), [](const auto& p, const auto& q) {
    return std::tie(std::get<0>(p), std::get<1>(p)) < std::tie(std::get<0>(q), std::get<1>(q));
  });
  std::vector<std::tuple<GlobalIndex, GlobalIndex, double>> merged;
  for (const auto& entry : entries) {
    if (!merged.empty() && std::get<0>(merged.back()) == std::get<0>(entry) &&
        std::get<1>(merged.back()) == std::get<1>(entry))
      std::get<2>(merged.back()) += std::get<2>(entry);
    else
      merged.push_back(entry);
  }
  const std::size_t n_rows = map->getNodeNumElements();
  Teuchos::Array<std::size_t> row_lengths(n_rows, 0);
  for (const auto& entry : merged)
    ++row_lengths[map->getLocalElement(std::get<0>(entry))];
  result.stiffness = Teuchos::rcp(new TpetraMatrix(map, row_lengths()));
  for (std::size_t begin = 0; begin < merged.size();) {
    std::size_t end = begin;
    std::vector<GlobalIndex> columns;
    std::vector<double> values;
    while (end < merged.size() && std::get<0>(merged[end]) == std::get<0>(merged[begin])) {
      columns.push_back(std::get<1>(merged[end]));
      values.push_back(std::get<2>(merged[end]));
      ++end;
    }
    result.stiffness->insertGlobalValues(
        std::get<0>(merged[begin]),
        Teuchos::ArrayView<const GlobalIndex>(columns.data(), static_cast<int>(columns.size())),
        Teuchos::ArrayView<const double>(values.data(), static_cast<int>(values.size())));
    begin = end;
  }
  result.stiffness->fillComplete(map, map);
  return result;
}

}  // namespace railfe
