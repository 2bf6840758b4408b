#include "physics/common/node_set_stresses.hpp"

#include <unordered_map>

#include "physics/common/solid_assembly.hpp"
#include "physics/elements/hex8_stress_recovery.hpp"

namespace railfe {

std::vector<double> node_set_stresses(const MeshPartition& partition,
                                      const MaterialTable& materials, const double* u_overlap,
                                      const std::vector<std::vector<GlobalIndex>>& node_sets,
                                      bool one_point) {
  // Slot of each (set, node) pair: 6 stress sums and an element count, summed over the ranks.
  std::unordered_multimap<GlobalIndex, std::size_t> slots;
  std::size_t n_slots = 0;
  for (const auto& nodes : node_sets) {
    for (GlobalIndex node : nodes)
      slots.emplace(node, n_slots++);
  }
  std::vector<double> sums(7 * n_slots, 0.0);
  double x[8][3], u[24], stress[8][6];
  for (const auto& block : partition.blocks()) {
    if (partition.mesh().blocks[block.block].type != ElementType::hex8)
      continue;
    const ElasticMaterial& material = materials.of_block(block.block);
    const Hex8Strain strain = one_point ? Hex8Strain::centre
                              : material.element == SolidElement::enhanced_strain
                                  ? Hex8Strain::enhanced_strain
                                  : Hex8Strain::full;
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
      bool probed = false;
      for (int a = 0; a < 8 && !probed; ++a)
        probed = slots.count(partition.global_node(nodes[a])) > 0;
      if (!probed)
        continue;
      element_coordinates(partition, block, e, x);
      for (int a = 0; a < 8; ++a) {
        for (int d = 0; d < 3; ++d)
          u[3 * a + d] = u_overlap[3 * nodes[a] + d];
      }
      hex8_corner_stresses(x, u, material.lame(), strain, stress);
      for (int a = 0; a < 8; ++a) {
        const auto range = slots.equal_range(partition.global_node(nodes[a]));
        for (auto slot = range.first; slot != range.second; ++slot) {
          double* sum = &sums[7 * slot->second];
          for (int c = 0; c < 6; ++c)
            sum[c] += stress[a][c];
          sum[6] += 1;
        }
      }
    }
  }
  partition.comm().sum_in_place(sums);
  std::vector<double> result(6 * node_sets.size(), 0.0);
  std::size_t slot = 0;
  for (std::size_t set = 0; set < node_sets.size(); ++set) {
    int counted = 0;
    for (std::size_t k = 0; k < node_sets[set].size(); ++k, ++slot) {
      const double* sum = &sums[7 * slot];
      if (sum[6] == 0)
        continue;
      ++counted;
      for (int c = 0; c < 6; ++c)
        result[6 * set + c] += sum[c] / sum[6];
    }
    for (int c = 0; c < 6 && counted > 0; ++c)
      result[6 * set + c] /= counted;
  }
  return result;
}

}  // namespace railfe
