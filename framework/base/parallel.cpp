#include "framework/base/parallel.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include <Teuchos_DefaultMpiComm.hpp>

#include "framework/base/error.hpp"

namespace railfe {

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &n_ranks_);
}

Teuchos::RCP<const Teuchos::Comm<int>> Communicator::teuchos() const {
  return Teuchos::rcp(new Teuchos::MpiComm<int>(comm_));
}

void Communicator::barrier() const {
  MPI_Barrier(comm_);
}

void Communicator::quiet_barrier() const {
  using Clock = std::chrono::steady_clock;
  MPI_Request request;
  MPI_Ibarrier(comm_, &request);
  const Clock::time_point start = Clock::now();
  int done = 0;
  MPI_Test(&request, &done, MPI_STATUS_IGNORE);
  while (!done) {
    // Open MPI polls at full speed inside a blocking call: only a sleep gives the core away.
    // Each nap is a tenth of the wait so far (50 µs to 2 ms): a short wait is barely lengthened,
    // and a long one costs well under 1 % of a core.
    const Clock::duration waited = Clock::now() - start;
    if (waited > std::chrono::milliseconds(1))
      std::this_thread::sleep_for(std::clamp<Clock::duration>(
          waited / 10, std::chrono::microseconds(50), std::chrono::milliseconds(2)));
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
  }
}

void Communicator::broadcast(std::string& text) const {
  unsigned long long size = text.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, comm_);
  text.resize(size);
  if (size > 0)
    MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, comm_);
}

void Communicator::broadcast(std::vector<double>& values) const {
  unsigned long long size = values.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, comm_);
  values.resize(size);
  if (size > 0)
    MPI_Bcast(values.data(), static_cast<int>(size), MPI_DOUBLE, 0, comm_);
}

namespace {

template <typename T>
T all_reduce(T value, MPI_Datatype type, MPI_Op operation, MPI_Comm comm) {
  T result{};
  MPI_Allreduce(&value, &result, 1, type, operation, comm);
  return result;
}

}  // namespace

double Communicator::sum(double value) const {
  return all_reduce(value, MPI_DOUBLE, MPI_SUM, comm_);
}

long long Communicator::sum(long long value) const {
  return all_reduce(value, MPI_LONG_LONG, MPI_SUM, comm_);
}

double Communicator::max(double value) const {
  return all_reduce(value, MPI_DOUBLE, MPI_MAX, comm_);
}

long long Communicator::max(long long value) const {
  return all_reduce(value, MPI_LONG_LONG, MPI_MAX, comm_);
}

double Communicator::min(double value) const {
  return all_reduce(value, MPI_DOUBLE, MPI_MIN, comm_);
}

void Communicator::sum_in_place(std::vector<double>& values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
}

namespace {

template <typename T>
std::vector<T> gather_impl(const std::vector<T>& local, MPI_Datatype type, MPI_Comm comm,
                           int n_ranks, bool to_all, bool is_root) {
  int count = static_cast<int>(local.size());
  std::vector<int> counts(n_ranks), offsets(n_ranks, 0);
  if (to_all) {
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  } else {
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  }
  long long total = 0;
  for (int r = 0; r < n_ranks; ++r) {
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  std::vector<T> result((to_all || is_root) ? total : 0);
  if (to_all) {
    MPI_Allgatherv(local.data(), count, type, result.data(), counts.data(), offsets.data(), type,
                   comm);
  } else {
    MPI_Gatherv(local.data(), count, type, result.data(), counts.data(), offsets.data(), type, 0,
                comm);
  }
  return result;
}

}  // namespace

std::vector<long long> Communicator::all_gather(const std::vector<long long>& local) const {
  return gather_impl(local, MPI_LONG_LONG, comm_, n_ranks_, true, is_root());
}

std::vector<double> Communicator::gather_to_root(const std::vector<double>& local) const {
  return gather_impl(local, MPI_DOUBLE, comm_, n_ranks_, false, is_root());
}

std::vector<long long> Communicator::gather_to_root(const std::vector<long long>& local) const {
  return gather_impl(local, MPI_LONG_LONG, comm_, n_ranks_, false, is_root());
}

void Communicator::agree(const std::string& local_error, bool as_input_error) const {
  // The lowest failing rank's message wins, so every rank throws the same text.
  const int mine = local_error.empty() ? n_ranks_ : rank_;
  int first_failing = n_ranks_;
  MPI_Allreduce(&mine, &first_failing, 1, MPI_INT, MPI_MIN, comm_);
  if (first_failing == n_ranks_)
    return;
  std::string message = local_error;
  unsigned long long size = message.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, first_failing, comm_);
  message.resize(size);
  if (size > 0)
    MPI_Bcast(message.data(), static_cast<int>(size), MPI_CHAR, first_failing, comm_);
  if (as_input_error)
    throw InputError(message);
  throw RunError(message);
}

void Communicator::run_collectively(const std::function<void()>& phase) const {
  std::string input_error, run_error;
  try {
    phase();
  } catch (const InputError& error) {
    input_error = error.what();
  } catch (const RunError& error) {
    run_error = error.what();
  }
  agree(input_error, true);
  agree(run_error, false);
}

}  // namespace railfe
