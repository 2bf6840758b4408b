#pragma once
/// \file
/// CSV for histories and scalar results: one header row whose names carry their units
/// (time_s, force_N), then rows of numbers at full precision. Opens in any spreadsheet.

#include <fstream>
#include <string>
#include <vector>

namespace railfe {

/// A CSV file written by rank 0 (other ranks hold an inactive writer).
class CsvWriter {
 public:
  /// Opens \p path and writes the header \p columns when \p active. Throws RunError if the file
  /// cannot be opened.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool active);
  /// Writes a row of text cells (for label columns); the count must match the header. A cell
  /// holding a comma, a quote or a line break is quoted (RFC 4180), so a label such as a deck's
  /// "umbrella (0,0)" keeps its row's columns.
  void write_row(const std::vector<std::string>& cells);
  /// Writes a row of numbers with 17 significant digits.
  void write_row(const std::vector<double>& values);
  /// Flushes to disk (call at intervals so a long run's history survives a crash).
  void flush();

  /// Formats \p value the way write_row() does.
  static std::string format(double value);
  /// \p cell as a CSV field: unchanged, or in double quotes with its quotes doubled where it
  /// holds a comma, a quote or a line break.
  static std::string quoted(const std::string& cell);
  /// The cells of one line of such a file: split at the commas outside quotes, a quoted cell
  /// unquoted (its doubled quotes single). What quoted() writes, this reads back.
  static std::vector<std::string> cells(const std::string& line);

 private:
  std::ofstream file_;
  std::size_t n_columns_;
  bool active_;
};

}  // namespace railfe
