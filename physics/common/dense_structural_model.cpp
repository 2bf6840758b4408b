#include "physics/common/dense_structural_model.hpp"

#include "physics/common/rigid_links.hpp"
#include "physics/common/structural_assembly.hpp"
#include "physics/elements/rigid_link.hpp"

namespace railfe {

DenseStructuralModel::DenseStructuralModel(const Mesh& mesh, const SectionTable& sections,
                                           const std::string& deck) {
  const GlobalIndex n_nodes = mesh.n_nodes();
  const std::vector<RigidLink> links = mesh_rigid_links(mesh);
  check_rigid_links(
      links, [](GlobalIndex) { return 6; }, deck, "Mesh");
  std::vector<GlobalIndex> master_of(n_nodes, -1);
  for (const RigidLink& link : links)
    for (GlobalIndex slave : link.slaves)
      master_of[slave] = link.master;
  first_unknown_.assign(n_nodes, -1);
  Eigen::Index n = 0;
  for (GlobalIndex node = 0; node < n_nodes; ++node)
    if (master_of[node] < 0) {
      first_unknown_[node] = n;
      n += 6;
    }
  carry_ = Eigen::MatrixXd::Zero(6 * n_nodes, n);
  for (GlobalIndex node = 0; node < n_nodes; ++node) {
    const GlobalIndex master = master_of[node];
    if (master < 0) {
      carry_.block(6 * node, first_unknown_[node], 6, 6).setIdentity();
      continue;
    }
    const auto x = mesh.node(node), x_m = mesh.node(master);
    const Eigen::Vector3d offset(x[0] - x_m[0], x[1] - x_m[1], x[2] - x_m[2]);
    carry_.block(6 * node, first_unknown_[master], 6, 6) = rigid_link_matrix(offset);
  }

  // Element by element into the matrices of every node's six motions, then C_ᵀ A C_.
  const Eigen::Index n_all = 6 * n_nodes;
  Eigen::MatrixXd all[3];
  for (auto& matrix : all)
    matrix = Eigen::MatrixXd::Zero(n_all, n_all);
  const StructuralMatrix kinds[3] = {StructuralMatrix::mass, StructuralMatrix::stiffness,
                                     StructuralMatrix::damping};
  double element[12 * 12];
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (!sections.has_section(static_cast<int>(b)))
      continue;
    const ElementBlock& block = mesh.blocks[b];
    const StructuralSection& section = sections.of_block(static_cast<int>(b));
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      const int n_element = block.n_element_nodes(e);
      const double* coordinates[2] = {&mesh.coordinates[3 * nodes[0]],
                                      &mesh.coordinates[3 * nodes[n_element > 1 ? 1 : 0]]};
      for (int k = 0; k < 3; ++k) {
        if (!structural_element_matrix(kinds[k], section, coordinates, n_element, false, element))
          continue;
        const int size = 6 * n_element;
        for (int i = 0; i < size; ++i)
          for (int j = 0; j < size; ++j)
            all[k](6 * nodes[i / 6] + i % 6, 6 * nodes[j / 6] + j % 6) += element[i * size + j];
      }
    }
  }
  mass_ = carry_.transpose() * all[0] * carry_;
  stiffness_ = carry_.transpose() * all[1] * carry_;
  damping_ = carry_.transpose() * all[2] * carry_;
}

Eigen::MatrixXd DenseStructuralModel::node_motion(GlobalIndex node) const {
  return carry_.middleRows(6 * node, 6);
}

Eigen::VectorXd DenseStructuralModel::gravity_load(const Eigen::Vector3d& g) const {
  // Every node translated by g is the unknowns' rigid translation: masters by g, no rotation.
  Eigen::VectorXd translation = Eigen::VectorXd::Zero(n_unknowns());
  for (Eigen::Index first : first_unknown_)
    if (first >= 0)
      translation.segment<3>(first) = g;
  return mass_ * translation;
}

}  // namespace railfe
