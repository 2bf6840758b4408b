// Assembly and constraints at 1 and 2 ranks: the FE matrix equals a dense sum of element matrices
// over the whole mesh; constrained solutions satisfy their constraints and are optimal on the
// admissible space.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>
#include <map>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/solvers/direct_solvers.hpp"
#include "framework/solvers/gathered_matrix.hpp"
#include "framework/testing/assembly_testing.hpp"

namespace railfe {
namespace {

// An element matrix that differs between elements and entries (not symmetric), so misplaced or
// missed contributions show.
double test_entry(GlobalIndex element, int row, int column) {
  return std::sin(1.0 + element) * 10 + row * 0.37 - column * 0.11 + (row == column ? 50 : 0);
}

// An SPD element matrix: (8 I - ones + 0.01 I) ⊗ I3, scaled by the element number.
void spd_element(GlobalIndex element, double* matrix) {
  for (int r = 0; r < 24; ++r) {
    for (int c = 0; c < 24; ++c) {
      const bool same_component = r % 3 == c % 3;
      const double graph = (r / 3 == c / 3 ? 8.01 : 0.0) - 1.0;
      matrix[24 * r + c] = same_component ? (1.0 + element % 3) * graph : 0.0;
    }
  }
}

struct Fixture {
  Communicator comm;
  Mesh mesh;
  std::unique_ptr<MeshPartition> partition;
  std::unique_ptr<DofMap> dofs;

  explicit Fixture(std::array<int, 3> elements = {3, 2, 2}) {
    BoxSpec spec;
    spec.elements = elements;
    mesh = generate_box(spec);
    partition = std::make_unique<MeshPartition>(mesh, comm, PartitionMethod::multijagged);
    dofs = std::make_unique<DofMap>(*partition, 3);
  }

  GlobalIndex global_element(std::size_t local_block, LocalIndex e) const {
    const auto& block = partition->blocks()[local_block];
    return mesh.blocks[block.block].first_element + block.elements[e];
  }

  template <typename ElementMatrix>
  void assemble(FeMatrix& matrix, ElementMatrix element_matrix) const {
    double values[576];
    matrix.begin_assembly();
    for (std::size_t b = 0; b < partition->blocks().size(); ++b) {
      for (LocalIndex e = 0; e < partition->blocks()[b].n_elements(); ++e) {
        element_matrix(global_element(b, e), values);
        matrix.add_element(partition->first_local_element(b) + e, values);
      }
    }
    matrix.end_assembly();
  }
};

TEST(FeMatrix, EqualsTheDenseSumOfElementMatrices) {
  Fixture f;
  FeMatrix matrix(*f.dofs);
  auto fill = [](GlobalIndex element, double* values) {
    for (int r = 0; r < 24; ++r) {
      for (int c = 0; c < 24; ++c)
        values[24 * r + c] = test_entry(element, r, c);
    }
  };
  // Twice: the second assembly must start from zero again.
  f.assemble(matrix, fill);
  f.assemble(matrix, fill);
  const auto A = matrix.matrix();

  // Reference: every element of the whole mesh, summed into dense rows keyed by global DOF.
  testing::DenseRows reference;
  const auto& block = f.mesh.blocks[0];
  for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
    const GlobalIndex* nodes = block.element_nodes(e);
    for (int r = 0; r < 24; ++r) {
      for (int c = 0; c < 24; ++c) {
        reference[3 * nodes[r / 3] + r % 3][3 * nodes[c / 3] + c % 3] += test_entry(e, r, c);
      }
    }
  }
  const long long rows_checked = testing::expect_rows_equal(*A, reference);
  EXPECT_EQ(f.comm.sum(rows_checked), 3 * f.mesh.n_nodes());
}

using testing::solve_constrained;

// u*: a smooth field over global DOFs, used as the exact solution.
double exact(GlobalIndex dof) {
  return std::sin(0.3 * dof) + 0.1 * (dof % 3);
}

TEST(LinearConstraints, PrescribedValuesAreExactAndReactionsBalance) {
  Fixture f;
  FeMatrix stiffness(*f.dofs);
  f.assemble(stiffness, spd_element);
  auto K = stiffness.matrix();
  TpetraVector u_exact(f.dofs->owned_map()), forces(f.dofs->owned_map());
  for (LocalIndex i = 0; i < f.dofs->n_owned_dofs(); ++i) {
    u_exact.replaceLocalValue(i, exact(f.dofs->owned_map()->getGlobalElement(i)));
  }
  K->apply(u_exact, forces);
  TpetraVector K_u(forces, Teuchos::Copy);
  LinearConstraints constraints(*f.dofs, "test");
  std::vector<GlobalIndex> fixed;
  for (GlobalIndex node : f.mesh.node_set("xmin", "", "").nodes) {
    for (int d = 0; d < 3; ++d) {
      fixed.push_back(3 * node + d);
      constraints.prescribe(3 * node + d, exact(3 * node + d));
      // Loads at prescribed DOFs do not change the solution, only the reactions.
      const LocalIndex local = f.dofs->owned_map()->getLocalElement(3 * node + d);
      if (local >= 0)
        forces.replaceLocalValue(local, 123.0);
    }
  }
  constraints.finalize();
  EXPECT_EQ(constraints.n_prescribed(), static_cast<GlobalIndex>(fixed.size()));
  const TpetraVector u = solve_constrained(K, forces, constraints);
  TpetraVector reactions(f.dofs->owned_map());
  constraints.reactions(u, reactions);
  const auto u_data = u.getData(), exact_data = u_exact.getData();
  const auto r_data = reactions.getData(), ku_data = K_u.getData();
  for (LocalIndex i = 0; i < f.dofs->n_owned_dofs(); ++i) {
    EXPECT_NEAR(u_data[i], exact_data[i], 1e-10);
    const GlobalIndex dof = f.dofs->owned_map()->getGlobalElement(i);
    const bool is_fixed = std::find(fixed.begin(), fixed.end(), dof) != fixed.end();
    EXPECT_NEAR(r_data[i], is_fixed ? ku_data[i] - 123.0 : 0.0, 1e-9 * (1 + std::abs(ku_data[i])));
  }
}

TEST(LinearConstraints, MultipointSolutionIsTheConstrainedMinimum) {
  Fixture f;
  FeMatrix stiffness(*f.dofs);
  f.assemble(stiffness, spd_element);
  auto K = stiffness.matrix();
  // Slaves: the DOFs of the face x = 1 follow 2 × the matching DOF at x = 0, plus 0.1.
  const auto& slaves = f.mesh.node_set("xmax", "", "").nodes;
  const auto& masters = f.mesh.node_set("xmin", "", "").nodes;
  ASSERT_EQ(slaves.size(), masters.size());
  LinearConstraints constraints(*f.dofs, "test");
  std::map<GlobalIndex, GlobalIndex> master_of;
  for (std::size_t k = 0; k < slaves.size(); ++k) {
    for (int d = 0; d < 3; ++d) {
      constraints.add_multipoint({3 * slaves[k] + d, {{3 * masters[k] + d, 2.0}}, 0.1});
      master_of[3 * slaves[k] + d] = 3 * masters[k] + d;
    }
  }
  constraints.prescribe(3 * f.mesh.node_set("ymin", "", "").nodes[1] + 2, 0.25);
  constraints.finalize();
  TpetraVector forces(f.dofs->owned_map());
  for (LocalIndex i = 0; i < f.dofs->n_owned_dofs(); ++i) {
    forces.replaceLocalValue(i, std::cos(1.0 + f.dofs->owned_map()->getGlobalElement(i)));
  }
  const TpetraVector u = solve_constrained(K, forces, constraints);

  // Gather u and the residual r = K u - f on rank 0 and check there.
  TpetraVector residual(f.dofs->owned_map());
  K->apply(u, residual);
  residual.update(-1.0, forces, 1.0);
  const GatheredMatrix gathered(*K);
  const auto u_all = gathered.gather(u);
  const auto r_all = gathered.gather(residual);
  if (!gathered.on_root())
    return;
  std::map<GlobalIndex, double> u_of, r_of;
  for (long i = 0; i < gathered.n_rows(); ++i) {
    u_of[gathered.global_index(i)] = u_all[i];
    r_of[gathered.global_index(i)] = r_all[i];
  }
  for (const auto& [slave, master] : master_of) {
    EXPECT_NEAR(u_of[slave], 2.0 * u_of[master] + 0.1, 1e-12);
  }
  const GlobalIndex fixed = 3 * f.mesh.node_set("ymin", "", "").nodes[1] + 2;
  EXPECT_NEAR(u_of[fixed], 0.25, 1e-14);
  // Optimality: for each free master DOF m, r_m + 2 r_s = 0 (variation of m moves its slave).
  std::map<GlobalIndex, double> projected(r_of.begin(), r_of.end());
  for (const auto& [slave, master] : master_of) {
    projected[master] += 2.0 * r_of[slave];
    projected.erase(slave);
  }
  projected.erase(fixed);
  for (const auto& [dof, value] : projected)
    EXPECT_NEAR(value, 0.0, 1e-9) << "dof " << dof;
}

TEST(LinearConstraints, ConflictsAreRefused) {
  Fixture f;
  LinearConstraints constraints(*f.dofs, "deck.xml");
  constraints.add_multipoint({3, {{0, 1.0}}, 0.0});
  constraints.add_multipoint({0, {{6, 1.0}}, 0.0});
  try {
    constraints.finalize();
    ADD_FAILURE() << "chained constraints accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("both a master and a slave"), std::string::npos);
  }
}

}  // namespace
}  // namespace railfe
