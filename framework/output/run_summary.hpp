#pragma once
/// \file
/// The run summary: what was modelled, its size, the solver's iterations and residuals, wall time
/// per phase and peak memory. Printed at the end and written beside the results as text (for
/// people) and JSON (for benchmark and regression scripts).

#include <string>
#include <utility>
#include <vector>

namespace railfe {

/// Sections of key/value lines, in the order they were added.
class RunSummary {
 public:
  /// Adds a text value.
  void add(const std::string& section, const std::string& key, const std::string& value);
  /// Adds a number with its unit ("" for counts and ratios).
  void add(const std::string& section, const std::string& key, double value,
           const std::string& unit = "");
  /// The first number whose key begins with \p prefix, in any section; \p fallback if none.
  double number(const std::string& prefix, double fallback = 0) const;
  /// The summary as aligned text.
  std::string text() const;
  /// The summary as a JSON object of objects (numbers stay numbers, units go into the key as
  /// "key [unit]").
  std::string json() const;

 private:
  struct Line {
    std::string key, text, unit;
    double number = 0;
    bool is_number = false;
  };
  struct Section {
    std::string name;
    std::vector<Line> lines;
  };
  Section& section(const std::string& name);
  std::vector<Section> sections_;
};

}  // namespace railfe
