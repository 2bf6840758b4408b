#pragma once
/// \file
/// Helpers shared by the assembly and constraint tests (framework and physics): building small
/// meshes by hand, solving a constrained system, comparing a distributed matrix with a dense
/// reference.

#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "framework/assembly/linear_constraints.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/solvers/direct_solvers.hpp"

namespace railfe::testing {

/// Appends a block of one element of \p type on \p nodes to \p mesh (and renumbers blocks).
inline void add_block(Mesh& mesh, const std::string& name, ElementType type,
                      const std::vector<GlobalIndex>& nodes) {
  ElementBlock block;
  block.name = name;
  block.id = static_cast<int>(mesh.blocks.size()) + 1;
  block.type = type;
  block.add_element(nodes.data(), static_cast<int>(nodes.size()));
  mesh.blocks.push_back(block);
  mesh.number_blocks();
}

/// Applies \p constraints (finalized) to K u = \p forces (K is modified), solves with CHOLMOD and
/// returns u (collective).
inline TpetraVector solve_constrained(const Teuchos::RCP<TpetraMatrix>& K,
                                      const TpetraVector& forces, LinearConstraints& constraints) {
  TpetraVector loads(forces, Teuchos::Copy);
  auto system = constraints.apply(K, loads);
  auto solver = make_cholmod_solver(1e-12);
  solver->setup(system, ProblemTraits{});
  TpetraVector u(forces.getMap());
  solver->solve(loads, u);
  constraints.recover(u);
  return u;
}

/// Dense rows keyed by global row, then global column.
using DenseRows = std::map<GlobalIndex, std::map<GlobalIndex, double>>;

/// Expects every owned row of \p A to hold exactly the entries of \p reference (relative 1e-12);
/// returns the number of rows checked on this rank.
inline long long expect_rows_equal(const TpetraMatrix& A, const DenseRows& reference) {
  const auto row_map = A.getRowMap();
  long long rows_checked = 0;
  for (std::size_t i = 0; i < row_map->getNodeNumElements(); ++i) {
    const GlobalIndex row = row_map->getGlobalElement(static_cast<LocalIndex>(i));
    std::size_t n = A.getNumEntriesInGlobalRow(row);
    Teuchos::Array<GlobalIndex> columns(n);
    Teuchos::Array<double> values(n);
    A.getGlobalRowCopy(row, columns(), values(), n);
    const auto& expected = reference.at(row);
    EXPECT_EQ(n, expected.size()) << "row " << row;
    for (std::size_t k = 0; k < n; ++k) {
      const double want = expected.at(columns[k]);
      EXPECT_NEAR(values[k], want, 1e-12 * std::abs(want) + 1e-12) << row << "," << columns[k];
    }
    ++rows_checked;
  }
  return rows_checked;
}

}  // namespace railfe::testing
