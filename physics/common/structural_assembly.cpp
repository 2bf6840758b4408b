#include "physics/common/structural_assembly.hpp"

#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "framework/base/error.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/elements/point_mass.hpp"

namespace railfe {

namespace {

using Matrix = StructuralMatrix;

}  // namespace

bool structural_element_matrix(StructuralMatrix kind, const StructuralSection& section,
                               const double* const* coordinates, int n_nodes, bool lumped,
                               double* out) {
  using RowMajor12 = Eigen::Matrix<double, 12, 12, Eigen::RowMajor>;
  using RowMajor6 = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;
  const auto put12 = [&](const Matrix12& m) { Eigen::Map<RowMajor12>{out} = m; };
  const auto put6 = [&](const Matrix6& m) { Eigen::Map<RowMajor6>{out} = m; };
  switch (section.kind) {
    case StructuralKind::beam: {
      if (kind == Matrix::damping)
        return false;
      const BeamElement beam = make_beam(coordinates[0], coordinates[1], section.beam);
      const BeamMass mass = lumped ? BeamMass::lumped : section.beam.mass;
      put12(kind == Matrix::stiffness ? beam.stiffness() : beam.mass(mass));
      return true;
    }
    case StructuralKind::spring: {
      if (kind == Matrix::mass)
        return false;
      const auto& values =
          kind == Matrix::stiffness ? section.spring.stiffness : section.spring.damping;
      const Matrix6 block = spring_block(values, section.spring.axes);
      if (n_nodes == 1)
        put6(block);
      else
        put12(two_node_matrix(block));
      return true;
    }
    case StructuralKind::point_mass:
      if (kind != Matrix::mass)
        return false;
      put6(point_mass_matrix(section.point.mass, section.point.inertia, section.point.offset));
      return true;
  }
  return false;
}

namespace {

// The coordinates of an element's first two nodes (the first twice for a one-node element).
std::array<const double*, 2> node_coordinates(const MeshPartition& partition,
                                              const LocalIndex* nodes, int n_nodes) {
  return {partition.coordinates(nodes[0]), partition.coordinates(nodes[n_nodes > 1 ? 1 : 0])};
}

// Throws std::logic_error unless every node of the element carries six DOFs (a mixed map gives
// solid nodes three; the modules refuse structural elements on solid nodes before assembly).
void require_six(const DofMap& dofs, const LocalIndex* nodes, int n_nodes) {
  for (int a = 0; a < n_nodes; ++a)
    if (dofs.dofs_of_node(nodes[a]) != 6)
      throw std::logic_error("structural elements need 6 DOFs at each of their nodes (node " +
                             std::to_string(dofs.partition().global_nodes()[nodes[a]] + 1) +
                             " has " + std::to_string(dofs.dofs_of_node(nodes[a])) + ")");
}

void add_matrix(FeMatrix& A, Matrix kind, const SectionTable& sections, bool lumped) {
  const MeshPartition& partition = A.dofs().partition();
  alignas(64) double matrix[12 * 12];
  for (std::size_t b = 0; b < partition.blocks().size(); ++b) {
    const auto& block = partition.blocks()[b];
    if (!sections.has_section(block.block))
      continue;
    const StructuralSection& section = sections.of_block(block.block);
    const LocalIndex first = partition.first_local_element(b);
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
      const int n_nodes = static_cast<int>(block.offsets[e + 1] - block.offsets[e]);
      if (!structural_element_matrix(kind, section,
                                     node_coordinates(partition, nodes, n_nodes).data(), n_nodes,
                                     lumped, matrix))
        continue;
      require_six(A.dofs(), nodes, n_nodes);
      A.add_element(first + e, matrix);
    }
  }
}

}  // namespace

void add_structural_stiffness(FeMatrix& K, const SectionTable& sections) {
  add_matrix(K, Matrix::stiffness, sections, false);
}

void add_structural_mass(FeMatrix& M, const SectionTable& sections, bool lumped) {
  add_matrix(M, Matrix::mass, sections, lumped);
}

void add_structural_damping(FeMatrix& C, const SectionTable& sections) {
  add_matrix(C, Matrix::damping, sections, false);
}

void assemble_structural_stiffness(FeMatrix& K, const SectionTable& sections) {
  K.begin_assembly();
  add_structural_stiffness(K, sections);
  K.end_assembly();
}

void assemble_structural_mass(FeMatrix& M, const SectionTable& sections, bool lumped) {
  M.begin_assembly();
  add_structural_mass(M, sections, lumped);
  M.end_assembly();
}

void assemble_structural_damping(FeMatrix& C, const SectionTable& sections) {
  C.begin_assembly();
  add_structural_damping(C, sections);
  C.end_assembly();
}

void add_structural_gravity(const SectionTable& sections, const DofMap& dofs,
                            const std::array<double, 3>& gravity, double* overlap_forces) {
  const MeshPartition& partition = dofs.partition();
  alignas(64) double matrix[12 * 12];
  for (const auto& block : partition.blocks()) {
    if (!sections.has_section(block.block))
      continue;
    const StructuralSection& section = sections.of_block(block.block);
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
      const int n_nodes = static_cast<int>(block.offsets[e + 1] - block.offsets[e]);
      if (!structural_element_matrix(Matrix::mass, section,
                                     node_coordinates(partition, nodes, n_nodes).data(), n_nodes,
                                     false, matrix))
        continue;
      require_six(dofs, nodes, n_nodes);
      const int n = 6 * n_nodes;
      for (int i = 0; i < n; ++i) {
        double sum = 0;
        for (int a = 0; a < n_nodes; ++a)
          for (int d = 0; d < 3; ++d)
            sum += matrix[i * n + 6 * a + d] * gravity[d];
        overlap_forces[dofs.local_dof(nodes[i / 6], i % 6)] += sum;
      }
    }
  }
}

void assemble_structural_loads(const SolidConditions& conditions, const SectionTable& sections,
                               const DofMap& dofs, TpetraVector& owned_forces) {
  TpetraVector overlap(dofs.overlap_map());
  {
    auto f = overlap.getDataNonConst();
    const auto& g = conditions.gravity;
    if (g[0] != 0 || g[1] != 0 || g[2] != 0)
      add_structural_gravity(sections, dofs, g, f.getRawPtr());
  }
  dofs.overlap_to_owned_sum(overlap, owned_forces);
  add_nodal_forces(conditions, dofs, owned_forces.getDataNonConst().getRawPtr());
}

void add_structural_constraints(const SolidConditions& conditions, const DofMap& dofs,
                                LinearConstraints& constraints) {
  prescribe_displacements(conditions, dofs, constraints);
  constraints.finalize();
}

void check_structural_conditions(const SolidConditions& conditions, const std::string& deck,
                                 const std::string& path) {
  const auto refuse = [&](const std::string& what, const std::string& name) {
    throw_input_error(deck, path + "/" + what + "/" + name,
                      "needs solid (hex8) elements, and the model has only beams, springs and "
                      "point masses",
                      "Nodal forces (with Total moment) and Gravity on structural models");
  };
  if (!conditions.surface_loads.empty())
    refuse("Surface loads", conditions.surface_loads.front().name);
  if (!conditions.centrifugal_loads.empty())
    refuse("Centrifugal loads", conditions.centrifugal_loads.front().name);
  if (!conditions.ties.empty())
    refuse("Ties", conditions.ties.front().name);
}

namespace {

// The first node of \p nodes that carries translations only (a solid node), or -1.
GlobalIndex first_solid_node(const std::vector<GlobalIndex>& nodes,
                             const std::vector<int>& node_dofs) {
  for (GlobalIndex node : nodes)
    if (node_dofs[node] == 3)
      return node;
  return -1;
}

}  // namespace

void check_mixed_model(const SolidConditions& conditions, const Mesh& mesh, const std::string& deck,
                       const std::string& path) {
  const std::vector<int> node_dofs = DofMap::mesh_node_dofs(mesh);
  const auto solid_node = [&](const std::string& set) {
    return first_solid_node(mesh.node_set(set, deck, path).nodes, node_dofs);
  };
  for (const auto& condition : conditions.displacements) {
    const bool rotation = std::any_of(condition.components.begin(), condition.components.end(),
                                      [](int c) { return c >= 3; });
    const GlobalIndex node = rotation ? solid_node(condition.node_set) : -1;
    if (node >= 0)
      throw_input_error(deck, path + "/Displacements/" + condition.name + "/Components",
                        "prescribes a rotation, and node " + std::to_string(node + 1) +
                            " of node set '" + condition.node_set +
                            "' is a solid node with translations only",
                        "the letters x, y and z on solid nodes (rx, ry, rz on beam, spring and "
                        "point-mass nodes only)");
  }
  for (const auto& force : conditions.nodal_forces) {
    const auto& m = force.total_moment;
    const GlobalIndex node = m[0] != 0 || m[1] != 0 || m[2] != 0 ? solid_node(force.node_set) : -1;
    if (node >= 0)
      throw_input_error(deck, path + "/Nodal forces/" + force.name + "/Total moment",
                        "is not zero, and node " + std::to_string(node + 1) + " of node set '" +
                            force.node_set + "' is a solid node with translations only",
                        "a Total moment on beam, spring and point-mass nodes only");
  }
  for (const auto& block : mesh.blocks) {
    if (!is_structural_type(block.type))
      continue;
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int a = 0; a < block.n_element_nodes(e); ++a)
        if (node_dofs[nodes[a]] != 6)
          throw_input_error(deck, "Mesh",
                            "block '" + block.name + "' element " + std::to_string(e + 1) +
                                " acts on node " + std::to_string(nodes[a] + 1) +
                                ", a solid node with translations only",
                            "structural elements on nodes of their own, tied to the solid by a "
                            "Solid-beam tie or a rigid link");
    }
  }
}

}  // namespace railfe
