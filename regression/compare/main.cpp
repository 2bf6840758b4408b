// railfe-compare: the regression harness's comparator.
//
//   railfe-compare check EXPECTED.xml RESULTS_DIR
//       evaluates every check of a case's expected-results file; exit 0 if all pass.
//   railfe-compare diff REFERENCE_DIR CANDIDATE_DIR [--expected EXPECTED.xml] [--relative R]
//                       [--floor F]
//       compares every CSV and Exodus file of two runs (e.g. 1 and 2 MPI ranks), with the
//       tolerance of the case's "Parallel agreement" or the one given.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "framework/base/error.hpp"
#include "regression/compare/directory_diff.hpp"
#include "regression/compare/expectations.hpp"

namespace {

const char* kUsage =
    "usage: railfe-compare check EXPECTED.xml RESULTS_DIR\n"
    "       railfe-compare diff REFERENCE_DIR CANDIDATE_DIR [--expected EXPECTED.xml]\n"
    "                      [--relative R] [--floor F]\n";

int check(const std::string& expected, const std::string& directory) {
  std::string requirement;
  const auto outcomes = railfe::evaluate_expectations(expected, directory, &requirement);
  std::cout << "requirement: " << requirement << "\n";
  const bool passed = railfe::report_outcomes(std::cout, outcomes);
  std::cout << (passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return passed ? 0 : 1;
}

int diff(int argc, char** argv) {
  railfe::DiffTolerance tolerance;
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    const double value = std::atof(argv[i + 1]);
    if (option == "--expected") {
      tolerance = railfe::parallel_tolerance(argv[i + 1]);
    } else if (option == "--relative") {
      tolerance.relative = value;
    } else if (option == "--floor") {
      tolerance.floor = value;
    } else {
      std::cerr << "railfe-compare: unknown option " << option << "\n" << kUsage;
      return 2;
    }
  }
  const bool same = railfe::compare_directories(argv[2], argv[3], tolerance, std::cout);
  std::cout << (same ? "directories agree\n" : "DIRECTORIES DIFFER\n");
  return same ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = 2;
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "check" && argc == 4) {
      status = check(argv[2], argv[3]);
    } else if (mode == "diff" && argc >= 4) {
      status = diff(argc, argv);
    } else {
      std::cerr << kUsage;
    }
  } catch (const railfe::InputError& error) {
    std::cerr << "railfe-compare: " << error.what() << "\n";
    status = 2;
  } catch (const std::exception& error) {
    std::cerr << "railfe-compare: " << error.what() << "\n";
    status = 2;
  }
  MPI_Finalize();
  return status;
}
