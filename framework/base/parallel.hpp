#pragma once
/// \file
/// The MPI communicator as railfe uses it: collectives on plain types, and the error agreement
/// that lets every rank stop cleanly when any rank finds a problem.

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

namespace Teuchos {
template <typename Ordinal>
class Comm;
}

namespace railfe {

/// A communicator over the ranks of one run. Cheap to copy; does not own the MPI communicator.
class Communicator {
 public:
  /// Wraps \p comm (MPI_COMM_WORLD by default).
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);

  /// This rank's index, 0 .. n_ranks()-1.
  int rank() const { return rank_; }
  /// Number of ranks.
  int n_ranks() const { return n_ranks_; }
  /// True on the rank that prints and writes files that are not per rank.
  bool is_root() const { return rank_ == 0; }
  /// The raw MPI communicator.
  MPI_Comm mpi() const { return comm_; }
  /// The same communicator as Teuchos/Tpetra want it.
  Teuchos::RCP<const Teuchos::Comm<int>> teuchos() const;

  /// Blocks until every rank arrives.
  void barrier() const;
  /// Blocks until every rank arrives, sleeping rather than polling after the first millisecond:
  /// for ranks that wait while rank 0 works alone (a direct factorization), so that their cores
  /// are free for its threads. Wakes within a tenth of the wait (at most 2 ms) of the last arrival.
  void quiet_barrier() const;
  /// Sends \p text from rank 0 to every rank.
  void broadcast(std::string& text) const;
  /// Sends \p values from rank 0 to every rank (resized on receivers).
  void broadcast(std::vector<double>& values) const;
  /// Sum over ranks.
  double sum(double value) const;
  /// Sum over ranks.
  long long sum(long long value) const;
  /// Maximum over ranks.
  double max(double value) const;
  /// Maximum over ranks.
  long long max(long long value) const;
  /// Minimum over ranks.
  double min(double value) const;
  /// Element-wise sum over ranks, in place.
  void sum_in_place(std::vector<double>& values) const;
  /// Concatenates every rank's \p local values, in rank order, on every rank.
  std::vector<long long> all_gather(const std::vector<long long>& local) const;
  /// Concatenates every rank's \p local values, in rank order, on rank 0 (empty elsewhere).
  std::vector<double> gather_to_root(const std::vector<double>& local) const;
  /// Concatenates every rank's \p local values, in rank order, on rank 0 (empty elsewhere).
  std::vector<long long> gather_to_root(const std::vector<long long>& local) const;

  /// Collective error agreement. Every rank calls it with its own error message ("" if none).
  /// If any rank has one, every rank throws: InputError when \p as_input_error, else RunError,
  /// carrying the message of the lowest failing rank.
  void agree(const std::string& local_error, bool as_input_error) const;

  /// Runs \p phase on every rank; an InputError or RunError thrown on some ranks only is turned
  /// into the same exception on all ranks (so no rank waits forever in a later collective). Only
  /// use around code whose own collectives cannot be left half-entered by a throwing rank.
  void run_collectively(const std::function<void()>& phase) const;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int n_ranks_ = 1;
};

}  // namespace railfe
