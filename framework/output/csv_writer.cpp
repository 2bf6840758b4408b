#include "framework/output/csv_writer.hpp"

#include <cstdio>
#include <stdexcept>

#include "framework/base/error.hpp"

namespace railfe {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool active)
    : n_columns_(columns.size()), active_(active) {
  if (!active_)
    return;
  file_.open(path);
  if (!file_)
    throw RunError("cannot write '" + path + "'");
  write_row(columns);
}

void CsvWriter::write_row(const std::vector<std::string>& cells) {
  if (!active_)
    return;
  if (cells.size() != n_columns_)
    throw std::logic_error("railfe: CSV row has the wrong width");
  for (std::size_t i = 0; i < cells.size(); ++i)
    file_ << (i ? "," : "") << quoted(cells[i]);
  file_ << "\n";
}

std::string CsvWriter::quoted(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos)
    return cell;
  std::string text = "\"";
  for (char c : cell) {
    text += c;
    if (c == '"')
      text += c;
  }
  return text + "\"";
}

std::vector<std::string> CsvWriter::cells(const std::string& line) {
  std::vector<std::string> found(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      found.back() += line[++i];
    else if (c == '"')
      in_quotes = !in_quotes;
    else if (c == ',' && !in_quotes)
      found.emplace_back();
    else
      found.back() += c;
  }
  return found;
}

void CsvWriter::write_row(const std::vector<double>& values) {
  std::vector<std::string> cells;
  cells.reserve(values.size());
  for (double value : values)
    cells.push_back(format(value));
  write_row(cells);
}

void CsvWriter::flush() {
  if (active_)
    file_.flush();
}

std::string CsvWriter::format(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace railfe
