#include "physics/contact_patch/lateral_separation_file.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/base/error.hpp"
#include "framework/base/numeric_csv.hpp"

namespace railfe {

LateralSeparation read_lateral_separation(const std::string& path, const std::string& deck,
                                          const std::string& where) {
  const auto rows = read_numeric_csv(path);
  if (!rows)
    throw_input_error(deck, where, "'" + path + "' cannot be read",
                      "a CSV file relative to the deck's directory");
  const std::string allowed =
      "a header line, then rows y, s (m) or y, s, R (m; R the wheel's rolling radius) with y "
      "increasing, every row with as many values";
  LateralSeparation lateral;
  for (const NumericCsvRow& row : *rows) {
    const std::vector<double>& v = row.values;
    const std::size_t width =
        lateral.y.empty() ? v.size() : (lateral.rolling_radius.empty() ? 2u : 3u);
    const bool finite = std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    const std::string at = "'" + path + "', line " + std::to_string(row.line) + ": ";
    if (!row.all_numbers || v.size() != width || width < 2 || width > 3 || !finite ||
        (width == 3 && !(v[2] > 0)))
      throw_input_error(deck, where,
                        at + "not " + (width == 3 ? "three" : "two") + " finite numbers" +
                            (width == 3 ? ", R > 0" : ""),
                        allowed);
    if (!lateral.y.empty() && !(v[0] > lateral.y.back()))
      throw_input_error(deck, where, at + "y does not increase", allowed);
    lateral.y.push_back(v[0]);
    lateral.s.push_back(v[1]);
    if (width == 3)
      lateral.rolling_radius.push_back(v[2]);
  }
  if (lateral.y.size() < 3)
    throw_input_error(deck, where,
                      "'" + path + "' has " + std::to_string(lateral.y.size()) + " rows",
                      "at least 3 rows y, s");
  return lateral;
}

}  // namespace railfe
