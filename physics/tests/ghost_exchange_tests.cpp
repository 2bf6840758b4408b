// The explicit module's ghost exchange against Tpetra's Import and Export on the same DOF maps:
// at 1, 2 and 3 ranks (3: a rank with two neighbours, and nodes shared by three ranks).

#include <gtest/gtest.h>

#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/explicit/ghost_exchange.hpp"

namespace railfe {
namespace {

/// A value no other DOF (or rank) has, so a misplaced entry cannot pass.
double value_of(GlobalIndex dof, double offset) {
  return 0.25 + 1.5 * static_cast<double>(dof) + offset;
}

struct CutBox {
  Communicator comm;
  Mesh mesh;
  MeshPartition partition;
  DofMap dofs;
  CutBox()
      : mesh(generate_box(BoxSpec{{0, 0, 0}, {3, 2, 1}, {9, 4, 3}})),
        partition(mesh, comm, PartitionMethod::multijagged),
        dofs(partition, 3) {}
  GlobalIndex global(std::size_t k) const {
    return dofs.overlap_map()->getGlobalElement(static_cast<LocalIndex>(k));
  }
};

TEST(GhostExchange, GhostsReceiveTheirOwnersValues) {
  CutBox s;
  GhostExchange exchange(s.dofs);
  EXPECT_EQ(exchange.active(), s.comm.n_ranks() > 1);
  const std::size_t n_owned = s.dofs.n_owned_dofs(), n_overlap = s.dofs.n_overlap_dofs();
  if (s.comm.n_ranks() > 1) {
    const long long ghosts = s.comm.sum(static_cast<long long>(n_overlap - n_owned));
    EXPECT_GT(ghosts, 0) << "the box should be cut, so that ghosts exist";
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> u(n_overlap, nan), v(n_overlap, nan);
  for (std::size_t k = 0; k < n_owned; ++k) {
    u[k] = value_of(s.global(k), 0);
    v[k] = value_of(s.global(k), 0.5);
  }
  exchange.update_ghosts(u.data(), v.data());
  for (std::size_t k = 0; k < n_overlap; ++k) {
    EXPECT_EQ(u[k], value_of(s.global(k), 0)) << "entry " << k << " of " << n_overlap;
    EXPECT_EQ(v[k], value_of(s.global(k), 0.5)) << "entry " << k << " of " << n_overlap;
  }
}

TEST(GhostExchange, OwnersSumEveryRanksContributionAsTpetraExportDoes) {
  CutBox s;
  GhostExchange exchange(s.dofs);
  const std::size_t n_owned = s.dofs.n_owned_dofs(), n_overlap = s.dofs.n_overlap_dofs();
  // Every rank contributes its own value to every entry it holds, owned or ghost.
  std::vector<double> forces(n_overlap);
  for (std::size_t k = 0; k < n_overlap; ++k)
    forces[k] = value_of(s.global(k), 100.0 * s.comm.rank());
  const std::vector<double> before = forces;
  exchange.sum_into_owners(forces.data());

  TpetraVector overlap(s.dofs.overlap_map()), owned(s.dofs.owned_map());
  {
    auto data = overlap.getDataNonConst();
    for (std::size_t k = 0; k < n_overlap; ++k)
      data[k] = before[k];
  }
  owned.doExport(overlap, *s.dofs.importer(), Tpetra::ADD);
  const auto expected = owned.getData();
  for (std::size_t k = 0; k < n_owned; ++k)
    EXPECT_NEAR(forces[k], expected[k], 1e-13 * std::abs(expected[k])) << "owned entry " << k;
  for (std::size_t k = n_owned; k < n_overlap; ++k)
    EXPECT_EQ(forces[k], before[k]) << "ghost entry " << k << " must be left as it was";
  // The test is not trivial: some owned entries gathered another rank's share.
  long long gathered = 0;
  for (std::size_t k = 0; k < n_owned; ++k)
    gathered += expected[k] != before[k] ? 1 : 0;
  const long long gathered_anywhere = s.comm.sum(gathered);
  if (s.comm.n_ranks() > 1) {
    EXPECT_GT(gathered_anywhere, 0);
  }
}

TEST(GhostExchange, RepeatedExchangesReuseTheirBuffers) {
  CutBox s;
  GhostExchange exchange(s.dofs);
  const std::size_t n_owned = s.dofs.n_owned_dofs(), n_overlap = s.dofs.n_overlap_dofs();
  std::vector<double> u(n_overlap, 0.0), v(n_overlap, 0.0);
  for (int round = 0; round < 3; ++round) {
    for (std::size_t k = 0; k < n_owned; ++k)
      u[k] = v[k] = value_of(s.global(k), round);
    exchange.update_ghosts(u.data(), v.data());
    for (std::size_t k = n_owned; k < n_overlap; ++k)
      ASSERT_EQ(u[k], value_of(s.global(k), round)) << "round " << round;
  }
}

}  // namespace
}  // namespace railfe
