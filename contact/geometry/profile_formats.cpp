#include "contact/geometry/profile_formats.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

// The numbers of a point line, split at blanks, commas and semicolons; empty when a field is not
// a number (the field is left in \p bad).
std::vector<double> point_fields(std::string text, std::string& bad) {
  for (char& c : text)
    if (c == ',' || c == ';' || c == '\t')
      c = ' ';
  std::istringstream fields(text);
  std::vector<double> values;
  std::string token;
  while (fields >> token) {
    const auto value = profile_number(token);
    if (!value) {
      bad = token;
      return {};
    }
    values.push_back(*value);
  }
  return values;
}

std::string trimmed(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::optional<double> profile_number(const std::string& token) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(token.c_str(), &end);
  if (token.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
    return std::nullopt;
  return value;
}

ProfileFile read_miniprof(std::istream& in, const std::string& path, ProfileType type) {
  ProfileFile file;
  file.source = path;
  file.type = type;
  std::string line, columns;
  std::optional<double> declared;
  int number = 0;
  auto fail = [&](const std::string& problem, const std::string& allowed) {
    throw_input_error(path, "line " + std::to_string(number), problem, allowed);
  };
  while (std::getline(in, line)) {
    ++number;
    std::string text = trimmed(line);
    if (text.empty())
      continue;
    const std::size_t equals = text.find('=');
    if (file.points.empty() && equals != std::string::npos) {
      const std::string key = text.substr(0, equals), value = text.substr(equals + 1);
      if (key == "ColumnDef")
        columns = value;
      else if (key == "XYPoints" && !value.empty() && !(declared = profile_number(value)))
        fail("XYPoints = " + value + " is not a count", "a whole number");
      continue;
    }
    if (text.front() == '"')  // MiniProf's marker of an edited point
      text = trimmed(text.substr(1));
    std::string bad;
    const std::vector<double> values = point_fields(text, bad);
    if (!bad.empty())
      fail("'" + bad + "' in the point list is not a number", "X Y in mm");
    if (values.size() < 2)
      fail("a profile point needs X and Y", "X Y in mm");
    if (columns.rfind("X,Y", 0) != 0)
      fail("no ColumnDef=X,Y line before the points (found '" + columns + "')", "ColumnDef=X,Y...");
    file.points.push_back({-values[0] / 1000, values[1] / 1000});
    file.lines.push_back(number);
  }
  if (file.points.empty())
    throw_input_error(path, "", "lists no profile points", "a MiniProf .ban/.whl profile");
  if (declared && *declared != static_cast<double>(file.points.size()))
    throw_input_error(path, "XYPoints",
                      "declares " + std::to_string(static_cast<long>(*declared)) +
                          " points but the file lists " + std::to_string(file.points.size()),
                      "the count of the listed points (a truncated file?)");
  return file;
}

ProfileFile read_two_columns(std::istream& in, const std::string& path) {
  ProfileFile file;
  file.source = path;
  file.type = ProfileType::unspecified;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string text = trimmed(line.substr(0, line.find('#')));
    if (text.empty())
      continue;
    std::string bad;
    const std::vector<double> values = point_fields(text, bad);
    if (!bad.empty() || values.size() != 2)
      throw_input_error(path, "line " + std::to_string(number),
                        bad.empty() ? "needs exactly two numbers" : "'" + bad + "' is not a number",
                        "y z in mm, '#' for comments");
    file.points.push_back({values[0] / 1000, values[1] / 1000});
    file.lines.push_back(number);
  }
  if (file.points.empty())
    throw_input_error(path, "", "lists no profile points", "y z lines in mm");
  return file;
}

}  // namespace railfe
