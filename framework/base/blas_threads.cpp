#include "framework/base/blas_threads.hpp"

#include <dirent.h>
#include <dlfcn.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <thread>

namespace railfe {

bool set_blas_threads(int threads) {
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr)
    return false;
  // Looked up at run time: the BLAS behind libblas.so.3 is the system's choice, and only
  // OpenBLAS has the call.
  using Setter = void (*)(int);
  static const auto setter =
      reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (setter == nullptr)
    return false;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  setter(std::clamp(threads, 1, cores));
  return true;
}

namespace {

// The threads of this process (Linux: /proc/self/task).
std::vector<pid_t> process_threads() {
  std::vector<pid_t> threads;
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (const dirent* entry = readdir(tasks))
      if (entry->d_name[0] != '.')
        threads.push_back(static_cast<pid_t>(std::stol(entry->d_name)));
    closedir(tasks);
  }
  return threads;
}

}  // namespace

BorrowedBlasThreads::BorrowedBlasThreads(int threads) {
  if (threads <= 1 || !set_blas_threads(threads))
    return;
  set_ = true;
  // mpiexec binds each rank to its core (Open MPI's default up to two ranks), and the BLAS
  // threads, started with the process, inherit rank 0's: they would all share one core. Widen
  // every thread to the machine's cores while the other ranks sleep; the destructor restores.
  cpu_set_t all;
  CPU_ZERO(&all);
  const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
  for (long cpu = 0; cpu < cpus && cpu < CPU_SETSIZE; ++cpu)
    CPU_SET(cpu, &all);
  for (pid_t thread : process_threads()) {
    cpu_set_t mask;
    if (sched_getaffinity(thread, sizeof mask, &mask) != 0)
      continue;
    if (sched_setaffinity(thread, sizeof all, &all) == 0)
      saved_.emplace_back(thread, mask);
  }
}

BorrowedBlasThreads::~BorrowedBlasThreads() {
  if (!set_)
    return;
  set_blas_threads(1);
  for (const auto& [thread, mask] : saved_)
    sched_setaffinity(thread, sizeof mask, &mask);
}

}  // namespace railfe
