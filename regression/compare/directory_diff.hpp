#pragma once
/// \file
/// Comparing two results directories file by file, as exodiff would (Debian has none): every
/// number in every CSV, every value of every Exodus variable at every output time.

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace railfe {

/// Tolerance of a directory comparison: values a, b agree when |a − b| <= relative ×
/// max(|b|, scale) or |a − b| <= floor, where scale is the largest |value| of the quantity the
/// value belongs to (CSV columns with the same unit suffix, Exodus variables with the same name
/// before their last '_': the components of one vector or tensor). The test is thus normwise per
/// quantity, so components that are round-off noise around zero (1e-18 in one run, -5e-18 in
/// another, beside values of 1e-4) do not fail it.
struct DiffTolerance {
  double relative = 1e-8;  ///< normwise relative tolerance
  double floor = 0.0;      ///< absolute floor
  /// CSV columns and Exodus variables not compared: quantities a method leaves arbitrary (the
  /// split of a rigid-body eigenspace into modes).
  std::vector<std::string> ignored;
  /// Whether \p name is ignored.
  bool ignores(const std::string& name) const {
    return std::find(ignored.begin(), ignored.end(), name) != ignored.end();
  }
};

/// Compares every *.csv and *.exo file of \p reference with the file of the same name in
/// \p candidate (summary files and files only in one directory are reported). Prints one line per
/// file and per mismatch; returns true when everything agrees.
bool compare_directories(const std::string& reference, const std::string& candidate,
                         const DiffTolerance& tolerance, std::ostream& out);

}  // namespace railfe
