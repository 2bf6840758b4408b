#pragma once
/// \file
/// Tables of numbers that users give as CSV files (irregularities, profile separations): a header
/// line, then rows of numbers separated by commas or blanks. Each reader checks the widths and
/// ranges it needs and names the file and line at fault.

#include <optional>
#include <string>
#include <vector>

namespace railfe {

/// One data row of a numeric CSV file.
struct NumericCsvRow {
  int line = 0;                ///< line number in the file (the header is line 1)
  std::vector<double> values;  ///< the numbers read, left to right
  bool all_numbers = true;     ///< false where a field is not a number (values stop before it)
};

/// The data rows of \p path after its header line, blank lines skipped; nullopt when the file
/// cannot be opened.
std::optional<std::vector<NumericCsvRow>> read_numeric_csv(const std::string& path);

}  // namespace railfe
