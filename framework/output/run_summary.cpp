#include "framework/output/run_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace railfe {

RunSummary::Section& RunSummary::section(const std::string& name) {
  for (auto& existing : sections_) {
    if (existing.name == name)
      return existing;
  }
  sections_.push_back({name, {}});
  return sections_.back();
}

void RunSummary::add(const std::string& section_name, const std::string& key,
                     const std::string& value) {
  section(section_name).lines.push_back({key, value, "", 0, false});
}

void RunSummary::add(const std::string& section_name, const std::string& key, double value,
                     const std::string& unit) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  section(section_name).lines.push_back({key, buffer, unit, value, true});
}

double RunSummary::number(const std::string& prefix, double fallback) const {
  for (const auto& section : sections_)
    for (const auto& line : section.lines)
      if (line.is_number && line.key.compare(0, prefix.size(), prefix) == 0)
        return line.number;
  return fallback;
}

std::string RunSummary::text() const {
  std::ostringstream out;
  for (const auto& section : sections_) {
    out << section.name << "\n";
    std::size_t width = 0;
    for (const auto& line : section.lines)
      width = std::max(width, line.key.size());
    for (const auto& line : section.lines) {
      out << "  " << line.key << std::string(width - line.key.size() + 2, ' ') << line.text;
      if (!line.unit.empty())
        out << " " << line.unit;
      out << "\n";
    }
  }
  return out.str();
}

namespace {

std::string quoted(const std::string& text) {
  std::string result = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      result += '\\';
      result += c;
    } else if (c == '\n') {
      result += "\\n";
    } else if (static_cast<unsigned char>(c) >= 0x20) {
      result += c;
    }
  }
  return result + "\"";
}

}  // namespace

std::string RunSummary::json() const {
  std::ostringstream out;
  out << "{\n";
  for (std::size_t s = 0; s < sections_.size(); ++s) {
    const auto& section = sections_[s];
    out << "  " << quoted(section.name) << ": {\n";
    for (std::size_t l = 0; l < section.lines.size(); ++l) {
      const auto& line = section.lines[l];
      const std::string key = line.unit.empty() ? line.key : line.key + " [" + line.unit + "]";
      out << "    " << quoted(key) << ": ";
      if (line.is_number && std::isfinite(line.number)) {
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "%.17g", line.number);
        out << buffer;
      } else {
        out << quoted(line.text);
      }
      out << (l + 1 < section.lines.size() ? ",\n" : "\n");
    }
    out << "  }" << (s + 1 < sections_.size() ? ",\n" : "\n");
  }
  out << "}\n";
  return out.str();
}

}  // namespace railfe
