#include "contact/geometry/profile_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "contact/geometry/profile_formats.hpp"
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

// The SIMPACK spline block's processing settings railfe does not apply (the point list is used
// as it stands); bounds are left out, since their neutral values are not zero.
bool is_ignored_processing(const std::string& key) {
  return key == "mirror.y" || key == "mirror.z" || key == "inversion" || key == "shift.y" ||
         key == "shift.z" || key == "rotate";
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
      const auto type = profile_number(value);
      if (!type || (*type != 0 && *type != 1))
        fail("type = " + value + " is not a profile type", "0 (rail) or 1 (wheel)");
      type_ = static_cast<int>(*type);
    } else if (block_ == "spline" && key == "units.len.f") {
      const auto factor = profile_number(value);
      if (!factor || *factor <= 0)
        fail("units.len.f = " + value + " is not a unit factor", "a positive number");
      unit_factor_ = *factor;
    } else if (block_ == "spline" && is_ignored_processing(key)) {
      const auto number = profile_number(value);
      if (!number || *number != 0)
        file_.warnings.push_back(path_ + ": line " + std::to_string(line_number_) + ": " + key +
                                 " = " + value +
                                 " is not applied: the points are taken as listed (use the deck's "
                                 "Wheel mirrored / Rail mirrored / Wheel running point instead)");
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
      const auto value = profile_number(token);
      if (!value)
        fail("'" + token + "' in the point list is not a number");
      values.push_back(*value);
    }
    if (values.size() < 2 || values.size() > 3)
      fail("a profile point needs y and z (and optionally a weight)", "y z [weight]");
    file_.points.push_back({values[0], values[1]});
    file_.lines.push_back(line_number_);
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

// A wheel's highest point (the flange tip) on +y and above its running point; a rail's lowest z
// (its top) inside, not at an end: what a mirrored or upside-down file gets wrong. \p type is
// what the profile is used as.
void check_orientation(const ProfileFile& file, ProfileType type) {
  const auto& p = file.points;
  auto higher = [](auto& a, auto& b) { return a[1] < b[1]; };
  if (type == ProfileType::wheel) {
    const auto tip = std::max_element(p.begin(), p.end(), higher);
    if ((*tip)[0] <= 0)
      throw_input_error(file.source, "",
                        "the wheel's flange (its highest point) lies at y <= 0: the profile is "
                        "mirrored or upside down",
                        "y from the running point towards the flange, z radially outwards");
    // The point nearest the running point (y = 0) must lie below the tip: z points outwards.
    const auto running = std::min_element(
        p.begin(), p.end(), [](auto& a, auto& b) { return std::abs(a[0]) < std::abs(b[0]); });
    const double rise = (*tip)[1] - (*running)[1];
    const double fall = (*running)[1] - (*std::min_element(p.begin(), p.end(), higher))[1];
    // Turned over (mirrored and upside down), the flange becomes a deep groove below the
    // running point and the tread's far end the highest point.
    if (!(rise > 0) || (fall > 0.010 && fall > rise))
      throw_input_error(file.source, "",
                        "the wheel is upside down: it rises " + std::to_string(rise * 1e3) +
                            " mm above its running point (y = 0) and falls " +
                            std::to_string(fall * 1e3) + " mm below it",
                        "z radially outwards, the flange tip the highest point, on +y");
  } else if (type == ProfileType::rail) {
    const auto top = std::min_element(p.begin(), p.end(), higher);
    if (top == p.begin() || top == p.end() - 1)
      throw_input_error(file.source, "",
                        "the rail's top (its least z) lies at an end of the profile: the profile "
                        "is upside down or not a rail head",
                        "z downwards, the head's top inside the profile");
  }
}

}  // namespace

ProfileFile read_profile_file(const std::string& path, const ProfileReadSettings& checks,
                              ProfileType role) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw_input_error(path, "", "is a directory, not a profile file",
                      "a SIMPACK .prr/.prw, MiniProf .ban/.whl or two-column .txt/.dat/.csv file");
  std::ifstream in(path);
  if (!in)
    throw_input_error(path, "", "profile file not found or not readable");
  const std::string extension = std::filesystem::path(path).extension().string();
  ProfileFile file;
  if (extension == ".prr" || extension == ".prw")
    file = ProfileParser(path).parse(in);
  else if (extension == ".ban" || extension == ".whl")
    file = read_miniprof(in, path, extension == ".whl" ? ProfileType::wheel : ProfileType::rail);
  else if (extension == ".txt" || extension == ".dat" || extension == ".csv")
    file = read_two_columns(in, path);
  else
    throw_input_error(path, "", "unknown profile format '" + extension + "'",
                      "SIMPACK .prr/.prw, MiniProf .ban/.whl, two-column .txt/.dat/.csv");
  for (auto& point : file.points)
    point[0] = (checks.mirror_y ? -1 : 1) * (point[0] - checks.y_origin);
  check_profile(file.points, file.lines, path, checks);
  // A wheel or rail profile is centimetres to decimetres wide: anything else is a file in
  // another length unit than it says (or than its format assumes).
  double low = file.points.front()[0], high = low;
  for (const auto& point : file.points) {
    low = std::min(low, point[0]);
    high = std::max(high, point[0]);
  }
  if (high - low < 0.001 || high - low > 0.5)
    throw_input_error(
        path, "",
        "the profile is " + std::to_string(high - low) + " m wide: its length unit is wrong",
        "a profile 1 mm to 500 mm wide (SIMPACK: units.len.f = 1000 for mm; "
        "MiniProf and two-column files are read in mm)");
  if (file.points.back()[0] < file.points.front()[0]) {
    std::reverse(file.points.begin(), file.points.end());
    std::reverse(file.lines.begin(), file.lines.end());
  }
  check_orientation(file, file.type == ProfileType::unspecified ? role : file.type);
  return file;
}

std::string shipped_profile(const std::string& file_name) {
  return std::string(RAILFE_PROFILE_DIRECTORY) + "/" + file_name;
}

std::shared_ptr<const ProfileCurve> shipped_curve(const std::string& file_name) {
  return spline_curve(read_profile_file(shipped_profile(file_name)).points);
}

}  // namespace railfe
