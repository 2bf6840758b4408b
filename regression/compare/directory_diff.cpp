#include "regression/compare/directory_diff.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <vector>

#include "framework/mesh/mesh_readers.hpp"
#include "regression/compare/result_files.hpp"

namespace railfe {

namespace fs = std::filesystem;

namespace {

// The quantity a column or variable belongs to: the name up to its last '_', which holds the
// unit of a CSV column (force_N) or the component of an Exodus vector or tensor
// (displacement_x, stress_xy). Values are compared against the largest value of their quantity,
// so a component that is round-off around zero is judged against its siblings, not itself.
std::string quantity_of(const std::string& name, bool unit_suffix) {
  const auto underscore = name.rfind('_');
  if (underscore == std::string::npos)
    return name;
  return unit_suffix ? name.substr(underscore) : name.substr(0, underscore);
}

double largest_magnitude(const std::vector<double>& values) {
  double scale = 0;
  for (double value : values)
    scale = std::max(scale, std::abs(value));
  return scale;
}

// Compares two series of one variable whose quantity has magnitude \p scale; reports the worst
// mismatch.
bool compare_series(const std::vector<double>& a, const std::vector<double>& b, double scale,
                    const DiffTolerance& tolerance, const std::string& what, std::ostream& out) {
  if (a.size() != b.size()) {
    out << "  " << what << ": " << a.size() << " values vs " << b.size() << "\n";
    return false;
  }
  double worst = 0;
  std::size_t where = 0;
  bool ok = true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    // Undefined on both sides (a flange contact that never happens) is agreement.
    if (std::isnan(a[i]) && std::isnan(b[i]))
      continue;
    const double difference = std::abs(a[i] - b[i]);
    const double allowed =
        std::max(tolerance.relative * std::max(std::abs(b[i]), scale), tolerance.floor);
    if (!(difference <= allowed)) {
      ok = false;
      if (!(difference <= worst)) {
        worst = difference;
        where = i;
      }
    }
  }
  if (!ok) {
    out << "  " << what << ": differs at entry " << where << " (" << a[where] << " vs " << b[where]
        << ", scale " << scale << ")\n";
  }
  return ok;
}

bool compare_csv(const std::string& a_path, const std::string& b_path,
                 const DiffTolerance& tolerance, std::ostream& out) {
  const CsvTable a = read_csv(a_path), b = read_csv(b_path);
  if (a.columns != b.columns || a.rows.size() != b.rows.size()) {
    out << "  columns or row counts differ\n";
    return false;
  }
  bool ok = true;
  std::vector<std::vector<double>> x(a.columns.size()), y(a.columns.size());
  std::map<std::string, double> scale;
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    if (tolerance.ignores(a.columns[c]))
      continue;
    for (std::size_t r = 0; r < a.rows.size(); ++r) {
      double u = 0, v = 0;
      const bool numbers = parse_number(a.rows[r][c], u) && parse_number(b.rows[r][c], v);
      if (numbers) {
        x[c].push_back(u);
        y[c].push_back(v);
      } else if (a.rows[r][c] != b.rows[r][c]) {
        out << "  column " << a.columns[c] << " row " << r << ": '" << a.rows[r][c] << "' vs '"
            << b.rows[r][c] << "'\n";
        ok = false;
      }
    }
    double& s = scale[quantity_of(a.columns[c], true)];
    s = std::max(s, largest_magnitude(y[c]));
  }
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    ok = compare_series(x[c], y[c], scale[quantity_of(a.columns[c], true)], tolerance,
                        "column " + a.columns[c], out) &&
         ok;
  }
  return ok;
}

bool compare_exodus(const std::string& a_path, const std::string& b_path,
                    const DiffTolerance& tolerance, std::ostream& out) {
  const ExodusContents a = exodus_contents(a_path), b = exodus_contents(b_path);
  if (a.nodal_variables != b.nodal_variables || a.element_variables != b.element_variables ||
      a.n_steps != b.n_steps) {
    out << "  variables or output times differ\n";
    return false;
  }
  const Mesh a_mesh = read_exodus_mesh(a_path), b_mesh = read_exodus_mesh(b_path);
  bool ok = true;
  for (int step = 1; step <= a.n_steps; ++step) {
    for (bool nodal : {true, false}) {
      const auto& names = nodal ? a.nodal_variables : a.element_variables;
      std::vector<std::vector<double>> x, y;
      std::map<std::string, double> scale;
      for (const auto& name : names) {
        if (tolerance.ignores(name)) {
          x.emplace_back();
          y.emplace_back();
          continue;
        }
        x.push_back(read_exodus_field(a_path, a_mesh, name, nodal, step).values);
        y.push_back(read_exodus_field(b_path, b_mesh, name, nodal, step).values);
        double& s = scale[quantity_of(name, false)];
        s = std::max(s, largest_magnitude(y.back()));
      }
      for (std::size_t v = 0; v < names.size(); ++v) {
        ok = compare_series(x[v], y[v], scale[quantity_of(names[v], false)], tolerance,
                            names[v] + " at output " + std::to_string(step), out) &&
             ok;
      }
    }
  }
  return ok;
}

}  // namespace

bool compare_directories(const std::string& reference, const std::string& candidate,
                         const DiffTolerance& tolerance, std::ostream& out) {
  bool ok = true;
  int compared = 0;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(reference))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    const std::string extension = file.extension().string();
    if (extension != ".csv" && extension != ".exo")
      continue;
    const fs::path other = fs::path(candidate) / file.filename();
    if (!fs::exists(other)) {
      out << file.filename().string() << ": missing in " << candidate << "\n";
      ok = false;
      continue;
    }
    bool same = false;
    try {
      same = extension == ".csv" ? compare_csv(file.string(), other.string(), tolerance, out)
                                 : compare_exodus(file.string(), other.string(), tolerance, out);
    } catch (const std::exception& error) {
      out << "  " << error.what() << "\n";
    }
    out << file.filename().string() << ": " << (same ? "same" : "DIFFERENT") << "\n";
    ok = ok && same;
    ++compared;
  }
  if (compared == 0) {
    out << "no result files in " << reference << "\n";
    return false;
  }
  return ok;
}

}  // namespace railfe
