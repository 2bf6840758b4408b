#pragma once
/// \file
/// A regression case's expected results and their evaluation against a results directory.
///
/// Each check reads one quantity (a CSV cell, or an Exodus field: every value, its extreme, or
/// one entity) and compares it with a reference: an analytic or external value with the tolerance
/// the method promises (Kind reference), or a tight non-regression value from an earlier run
/// (Kind regression). It passes when |computed − expected| <= max(relative × |expected|, floor).

#include <ostream>
#include <string>
#include <vector>

#include "framework/deck/parameter_spec.hpp"
#include "regression/compare/directory_diff.hpp"

namespace railfe {

/// Valid parameters of an expected-results file.
ParameterSpec expectation_parameters();

/// The outcome of one check.
struct CheckOutcome {
  std::string name;       ///< the check's name
  std::string kind;       ///< reference or regression
  double computed = 0;    ///< worst value found (the one furthest from expected)
  double expected = 0;    ///< what it was compared with
  double difference = 0;  ///< |computed − expected|
  double allowed = 0;     ///< the tolerance that applied
  bool passed = false;    ///< whether difference <= allowed
  std::string problem;    ///< why the check could not be evaluated ("" if it could)
};

/// Reads \p expected_file, evaluates every check on \p results_directory and returns the
/// outcomes. Throws InputError if the expected file itself is invalid.
std::vector<CheckOutcome> evaluate_expectations(const std::string& expected_file,
                                                const std::string& results_directory,
                                                std::string* requirement);

/// The tolerance for comparing runs on different numbers of ranks that \p expected_file asks for
/// (its "Parallel agreement" sublist; 1e-8 relative and no floor by default).
DiffTolerance parallel_tolerance(const std::string& expected_file);

/// Prints the outcomes as a table; returns true if every check passed.
bool report_outcomes(std::ostream& out, const std::vector<CheckOutcome>& outcomes);

}  // namespace railfe
