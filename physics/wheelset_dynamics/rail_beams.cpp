#include "physics/wheelset_dynamics/rail_beams.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "framework/base/error.hpp"
#include "physics/elements/beam_interpolation.hpp"

namespace railfe {

namespace {

constexpr TrackSide kContactSide[n_wheelset_contacts] = {TrackSide::right, TrackSide::right,
                                                         TrackSide::left, TrackSide::left};

}  // namespace

std::array<double, 2> rail_top(const WheelRailGeometry& geometry, TrackSide side) {
  const ProfileCurve& rail = geometry.rail(side);
  std::array<double, 2> top{0, std::numeric_limits<double>::infinity()};
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    const double s = rail.begin() + (rail.end() - rail.begin()) * i / n;
    const Vec2 point = rail.at(s).p;
    if (point.z < top[1])
      top = {point.y, point.z};
  }
  return top;
}

RailBeams::RailBeams(const RailBeamLayout& layout, std::array<double, 2> axis_y,
                     std::array<double, 2> axis_z)
    : axis_y_(axis_y), axis_z_(axis_z) {
  const double spans = layout.length / layout.seat_spacing;
  const long n_spans = std::lround(spans);
  if (n_spans < 1 || std::abs(spans - n_spans) > 1e-9 * spans)
    throw std::invalid_argument("the rails' length is not a whole number of seat spacings");
  if (layout.elements_per_span < 1)
    throw std::invalid_argument("a span needs at least one element");
  for (double k : layout.seat_stiffness)
    if (!(k > 0))
      throw std::invalid_argument(
          "every seat stiffness (x, y, z, roll) must be positive, else the rails are free to "
          "move");
  const int n_elements = static_cast<int>(n_spans) * layout.elements_per_span;
  const int nodes_per_rail = n_elements + 1;
  const double element_length = layout.length / n_elements;
  n_unknowns_ = static_cast<std::size_t>(2 * 6 * nodes_per_rail);
  std::vector<Eigen::Triplet<double>> k, m, c;
  const Eigen::Vector3d lateral(0, 1, 0);
  for (int rail = 0; rail < 2; ++rail) {
    const long first = 6L * nodes_per_rail * rail;
    std::vector<PathElement> path;
    for (int e = 0; e < n_elements; ++e) {
      const Eigen::Vector3d a(e * element_length, axis_y[rail], axis_z[rail]);
      const Eigen::Vector3d b((e + 1) * element_length, axis_y[rail], axis_z[rail]);
      const BeamElement beam(a, b, lateral, layout.material, layout.section, true);
      const Matrix12 ke = beam.stiffness(), me = beam.mass(layout.mass);
      std::array<long, 12> dofs;
      for (int i = 0; i < 12; ++i)
        dofs[i] = first + 6L * e + i;
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) {
          k.emplace_back(dofs[i], dofs[j], ke(i, j));
          if (me(i, j) != 0)
            m.emplace_back(dofs[i], dofs[j], me(i, j));
        }
      path.push_back({beam, dofs});
    }
    paths_.emplace_back(std::move(path));
    // Seats at every span's ends: along x, y, z and about x.
    for (long span = 0; span <= n_spans; ++span) {
      const long node = first + 6L * span * layout.elements_per_span;
      for (int d = 0; d < 4; ++d) {
        k.emplace_back(node + d, node + d, layout.seat_stiffness[d]);
        if (layout.seat_damping[d] > 0)
          c.emplace_back(node + d, node + d, layout.seat_damping[d]);
      }
    }
  }
  set_matrices(k, m, c);
}

RailBeams::RailBeams(const RailSpringLayout& layout, std::array<double, 2> axis_y,
                     std::array<double, 2> axis_z)
    : axis_y_(axis_y), axis_z_(axis_z) {
  for (double k : layout.stiffness)
    if (!(k > 0))
      throw std::invalid_argument(
          "every spring stiffness (y, z, roll) must be positive, else the rails are free to "
          "move");
  if (layout.mass < 0 || layout.roll_inertia < 0)
    throw std::invalid_argument("the rails' mass and roll inertia must not be negative");
  n_unknowns_ = 6;
  const auto n = static_cast<Eigen::Index>(n_unknowns_);
  stiffness_.resize(n, n);
  mass_.resize(n, n);
  damping_.resize(n, n);
  const double masses[3] = {layout.mass, layout.mass, layout.roll_inertia};
  for (int rail = 0; rail < 2; ++rail)
    for (int c = 0; c < 3; ++c) {
      const Eigen::Index i = 3 * rail + c;
      stiffness_.insert(i, i) = layout.stiffness[c];
      if (masses[c] > 0)
        mass_.insert(i, i) = masses[c];
      if (layout.damping[c] > 0)
        damping_.insert(i, i) = layout.damping[c];
    }
}

RailBeams::RailBeams(const GirderLayout& layout, double axis_z)
    : axis_y_{0, 0}, axis_z_{axis_z, axis_z}, origin_(layout.start), rigid_beyond_(true) {
  if (layout.spans < 1 || !(layout.span > 0) || layout.elements_per_span < 1)
    throw std::invalid_argument("the structure needs a span, of positive length and elements");
  for (double k : layout.bearing_stiffness)
    if (!(k > 0))
      throw std::invalid_argument(
          "every bearing stiffness (x, y, z, roll) must be positive, else a girder is free to "
          "move");
  const int per_span = layout.elements_per_span;
  const int n_elements = layout.spans * per_span;
  const double element_length = layout.span / per_span;
  // One beam line, continuous over the piers: the rails run on without a step or kink at a
  // pier. The abutments hold both ends along x, y, z and in roll, so the track is continuous
  // where it leaves the rigid ground.
  std::vector<long> unknown(6 * static_cast<std::size_t>(n_elements + 1));
  long next = 0;
  for (int node = 0; node <= n_elements; ++node)
    for (int d = 0; d < 6; ++d)
      unknown[6 * node + d] = (node == 0 || node == n_elements) && d < 4 ? -1 : next++;
  n_unknowns_ = static_cast<std::size_t>(next);
  std::vector<Eigen::Triplet<double>> k, m, c;
  const Eigen::Vector3d lateral(0, 1, 0);
  std::vector<PathElement> path;
  for (int e = 0; e < n_elements; ++e) {
    const double x = e * element_length;
    const BeamElement beam(Eigen::Vector3d(x, 0, axis_z),
                           Eigen::Vector3d(x + element_length, 0, axis_z), lateral, layout.material,
                           layout.section, true);
    const Matrix12 ke = beam.stiffness(), me = beam.mass(BeamMass::consistent);
    std::array<long, 12> dofs;
    for (int i = 0; i < 12; ++i)
      dofs[i] = unknown[6 * e + i];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) {
        if (dofs[i] < 0 || dofs[j] < 0)
          continue;
        k.emplace_back(dofs[i], dofs[j], ke(i, j));
        m.emplace_back(dofs[i], dofs[j], me(i, j));
        const double rayleigh = layout.rayleigh[0] * me(i, j) + layout.rayleigh[1] * ke(i, j);
        if (rayleigh != 0)
          c.emplace_back(dofs[i], dofs[j], rayleigh);
      }
    path.push_back({beam, dofs});
  }
  for (int pier = 1; pier < layout.spans; ++pier)
    for (int d = 0; d < 4; ++d) {
      const long dof = unknown[6 * pier * per_span + d];
      k.emplace_back(dof, dof, layout.bearing_stiffness[d]);
      if (layout.bearing_damping[d] > 0)
        c.emplace_back(dof, dof, layout.bearing_damping[d]);
    }
  paths_.emplace_back(path);
  paths_.emplace_back(std::move(path));
  set_matrices(k, m, c);
}

void RailBeams::set_matrices(const std::vector<Eigen::Triplet<double>>& k,
                             const std::vector<Eigen::Triplet<double>>& m,
                             const std::vector<Eigen::Triplet<double>>& c) {
  const auto n = static_cast<Eigen::Index>(n_unknowns_);
  stiffness_.resize(n, n);
  mass_.resize(n, n);
  damping_.resize(n, n);
  stiffness_.setFromTriplets(k.begin(), k.end());
  mass_.setFromTriplets(m.begin(), m.end());
  damping_.setFromTriplets(c.begin(), c.end());
}

BeamRails::BeamRails(const RailBeams& rails, std::size_t vehicle_offset,
                     std::function<double(double)> lateral, std::function<double(double)> vertical,
                     double start, double speed, std::vector<RailedWheelset> wheelsets)
    : rails_(rails),
      offset_(vehicle_offset),
      lateral_(std::move(lateral)),
      vertical_(std::move(vertical)),
      start_(start),
      speed_(speed),
      wheelsets_(std::move(wheelsets)),
      levers_(wheelsets_.size()) {}

void BeamRails::set_levers(const std::array<ContactState, n_wheelset_contacts>& states,
                           int wheelset) {
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    const auto axis = rails_.axis(kContactSide[k]);
    // θ_x e_x × (P − A) = θ_x (0, A_z − P_z, P_y − A_y).
    levers_[wheelset][k] = {axis[1] - states[k].point.rail_point.z,
                            states[k].point.rail_point.y - axis[0]};
  }
}

std::array<double, 2> BeamRails::offsets(double time, double position) const {
  const double s = start_ + position + speed_ * time;
  return {lateral_ ? lateral_(s) : 0.0, vertical_ ? vertical_(s) : 0.0};
}

void BeamRails::rows_at(double time, ConstraintRows& rows) {
  for (std::size_t w = 0; w < wheelsets_.size(); ++w) {
    const std::size_t nodes = offset_ + wheelsets_[w].nodes;
    const auto& levers = levers_[w];
    const double s = start_ + wheelsets_[w].position + speed_ * time;
    const auto offset = offsets(time, wheelsets_[w].position);
    if (rails_.on_springs()) {
      // The rails move with the wheelset: no x, and y, z and roll are the rails' own unknowns.
      for (int k = 0; k < n_wheelset_contacts; ++k)
        for (int i = 0; i < 3; ++i) {
          rows.start_row(i == 0 ? 0.0 : offset[i - 1]);
          rows.add_entry(nodes + 3 * k + i, 1.0);
          if (i == 0)
            continue;
          rows.add_entry(static_cast<std::size_t>(rails_.point_unknown(kContactSide[k], i - 1)),
                         -1.0);
          rows.add_entry(static_cast<std::size_t>(rails_.point_unknown(kContactSide[k], 2)),
                         -levers[k][i - 1]);
        }
      continue;
    }
    for (int k = 0; k < n_wheelset_contacts; ++k) {
      const BeamPath& path = rails_.path(kContactSide[k]);
      std::size_t element;
      double xi;
      const bool on_path = path.locate(s - rails_.origin(), element, xi);
      if (!on_path && !rails_.rigid_beyond()) {
        std::ostringstream message;
        message << "the wheelset has reached s = " << s << " m at t = " << time
                << " s, off the rails' beams (0 to " << path.length()
                << " m): lengthen Rails/Length or shorten the run";
        throw RunError(message.str());
      }
      for (int i = 0; i < 3; ++i) {
        rows.start_row(i == 0 ? 0.0 : offset[i - 1]);
        rows.add_entry(nodes + 3 * k + i, 1.0);
        if (!on_path)
          continue;  // rigid track before and after the structure
        const PathElement& piece = path.element(element);
        const auto N = beam_translation_interpolation(piece.beam, xi);
        // The roll, linear along the element (torsion), moves the point by its lever.
        const double lever = i == 0 ? 0.0 : levers[k][i - 1];
        for (int j = 0; j < 12; ++j) {
          if (piece.unknowns[j] < 0)
            continue;  // held by an abutment
          double value = N(i, j);
          if (j == 3)
            value += lever * (1 - xi);
          else if (j == 9)
            value += lever * xi;
          rows.add_entry(static_cast<std::size_t>(piece.unknowns[j]), -value);
        }
      }
    }
  }
}

void BeamRails::rates(double time, const double* u, const double* v, std::size_t n_rows,
                      double* velocity, double* acceleration) {
  rates_by_differences(*this, time, 1e-3 / std::max(speed_, 1e-9), u, v, n_rows, velocity,
                       acceleration);
}

std::array<double, 3 * n_wheelset_contacts> BeamRails::rail_displacements(double time,
                                                                          const double* u) {
  ConstraintRows rows;
  rows_at(time, rows);
  std::array<double, 3 * n_wheelset_contacts> d{};
  for (std::size_t r = 0; r < d.size(); ++r)
    for (std::size_t e = rows.offsets[r]; e < rows.offsets[r + 1]; ++e)
      if (rows.columns[e] < offset_)
        d[r] -= rows.values[e] * u[rows.columns[e]];
  return d;
}

}  // namespace railfe
