#pragma once
/// \file
/// The thread count of OpenBLAS, the BLAS under CHOLMOD. railfe keeps it at one thread and
/// lends rank 0 the cores of the ranks that sleep while it factorizes alone (a direct solver
/// gathers the matrix there). A user's OPENBLAS_NUM_THREADS overrides both.

#include <sched.h>
#include <sys/types.h>

#include <utility>
#include <vector>

namespace railfe {

/// Sets OpenBLAS to \p threads threads, when OpenBLAS is the BLAS loaded and the user did not set
/// OPENBLAS_NUM_THREADS; otherwise does nothing. Returns whether it set them.
bool set_blas_threads(int threads);

/// For its lifetime, the calling rank's BLAS runs on \p threads threads (capped by the cores),
/// and the rank's threads may run on every core of the machine (an MPI launcher binds each rank
/// to one); then one thread and the rank's own binding again.
class BorrowedBlasThreads {
 public:
  /// Sets \p threads threads (see set_blas_threads()).
  explicit BorrowedBlasThreads(int threads);
  /// Back to one thread.
  ~BorrowedBlasThreads();
  BorrowedBlasThreads(const BorrowedBlasThreads&) = delete;
  BorrowedBlasThreads& operator=(const BorrowedBlasThreads&) = delete;

 private:
  bool set_ = false;
  std::vector<std::pair<pid_t, cpu_set_t>> saved_;  // each thread's affinity before
};

}  // namespace railfe
