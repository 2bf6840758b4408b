// railfe: runs a deck, or describes the parameters decks may use.
//
//   railfe DECK.xml [--output DIR] [--quiet]
//   mpirun -np N railfe DECK.xml
//   railfe --describe [MODULE] [--markdown]
//   railfe --help | --version
#include <mpi.h>

#include <Tpetra_Core.hpp>

#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "framework/app/deck_layout.hpp"
#include "framework/app/runner.hpp"
#include "framework/base/blas_threads.hpp"

namespace {

const char* kUsage =
    "usage: railfe DECK.xml [--output DIR] [--quiet]\n"
    "       mpirun -np N railfe DECK.xml [--output DIR]\n"
    "       railfe --describe [MODULE|SECTION|framework] [--markdown]\n"
    "       railfe --help | --version\n"
    "\n"
    "Runs the analysis steps of a railfe deck (Teuchos ParameterList XML, SI units) and writes\n"
    "Exodus II results, CSV histories and a run summary to the results directory\n"
    "(default: <deck name>_results). --describe lists every valid deck parameter.\n"
    "Exit status: 0 success, 1 bad input, 2 computation failed, 3 internal error.\n";

struct Arguments {
  std::string deck, output, describe_target;
  bool help = false, version = false, describe = false, markdown = false, quiet = false;
  std::string problem;
};

Arguments parse(int argc, char** argv) {
  Arguments arguments;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      arguments.help = true;
    } else if (arg == "--version") {
      arguments.version = true;
    } else if (arg == "--quiet") {
      arguments.quiet = true;
    } else if (arg == "--markdown") {
      arguments.markdown = true;
    } else if (arg == "--describe") {
      arguments.describe = true;
      if (i + 1 < argc && argv[i + 1][0] != '-')
        arguments.describe_target = argv[++i];
    } else if (arg == "--output") {
      if (i + 1 >= argc) {
        arguments.problem = "--output needs a directory";
      } else {
        arguments.output = argv[++i];
      }
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.problem = "unknown option '" + arg + "'";
    } else if (arguments.deck.empty()) {
      arguments.deck = arg;
    } else {
      arguments.problem = "more than one deck given ('" + arguments.deck + "' and '" + arg + "')";
    }
  }
  if (arguments.problem.empty() && !arguments.help && !arguments.version && !arguments.describe &&
      arguments.deck.empty()) {
    arguments.problem = "no deck given";
  }
  return arguments;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  railfe::Communicator comm(MPI_COMM_WORLD);
  const bool root = comm.is_root();
  // One BLAS thread per rank: the ranks already fill the cores (direct solvers lend rank 0 more).
  railfe::set_blas_threads(1);
  try {
    railfe::ModuleRegistry registry;
    railfe::register_physics(registry);
    const Arguments arguments = parse(argc, argv);
    if (!arguments.problem.empty()) {
      if (root)
        std::fprintf(stderr, "railfe: %s\n\n%s", arguments.problem.c_str(), kUsage);
      return railfe::kBadInput;
    }
    if (arguments.help) {
      if (root)
        std::printf("%s", kUsage);
      return railfe::kSuccess;
    }
    if (arguments.version) {
      if (root)
        std::printf("railfe 0.1.0 (Trilinos 13.2)\n");
      return railfe::kSuccess;
    }
    if (arguments.describe) {
      std::ostringstream text;
      const auto format =
          arguments.markdown ? railfe::DescribeFormat::markdown : railfe::DescribeFormat::text;
      if (!railfe::describe_deck(text, registry, arguments.describe_target, format)) {
        if (root) {
          std::fprintf(stderr, "railfe: --describe: nothing is called '%s'; modules: ",
                       arguments.describe_target.c_str());
          for (const auto& name : registry.module_names())
            std::fprintf(stderr, "%s ", name.c_str());
          std::fprintf(stderr, "(or a section name, or 'framework')\n");
        }
        return railfe::kBadInput;
      }
      if (root)
        std::cout << text.str();
      return railfe::kSuccess;
    }
    railfe::RunOptions options{arguments.deck, arguments.output, arguments.quiet};
    return railfe::run_deck(options, registry, comm);
  } catch (const std::exception& error) {
    // Only a programming error gets here, possibly on one rank: say where, then stop them all.
    std::fprintf(stderr, "railfe: internal error on rank %d: %s\n", comm.rank(), error.what());
    if (comm.n_ranks() > 1)
      MPI_Abort(MPI_COMM_WORLD, railfe::kInternalError);
    return railfe::kInternalError;
  }
}
