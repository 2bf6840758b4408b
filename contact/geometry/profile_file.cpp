#include "contact/geometry/profile_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "framework/base/error.hpp"

namespace railfe {

namespace {

// The line without its comment ('!' or '%' outside quotes) and surrounding blanks.
std::string strip(const std::string& line) {
  bool quoted = false;
  std::size_t end = line.size();
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'')
      quoted = !quoted;
    if (!quoted && (line[i] == '!' || line[i] == '%')) {
      end = i;
      break;
    }
  }
  const std::size_t first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || first >= end)
    return "";
  const std::size_t last = line.find_last_not_of(" \t\r", end - 1);
  return line.substr(first, last - first + 1);
}

std::optional<double> number(const std::string& token) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(token.c_str(), &end);
  if (token.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
    return std::nullopt;
  return value;
}

class ProfileParser {
 public:
  explicit ProfileParser(std::string path) : path_(std::move(path)) {}

  ProfileFile parse(std::istream& in) {
    std::string line;
    while (std::getline(in, line)) {
      ++line_number_;
      read_line(strip(line));
    }
    if (in_points_)
      fail("point.begin without point.end");
    if (!type_)
      fail_file("no profile type (header.begin ... type = 0 or 1 ... header.end)");
    if (!unit_factor_)
      fail_file("no length unit (units.len.f, e.g. 1000 for mm, in the spline block)");
    if (file_.points.empty())
      fail_file("lists no profile points between point.begin and point.end");
    file_.source = path_;
    file_.type = *type_ == 1 ? ProfileType::wheel : ProfileType::rail;
    for (auto& point : file_.points) {
      point[0] /= *unit_factor_;
      point[1] /= *unit_factor_;
    }
    if (file_.points.size() > 1 && file_.points[1][0] < file_.points[0][0])
      std::reverse(file_.points.begin(), file_.points.end());
    return file_;
  }

 private:
  void read_line(const std::string& text) {
    if (text.empty())
      return;
    if (text == "point.begin") {
      in_points_ = true;
    } else if (text == "point.end") {
      in_points_ = false;
    } else if (in_points_) {
      read_point(text);
    } else if (text == "header.begin" || text == "spline.begin") {
      block_ = text.substr(0, text.find('.'));
    } else if (text == "header.end" || text == "spline.end") {
      block_.clear();
    } else if (const std::size_t equals = text.find('='); equals != std::string::npos) {
      read_setting(strip(text.substr(0, equals)), strip(text.substr(equals + 1)));
    }
  }

  void read_setting(const std::string& key, const std::string& value) {
    if (block_ == "header" && key == "type") {
      const auto type = number(value);
      if (!type || (*type != 0 && *type != 1))
        fail("type = " + value + " is not a profile type", "0 (rail) or 1 (wheel)");
      type_ = static_cast<int>(*type);
    } else if (block_ == "spline" && key == "units.len.f") {
      const auto factor = number(value);
      if (!factor || *factor <= 0)
        fail("units.len.f = " + value + " is not a unit factor", "a positive number");
      unit_factor_ = *factor;
    } else if (block_ == "spline" && key == "comment") {
      file_.comment = value.size() >= 2 && value.front() == '\'' && value.back() == '\''
                          ? value.substr(1, value.size() - 2)
                          : value;
    }
  }

  void read_point(const std::string& text) {
    std::istringstream fields(text);
    std::vector<double> values;
    std::string token;
    while (fields >> token) {
      const auto value = number(token);
      if (!value)
        fail("'" + token + "' in the point list is not a number");
      values.push_back(*value);
    }
    if (values.size() < 2 || values.size() > 3)
      fail("a profile point needs y and z (and optionally a weight)", "y z [weight]");
    const auto& points = file_.points;
    if (!points.empty()) {
      const double step = values[0] - points.back()[0];
      if (step == 0)
        fail("y = " + token_of(values[0]) + " is listed twice", "strictly monotonic y");
      if (points.size() > 1 && (step > 0) != (points.back()[0] > points[points.size() - 2][0])) {
        fail("y = " + token_of(values[0]) + " breaks the order of the points before it",
             "strictly increasing or strictly decreasing y");
      }
    }
    file_.points.push_back({values[0], values[1]});
  }

  static std::string token_of(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
  }

  [[noreturn]] void fail(const std::string& problem, const std::string& allowed = "") const {
    throw_input_error(path_, "line " + std::to_string(line_number_), problem, allowed);
  }
  [[noreturn]] void fail_file(const std::string& problem) const {
    throw_input_error(path_, "", problem, "a SIMPACK .prw/.prr profile");
  }

  std::string path_;
  ProfileFile file_;
  std::string block_;
  bool in_points_ = false;
  int line_number_ = 0;
  std::optional<int> type_;
  std::optional<double> unit_factor_;
};

}  // namespace

ProfileFile read_profile_file(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw_input_error(path, "", "profile file not found or not readable");
  return ProfileParser(path).parse(in);
}

std::string shipped_profile(const std::string& file_name) {
  return std::string(RAILFE_PROFILE_DIRECTORY) + "/" + file_name;
}

}  // namespace railfe
