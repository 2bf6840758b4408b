#include "framework/base/numeric_csv.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace railfe {

std::optional<std::vector<NumericCsvRow>> read_numeric_csv(const std::string& path) {
  std::ifstream file(path);
  if (!file)
    return std::nullopt;
  std::vector<NumericCsvRow> rows;
  std::string line;
  std::getline(file, line);  // header
  for (int number = 2; std::getline(file, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    NumericCsvRow row;
    row.line = number;
    for (double value; fields >> value;)
      row.values.push_back(value);
    row.all_numbers = fields.eof();
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace railfe
