// The mixed 3/6 DOF layout at 1 and 2 ranks: which nodes get rotations, a global numbering that
// every rank agrees on with the owned map a prefix of the overlapping one, and an FE matrix that
// equals the dense sum of element matrices of mixed sizes.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>

#include <cmath>
#include <map>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/testing/assembly_testing.hpp"

namespace railfe {
namespace {

// A 3 × 2 × 2 hex8 box (36 nodes, unit cube) with a beam from node 36 to 37 beyond its xmax face,
// node 36 carrying that face by a rigid link, a spring from box node 0 to node 38 and a point
// mass at node 37: 108 solid DOFs and 18 beam/body DOFs.
Mesh mixed_mesh() {
  BoxSpec spec;
  spec.elements = {3, 2, 2};
  Mesh mesh = generate_box(spec);
  for (double x : {1.5, 0.5, 0.5, 2.5, 0.5, 0.5, -0.5, 0.0, 0.0})
    mesh.coordinates.push_back(x);
  using testing::add_block;
  add_block(mesh, "beam", ElementType::beam2, {36, 37});
  std::vector<GlobalIndex> link{36};
  for (GlobalIndex node : mesh.node_set("xmax", "", "").nodes)
    link.push_back(node);
  add_block(mesh, "link", ElementType::rigid_link, link);
  add_block(mesh, "spring", ElementType::spring2, {0, 38});
  add_block(mesh, "mass", ElementType::point_mass, {37});
  return mesh;
}

TEST(DofMap, MixedLayoutGivesRotationsToBeamAndBodyNodesOnly) {
  const Communicator comm;
  const Mesh mesh = mixed_mesh();
  const MeshPartition partition(mesh, comm, PartitionMethod::multijagged);
  const DofMap dofs = DofMap::for_mesh(partition);
  ASSERT_FALSE(dofs.is_uniform());
  EXPECT_THROW(dofs.dofs_per_node(), std::logic_error);
  EXPECT_THROW(dofs.require_uniform(3, "the test"), std::logic_error);
  EXPECT_EQ(dofs.n_global_dofs(), 3 * 36 + 6 * 3);
  EXPECT_EQ(comm.sum(static_cast<long long>(dofs.n_owned_dofs())), 3 * 36 + 6 * 3);
  EXPECT_EQ(dofs.owned_map()->getGlobalNumElements(), 3u * 36 + 6 * 3);
  EXPECT_TRUE(dofs.owned_map()->isOneToOne());
  EXPECT_EQ(dofs.global_dof(36, 0), 108);
  EXPECT_EQ(dofs.global_dof(38, 5), 125);
  EXPECT_EQ(dofs.describe(108 + 4), "node 37 component θy");
  EXPECT_EQ(dofs.describe(3 * 5 + 2), "node 6 component z");
  EXPECT_EQ(dofs.solver_dofs_per_node(), 1);

  const auto& owned = *dofs.owned_map();
  const auto& overlap = *dofs.overlap_map();
  ASSERT_EQ(static_cast<LocalIndex>(overlap.getNodeNumElements()), dofs.n_overlap_dofs());
  for (LocalIndex i = 0; i < dofs.n_owned_dofs(); ++i)
    EXPECT_EQ(owned.getGlobalElement(i), overlap.getGlobalElement(i));
  for (LocalIndex node = 0; node < partition.n_local_nodes(); ++node) {
    const GlobalIndex global = partition.global_node(node);
    const int expected = global < 36 ? 3 : 6;  // box nodes in the link and spring stay solid
    ASSERT_EQ(dofs.dofs_of_node(node), expected) << "node " << global;
    EXPECT_EQ(dofs.dofs_of_global_node(global), expected);
    for (int c = 0; c < expected; ++c) {
      EXPECT_EQ(overlap.getGlobalElement(dofs.local_dof(node, c)), dofs.global_dof(global, c));
    }
  }
}

TEST(DofMap, UniformMeshesKeepTheUniformLayout) {
  const Communicator comm;
  BoxSpec spec;
  spec.elements = {2, 2, 1};
  const Mesh mesh = generate_box(spec);
  const MeshPartition partition(mesh, comm, PartitionMethod::multijagged);
  const DofMap dofs = DofMap::for_mesh(partition);
  ASSERT_TRUE(dofs.is_uniform());
  EXPECT_EQ(dofs.dofs_per_node(), 3);
  EXPECT_EQ(dofs.global_dof(4, 2), 14);
  EXPECT_EQ(dofs.n_global_dofs(), 3 * mesh.n_nodes());
  EXPECT_EQ(describe_dof(6 * 2 + 3, 6), "node 3 component θx");
  EXPECT_EQ(describe_dof(3 * 2 + 1, 3), "node 3 component y");
}

TEST(DofMap, BeamSharingASolidNodeIsRefused) {
  BoxSpec spec;
  Mesh mesh = generate_box(spec);
  testing::add_block(mesh, "beam", ElementType::beam2, {1, 7});
  try {
    DofMap::mesh_node_dofs(mesh);
    ADD_FAILURE() << "a beam on a solid node accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("node 2 belongs to a beam2 and a hex8"),
              std::string::npos)
        << error.what();
  }
}

// Entry (r, c) of element e's matrix: differs between elements and entries, not symmetric.
double entry(GlobalIndex element, int row, int column) {
  return std::sin(1.0 + element) * 10 + row * 0.37 - column * 0.11 + (row == column ? 50 : 0);
}

TEST(FeMatrix, MixedLayoutEqualsTheDenseSumOfElementMatrices) {
  const Communicator comm;
  const Mesh mesh = mixed_mesh();
  const MeshPartition partition(mesh, comm, PartitionMethod::multijagged);
  const DofMap dofs = DofMap::for_mesh(partition);
  FeMatrix matrix(dofs);
  std::vector<double> values;
  // Element DOFs node-major, each node with its own count.
  auto element_dofs = [&](const GlobalIndex* nodes, int count) {
    std::vector<GlobalIndex> list;
    for (int a = 0; a < count; ++a) {
      for (int c = 0; c < dofs.dofs_of_global_node(nodes[a]); ++c)
        list.push_back(dofs.global_dof(nodes[a], c));
    }
    return list;
  };
  for (int pass = 0; pass < 2; ++pass) {  // the second assembly must start from zero again
    matrix.begin_assembly();
    for (std::size_t b = 0; b < partition.blocks().size(); ++b) {
      const auto& local = partition.blocks()[b];
      const auto& block = mesh.blocks[local.block];
      for (LocalIndex e = 0; e < local.n_elements(); ++e) {
        const GlobalIndex element = local.elements[e];
        const int n = static_cast<int>(
            element_dofs(block.element_nodes(element), block.n_element_nodes(element)).size());
        values.assign(static_cast<std::size_t>(n) * n, 0.0);
        for (int r = 0; r < n; ++r) {
          for (int c = 0; c < n; ++c)
            values[n * r + c] = entry(block.first_element + element, r, c);
        }
        matrix.add_element(partition.first_local_element(b) + e, values.data());
      }
    }
    matrix.end_assembly();
  }
  const auto A = matrix.matrix();

  testing::DenseRows reference;
  for (const auto& block : mesh.blocks) {
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const auto list = element_dofs(block.element_nodes(e), block.n_element_nodes(e));
      for (std::size_t r = 0; r < list.size(); ++r) {
        for (std::size_t c = 0; c < list.size(); ++c)
          reference[list[r]][list[c]] += entry(block.first_element + e, r, c);
      }
    }
  }
  const long long rows_checked = testing::expect_rows_equal(*A, reference);
  EXPECT_EQ(comm.sum(rows_checked), 3 * 36 + 6 * 3);
}

}  // namespace
}  // namespace railfe
