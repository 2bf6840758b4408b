#include "physics/implicit/moving_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "framework/base/error.hpp"
#include "framework/base/numeric_csv.hpp"
#include "physics/elements/beam_interpolation.hpp"

namespace railfe {

BeamPath::BeamPath(std::vector<PathElement> elements) : elements_(std::move(elements)) {
  if (elements_.empty())
    throw RunError("a moving-contact path needs at least one beam element");
  starts_.push_back(0.0);
  for (const PathElement& e : elements_)
    starts_.push_back(starts_.back() + e.beam.length());
}

bool BeamPath::locate(double s, std::size_t& index, double& xi) const {
  const double tolerance = 1e-12 * length();
  if (!(s >= -tolerance && s <= length() + tolerance))
    return false;
  const auto after = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, s);
  index = static_cast<std::size_t>(after - starts_.begin()) - 1;
  xi = std::clamp((s - starts_[index]) / elements_[index].beam.length(), 0.0, 1.0);
  return true;
}

Irregularity::Irregularity(std::function<double(double)> vertical,
                           std::function<double(double)> lateral)
    : vertical_(std::move(vertical)), lateral_(std::move(lateral)) {}

Irregularity Irregularity::from_csv(const std::string& path) {
  const auto rows = read_numeric_csv(path);
  if (!rows)
    throw RunError("irregularity file '" + path + "' cannot be read");
  auto table = std::make_shared<std::array<std::vector<double>, 3>>();
  for (const NumericCsvRow& row : *rows) {
    const std::vector<double>& v = row.values;
    if (v.size() < 3 || ((*table)[0].size() > 0 && !(v[0] > (*table)[0].back())))
      throw RunError("irregularity file '" + path + "', line " + std::to_string(row.line) +
                     ": expected s, vertical, lateral with s increasing");
    for (int k = 0; k < 3; ++k)
      (*table)[k].push_back(v[k]);
  }
  if ((*table)[0].size() < 2)
    throw RunError("irregularity file '" + path + "' needs at least two rows");
  auto column = [table, path](int which) {
    return [table, path, which](double s) {
      const std::vector<double>& x = (*table)[0];
      if (s < x.front() || s > x.back()) {
        char text[160];
        std::snprintf(text, sizeof text, "' does not cover s = %.6g m (it spans %.6g to %.6g m)", s,
                      x.front(), x.back());
        throw RunError("irregularity file '" + path + text);
      }
      const std::size_t i = std::min<std::size_t>(
          static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), s) - x.begin()),
          x.size() - 1);
      const double w = (s - x[i - 1]) / (x[i] - x[i - 1]);
      return (1 - w) * (*table)[which][i - 1] + w * (*table)[which][i];
    };
  };
  return Irregularity(column(1), column(2));
}

MovingContacts::MovingContacts(BeamPath path, std::vector<MovingContactPoint> points)
    : path_(std::move(path)),
      points_(std::move(points)),
      engaged_(points_.size(), true),
      vertical_row_(points_.size(), -1),
      changed_at_(points_.size(), -std::numeric_limits<double>::infinity()),
      alternation_(points_.size()) {}

double MovingContacts::position(std::size_t index, double time) const {
  return points_[index].start + points_[index].speed * time;
}

void MovingContacts::locate(std::size_t index, double time, double s, std::size_t& element,
                            double& xi) const {
  if (!path_.locate(s, element, xi)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "moving contact '%s' leaves the structure at t = %.6g s: position %.6g m lies "
                  "outside its path [0, %.6g] m",
                  points_[index].name.c_str(), time, s, path_.length());
    throw RunError(text);
  }
}

void MovingContacts::add_row(long unknown, double s, int axis, double offset,
                             ConstraintRows& rows) const {
  std::size_t element;
  double xi;
  path_.locate(s, element, xi);
  const PathElement& e = path_.element(element);
  const Eigen::Matrix<double, 3, 12> n = beam_translation_interpolation(e.beam, xi);
  rows.start_row(offset);
  rows.add_entry(static_cast<std::size_t>(unknown), 1.0);
  for (int k = 0; k < 12; ++k)
    if (e.unknowns[k] >= 0)
      rows.add_entry(static_cast<std::size_t>(e.unknowns[k]), -n(axis, k));
}

void MovingContacts::rows_at(double time, ConstraintRows& rows) {
  for (std::size_t p = 0; p < points_.size(); ++p) {
    const MovingContactPoint& point = points_[p];
    const double s = position(p, time);
    std::size_t element;
    double xi;
    locate(p, time, s, element, xi);
    vertical_row_[p] = -1;
    if (!engaged_[p])
      continue;
    vertical_row_[p] = static_cast<long>(rows.size());
    add_row(point.vertical_unknown, s, 2, point.irregularity.vertical(s), rows);
    if (point.lateral_unknown >= 0)
      add_row(point.lateral_unknown, s, 1, point.irregularity.lateral(s), rows);
  }
}

double MovingContacts::surface(double s, int axis, const double* u) const {
  std::size_t element;
  double xi;
  path_.locate(s, element, xi);
  const PathElement& e = path_.element(element);
  const Eigen::Matrix<double, 3, 12> n = beam_translation_interpolation(e.beam, xi);
  double sum = 0;
  for (int k = 0; k < 12; ++k)
    if (e.unknowns[k] >= 0)
      sum += n(axis, k) * u[e.unknowns[k]];
  return sum;
}

bool MovingContacts::accept(double time, const double* u, const double* lambda) {
  bool changed = false;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    const MovingContactPoint& point = points_[p];
    const double s = position(p, time);
    if (changed_at_[p] == time)
      continue;  // one change per point and step: no release and engagement in a loop
    if (engaged_[p]) {
      // The force on the vehicle unknown is −λ: up (compression) while λ < 0.
      if (point.may_separate && lambda[vertical_row_[p]] > 0) {
        engaged_[p] = false;
        events_.push_back({point.name, time, s, true});
        changed_at_[p] = time;
        changed = true;
      }
    } else {
      const double gap =
          u[point.vertical_unknown] - surface(s, 2, u) - point.irregularity.vertical(s);
      if (gap < 0) {
        engaged_[p] = true;
        events_.push_back({point.name, time, s, false});
        changed_at_[p] = time;
        changed = true;
      }
    }
  }
  if (!changed)  // the step stands: follow each engaged point's step-to-step force mode
    for (std::size_t p = 0; p < points_.size(); ++p) {
      Alternation& m = alternation_[p];
      if (!engaged_[p] || changed_at_[p] == time) {
        m = Alternation();
        continue;
      }
      const double force = -lambda[vertical_row_[p]];
      if (m.seen == 2) {
        const double second = force - 2 * m.force[0] + m.force[1];
        // Alternating in sign and growing against the one two steps back: the mode.
        const bool grows = second * m.last < 0 && std::abs(second) > std::abs(m.before);
        m.run = grows ? m.run + 1 : 0;
        m.before = m.last;
        m.last = second;
        // 10 such steps in a row, above 1e-3 of the force (an alternation of 0.025 %).
        if (m.run >= 10 && std::abs(second) > 1e-3 * std::abs(force)) {
          restart_ = true;
          m = Alternation();
          continue;
        }
      }
      m.seen = std::min(m.seen + 1, 2);
      m.force[1] = m.force[0];
      m.force[0] = force;
    }
  return changed;
}

bool MovingContacts::needs_restart(double time, double spectral_radius) {
  bool restart = restart_ && spectral_radius >= 1 - 1e-12;
  restart_ = false;
  for (std::size_t p = 0; p < points_.size(); ++p)
    if (engaged_[p] && changed_at_[p] == time)
      restart = true;
  if (restart)  // the restart sets the multipliers afresh: follow the mode from there
    for (Alternation& m : alternation_)
      m = Alternation();
  return restart;
}

void MovingContacts::rates(double time, const double* u, const double* v, std::size_t n_rows,
                           double* velocity, double* acceleration) {
  const double h = 0.01;  // m: central differences over the contact patch's scale
  std::size_t row = 0;
  for (std::size_t p = 0; p < points_.size() && row < n_rows; ++p) {
    if (!engaged_[p])
      continue;
    const MovingContactPoint& point = points_[p];
    const double s = position(p, time);
    const double below = std::max(0.0, s - h), above = std::min(path_.length(), s + h);
    for (int axis : {2, 1}) {
      if (axis == 1 && point.lateral_unknown < 0)
        continue;
      const auto height = [&](double x) {
        return surface(x, axis, u) +
               (axis == 2 ? point.irregularity.vertical(x) : point.irregularity.lateral(x));
      };
      const double slope = (height(above) - height(below)) / (above - below);
      const double curvature = s - h >= 0 && s + h <= path_.length()
                                   ? (height(above) - 2 * height(s) + height(below)) / (h * h)
                                   : 0.0;
      const double slope_v = (surface(above, axis, v) - surface(below, axis, v)) / (above - below);
      velocity[row] = point.speed * slope;
      acceleration[row] = point.speed * point.speed * curvature + 2 * point.speed * slope_v;
      ++row;
    }
  }
}

std::vector<double> MovingContacts::contact_forces(const double* lambda) const {
  std::vector<double> forces(points_.size(), 0.0);
  for (std::size_t p = 0; p < points_.size(); ++p)
    if (vertical_row_[p] >= 0)
      forces[p] = -lambda[vertical_row_[p]];
  return forces;
}

void MovingContacts::add_point_load(double s, double force, double* f) const {
  std::size_t element;
  double xi;
  if (!path_.locate(s, element, xi))
    throw RunError("a moving load lies outside its path");
  const PathElement& e = path_.element(element);
  const Eigen::Matrix<double, 3, 12> n = beam_translation_interpolation(e.beam, xi);
  for (int k = 0; k < 12; ++k)
    if (e.unknowns[k] >= 0)
      f[e.unknowns[k]] += n(2, k) * force;
}

}  // namespace railfe
