#include "physics/common/solid_assembly.hpp"

#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "physics/elements/hex8.hpp"
#include "physics/elements/hex8_enhanced_strain.hpp"
#include "physics/elements/hex8_one_point.hpp"

namespace railfe {

void element_coordinates(const MeshPartition& partition, const LocalBlock& block,
                         LocalIndex element, double x[8][3]) {
  const LocalIndex* nodes = block.connectivity.data() + block.offsets[element];
  for (int a = 0; a < 8; ++a) {
    const double* c = partition.coordinates(nodes[a]);
    x[a][0] = c[0];
    x[a][1] = c[1];
    x[a][2] = c[2];
  }
}

namespace {

// Adds the matrix \p element_matrix(block, x, out) gives each local hex8 element into \p A
// (open for assembly).
template <typename ElementMatrix>
void add_hex8_matrix(FeMatrix& A, ElementMatrix element_matrix, Progress* progress) {
  const MeshPartition& partition = A.dofs().partition();
  alignas(64) double matrix[24 * 24];
  double x[8][3];
  for (std::size_t b = 0; b < partition.blocks().size(); ++b) {
    const auto& block = partition.blocks()[b];
    if (partition.mesh().blocks[block.block].type != ElementType::hex8)
      continue;
    const LocalIndex first = partition.first_local_element(b);
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      element_coordinates(partition, block, e, x);
      element_matrix(block.block, x, matrix);
      A.add_element(first + e, matrix);
      if (progress != nullptr && (e & 8191) == 0)
        progress->update(first + e);
    }
  }
}

}  // namespace

void assemble_elastic_stiffness(FeMatrix& K, const MaterialTable& materials, Progress* progress,
                                double one_point_kappa) {
  K.begin_assembly();
  add_elastic_stiffness(K, materials, progress, one_point_kappa);
  K.end_assembly();
}

void add_elastic_stiffness(FeMatrix& K, const MaterialTable& materials, Progress* progress,
                           double one_point_kappa) {
  add_hex8_matrix(
      K,
      [&](int block, const double x[8][3], double* matrix) {
        const ElasticMaterial& material = materials.of_block(block);
        if (one_point_kappa >= 0) {
          hex8_one_point_stiffness(x, material.lame(), one_point_kappa, matrix);
        } else if (material.element == SolidElement::enhanced_strain) {
          hex8_enhanced_strain_stiffness(x, material.lame(), matrix);
        } else {
          hex8_stiffness(x, material.lame(), matrix);
        }
      },
      progress);
}

void assemble_mass(FeMatrix& M, const MaterialTable& materials, bool lumped) {
  M.begin_assembly();
  add_mass(M, materials, lumped);
  M.end_assembly();
}

void add_mass(FeMatrix& M, const MaterialTable& materials, bool lumped) {
  add_hex8_matrix(
      M,
      [&](int block, const double x[8][3], double* matrix) {
        hex8_mass(x, materials.of_block(block).density, lumped, matrix);
      },
      nullptr);
}

namespace {

// Local hex8 element holding global element \p element, or false if another rank has it.
bool find_local_element(const MeshPartition& partition, GlobalIndex element,
                        const LocalBlock** block_out, LocalIndex* local_out) {
  if (partition.element_ranks()[element] != partition.comm().rank())
    return false;
  const Mesh& mesh = partition.mesh();
  const int block_index = mesh.block_of(element);
  const GlobalIndex in_block = element - mesh.blocks[block_index].first_element;
  for (const auto& block : partition.blocks()) {
    if (block.block != block_index)
      continue;
    const auto it = std::lower_bound(block.elements.begin(), block.elements.end(), in_block);
    *block_out = &block;
    *local_out = static_cast<LocalIndex>(it - block.elements.begin());
    return true;
  }
  return false;
}

double side_set_area(const SideSet& set, const MeshPartition& partition) {
  double area = 0;
  for (const Side& side : set.sides) {
    const LocalBlock* block;
    LocalIndex e;
    if (!find_local_element(partition, side.element, &block, &e))
      continue;
    double x[8][3];
    element_coordinates(partition, *block, e, x);
    area += hex8_face_area(x, side.face);
  }
  return partition.comm().sum(area);
}

// Adds m ω² r⊥ at every local node of the load's set, m the node's lumped mass from each hex8
// element around it (the overlap sum is completed by the caller).
void add_centrifugal_load(const CentrifugalLoad& load, const MaterialTable& materials,
                          const DofMap& dofs, Teuchos::ArrayRCP<double>& f) {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  std::vector<char> spinning(partition.n_local_nodes(), 0);
  for (GlobalIndex node : mesh.node_set(load.node_set, "", "").nodes) {
    const LocalIndex local = partition.local_node(node);
    if (local >= 0)
      spinning[local] = 1;
  }
  const auto& w = load.angular_velocity;
  const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double axis[3] = {w[0] / std::sqrt(w2), w[1] / std::sqrt(w2), w[2] / std::sqrt(w2)};
  double x[8][3];
  std::vector<double> mass(24 * 24);
  for (const auto& block : partition.blocks()) {
    if (mesh.blocks[block.block].type != ElementType::hex8)
      continue;
    const double density = materials.of_block(block.block).density;
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
      if (std::none_of(nodes, nodes + 8, [&](LocalIndex n) { return spinning[n] != 0; }))
        continue;
      element_coordinates(partition, block, e, x);
      hex8_mass(x, density, true, mass.data());
      for (int a = 0; a < 8; ++a) {
        if (!spinning[nodes[a]])
          continue;
        double r[3], along = 0;
        for (int d = 0; d < 3; ++d) {
          r[d] = x[a][d] - load.axis_point[d];
          along += r[d] * axis[d];
        }
        const double m = mass[(3 * a) * 25];
        for (int d = 0; d < 3; ++d)
          f[dofs.local_dof(nodes[a], d)] += m * w2 * (r[d] - along * axis[d]);
      }
    }
  }
}

}  // namespace

void assemble_solid_loads(const SolidConditions& conditions, const MaterialTable& materials,
                          const DofMap& dofs, TpetraVector& forces) {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  TpetraVector overlap(dofs.overlap_map());
  {
    auto f = overlap.getDataNonConst();
    double x[8][3];
    const bool has_gravity =
        conditions.gravity[0] != 0 || conditions.gravity[1] != 0 || conditions.gravity[2] != 0;
    for (const auto& block : partition.blocks()) {
      if (!has_gravity || mesh.blocks[block.block].type != ElementType::hex8)
        continue;
      const double density = materials.of_block(block.block).density;
      const double body[3] = {density * conditions.gravity[0], density * conditions.gravity[1],
                              density * conditions.gravity[2]};
      double element_forces[24];
      for (LocalIndex e = 0; e < block.n_elements(); ++e) {
        element_coordinates(partition, block, e, x);
        hex8_body_force(x, body, element_forces);
        const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
        for (int a = 0; a < 8; ++a) {
          for (int d = 0; d < 3; ++d)
            f[dofs.local_dof(nodes[a], d)] += element_forces[3 * a + d];
        }
      }
    }
    for (const auto& load : conditions.centrifugal_loads)
      add_centrifugal_load(load, materials, dofs, f);
    for (const auto& load : conditions.surface_loads) {
      const SideSet& set = mesh.side_set(load.side_set, "", "");
      std::array<double, 3> traction{};
      if (load.traction)
        traction = *load.traction;
      if (load.total_force) {
        const double area = side_set_area(set, partition);
        for (int d = 0; d < 3; ++d)
          traction[d] = (*load.total_force)[d] / area;
      }
      for (const Side& side : set.sides) {
        const LocalBlock* block;
        LocalIndex e;
        if (!find_local_element(partition, side.element, &block, &e))
          continue;
        element_coordinates(partition, *block, e, x);
        double face_forces[12];
        if (load.pressure) {
          hex8_face_pressure(x, side.face, *load.pressure, face_forces);
        } else {
          hex8_face_traction(x, side.face, traction.data(), face_forces);
        }
        const LocalIndex* nodes = block->connectivity.data() + block->offsets[e];
        for (int k = 0; k < 4; ++k) {
          const LocalIndex node = nodes[kHex8FaceNodes[side.face][k]];
          for (int d = 0; d < 3; ++d)
            f[dofs.local_dof(node, d)] += face_forces[3 * k + d];
        }
      }
    }
  }
  dofs.overlap_to_owned_sum(overlap, forces);
  add_nodal_forces(conditions, dofs, forces.getDataNonConst().getRawPtr());
}

void add_nodal_forces(const SolidConditions& conditions, const DofMap& dofs, double* owned_forces) {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  for (const auto& force : conditions.nodal_forces) {
    const NodeSet& set = mesh.node_set(force.node_set, "", "");
    long long active = 0;
    for (GlobalIndex node : set.nodes)
      active += partition.node_ranks()[node] >= 0;
    for (GlobalIndex node : set.nodes) {
      const LocalIndex local = partition.local_node(node);
      if (local < 0 || local >= partition.n_owned_nodes())
        continue;
      const bool rotations = dofs.dofs_of_node(local) == 6;  // a moment needs them
      for (int d = 0; d < 3; ++d) {
        owned_forces[dofs.local_dof(local, d)] += force.total_force[d] / active;
        if (rotations)
          owned_forces[dofs.local_dof(local, 3 + d)] += force.total_moment[d] / active;
      }
    }
  }
}

std::vector<std::pair<GlobalIndex, GlobalIndex>> pair_tied_nodes(const Tie& tie, const Mesh& mesh,
                                                                 const std::string& deck,
                                                                 const std::string& path) {
  std::vector<GlobalIndex> masters = mesh.node_set(tie.master_set, deck, path).nodes;
  std::sort(masters.begin(), masters.end(), [&](GlobalIndex a, GlobalIndex b) {
    return mesh.coordinates[3 * a] < mesh.coordinates[3 * b];
  });
  std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;
  for (GlobalIndex slave : mesh.node_set(tie.slave_set, deck, path).nodes) {
    const double* s = &mesh.coordinates[3 * slave];
    auto first = std::lower_bound(
        masters.begin(), masters.end(), s[0] - tie.tolerance,
        [&](GlobalIndex m, double value) { return mesh.coordinates[3 * m] < value; });
    GlobalIndex match = -1;
    for (auto it = first; it != masters.end() && mesh.coordinates[3 * *it] <= s[0] + tie.tolerance;
         ++it) {
      const double* m = &mesh.coordinates[3 * *it];
      const double distance =
          std::sqrt((m[0] - s[0]) * (m[0] - s[0]) + (m[1] - s[1]) * (m[1] - s[1]) +
                    (m[2] - s[2]) * (m[2] - s[2]));
      if (distance <= tie.tolerance && *it != slave) {
        match = *it;
        break;
      }
    }
    if (match < 0) {
      std::ostringstream problem;
      problem << "slave node " << slave + 1 << " of '" << tie.slave_set << "' at (" << s[0] << ", "
              << s[1] << ", " << s[2] << ") has no other node of '" << tie.master_set << "' within "
              << tie.tolerance << " m";
      throw_input_error(deck, path, problem.str(),
                        "node sets whose nodes coincide pairwise (raise Tolerance if they are "
                        "close but not equal)");
    }
    pairs.emplace_back(slave, match);
  }
  return pairs;
}

void prescribe_displacements(const SolidConditions& conditions, const DofMap& dofs,
                             LinearConstraints& constraints) {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  for (const auto& condition : conditions.displacements) {
    std::optional<Expression> expression;
    if (!condition.expression.empty())
      expression.emplace(condition.expression, "", "");
    for (GlobalIndex node : mesh.node_set(condition.node_set, "", "").nodes) {
      const LocalIndex local = partition.local_node(node);
      if (local < 0 || local >= partition.n_owned_nodes())
        continue;
      const double* c = partition.coordinates(local);
      const double value = expression ? (*expression)(c[0], c[1], c[2]) : condition.value;
      for (int component : condition.components)
        constraints.prescribe(dofs.global_dof(node, component), value);
    }
  }
}

void add_solid_constraints(
    const SolidConditions& conditions,
    const std::vector<std::vector<std::pair<GlobalIndex, GlobalIndex>>>& ties, const DofMap& dofs,
    LinearConstraints& constraints) {
  const MeshPartition& partition = dofs.partition();
  prescribe_displacements(conditions, dofs, constraints);
  for (const auto& pairs : ties) {
    for (const auto& [slave, master] : pairs) {
      if (partition.node_ranks()[slave] < 0 || partition.node_ranks()[master] < 0)
        continue;
      for (int d = 0; d < 3; ++d) {
        constraints.add_multipoint(
            {dofs.global_dof(slave, d), {{dofs.global_dof(master, d), 1.0}}, 0.0});
      }
    }
  }
  constraints.finalize();
}

std::vector<double> element_stresses(const MeshPartition& partition, const MaterialTable& materials,
                                     const double* u_overlap) {
  std::vector<double> stresses;
  stresses.reserve(6 * partition.n_local_elements());
  double x[8][3], u[24], stress[6];
  for (const auto& block : partition.blocks()) {
    const bool solid = partition.mesh().blocks[block.block].type == ElementType::hex8;
    for (LocalIndex e = 0; e < block.n_elements(); ++e) {
      if (!solid) {
        stresses.insert(stresses.end(), 6, 0.0);
        continue;
      }
      element_coordinates(partition, block, e, x);
      const LocalIndex* nodes = block.connectivity.data() + block.offsets[e];
      for (int a = 0; a < 8; ++a) {
        for (int d = 0; d < 3; ++d)
          u[3 * a + d] = u_overlap[3 * nodes[a] + d];
      }
      hex8_centre_stress(x, u, materials.of_block(block.block).lame(), stress);
      stresses.insert(stresses.end(), stress, stress + 6);
    }
  }
  return stresses;
}

ProblemTraits elasticity_traits(const DofMap& dofs) {
  const MeshPartition& partition = dofs.partition();
  ProblemTraits traits;
  traits.symmetric_positive_definite = true;
  traits.dofs_per_node = dofs.solver_dofs_per_node();
  traits.name_dof = [&dofs](GlobalIndex dof) { return dofs.describe(dof); };
  const LocalIndex n_owned = partition.n_owned_nodes();
  const auto comm = partition.comm().teuchos();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto node_map = Teuchos::rcp(new TpetraMap(
      invalid, Teuchos::ArrayView<const GlobalIndex>(partition.global_nodes().data(), n_owned), 0,
      comm));
  auto coordinates = Teuchos::rcp(new TpetraMultiVector(node_map, 3));
  auto modes = Teuchos::rcp(new TpetraMultiVector(dofs.owned_map(), 6));
  // Rigid-body modes about the centroid keep the six vectors well scaled.
  double centre[3] = {0, 0, 0};
  for (LocalIndex n = 0; n < n_owned; ++n) {
    for (int d = 0; d < 3; ++d)
      centre[d] += partition.coordinates(n)[d];
  }
  const double count = partition.comm().sum(static_cast<double>(n_owned));
  for (int d = 0; d < 3; ++d)
    centre[d] = partition.comm().sum(centre[d]) / count;
  for (int d = 0; d < 3; ++d) {
    auto column = coordinates->getDataNonConst(d);
    for (LocalIndex n = 0; n < n_owned; ++n)
      column[n] = partition.coordinates(n)[d];
  }
  std::vector<Teuchos::ArrayRCP<double>> mode(6);
  for (int k = 0; k < 6; ++k)
    mode[k] = modes->getDataNonConst(k);
  for (LocalIndex n = 0; n < n_owned; ++n) {
    const double* c = partition.coordinates(n);
    const double x = c[0] - centre[0], y = c[1] - centre[1], z = c[2] - centre[2];
    const LocalIndex first = dofs.local_dof(n, 0);
    for (int d = 0; d < 3; ++d)
      mode[d][first + d] = 1.0;  // translations
    // rotations about x, y, z: ω × r, and the rotation itself where the node has rotations
    mode[3][first + 1] = -z;
    mode[3][first + 2] = y;
    mode[4][first + 0] = z;
    mode[4][first + 2] = -x;
    mode[5][first + 0] = -y;
    mode[5][first + 1] = x;
    if (dofs.dofs_of_node(n) == 6) {
      for (int d = 0; d < 3; ++d)
        mode[3 + d][first + 3 + d] = 1.0;
    }
  }
  traits.node_coordinates = coordinates;
  traits.near_null_space = modes;
  return traits;
}

}  // namespace railfe
