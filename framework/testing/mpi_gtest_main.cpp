// googletest main for railfe's unit tests: starts MPI and Kokkos (through Tpetra's ScopeGuard)
// once, and lets only rank 0 print results so two-rank runs stay readable. Every rank still runs
// every test, and the process exits non-zero if any rank failed.
#include <gtest/gtest.h>
#include <mpi.h>

#include <Tpetra_Core.hpp>

#include "framework/base/blas_threads.hpp"

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  railfe::set_blas_threads(1);  // as railfe itself: the ranks fill the cores
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  int any_failed = 0;
  MPI_Allreduce(&failed, &any_failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return any_failed;
}
