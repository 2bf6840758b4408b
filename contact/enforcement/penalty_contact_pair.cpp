#include "contact/enforcement/penalty_contact_pair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/search/bucket_search.hpp"
#include "contact/search/quad_projection.hpp"

namespace railfe {

namespace {

using Vector = std::array<double, 3>;

double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm(const Vector& a) {
  return std::sqrt(dot(a, a));
}

// Unit normal of the bilinear face through \p corners at (xi, eta): ∂x/∂ξ × ∂x/∂η.
Vector face_normal(const std::array<const double*, 4>& c, double xi, double eta) {
  Vector dxi{}, deta{};
  for (int d = 0; d < 3; ++d) {
    dxi[d] = 0.25 * ((1 - eta) * (c[1][d] - c[0][d]) + (1 + eta) * (c[2][d] - c[3][d]));
    deta[d] = 0.25 * ((1 - xi) * (c[3][d] - c[0][d]) + (1 + xi) * (c[2][d] - c[1][d]));
  }
  Vector n{dxi[1] * deta[2] - dxi[2] * deta[1], dxi[2] * deta[0] - dxi[0] * deta[2],
           dxi[0] * deta[1] - dxi[1] * deta[0]};
  const double length = norm(n);
  for (double& value : n)
    value /= length;
  return n;
}

// Whether another of the \p candidates faces holds both nodes \p a and \p b (their edge is shared).
bool edge_shared(const std::vector<std::array<int, 4>>& faces, const std::vector<int>& candidates,
                 int face, int a, int b) {
  for (int f : candidates) {
    if (f == face)
      continue;
    const auto& nodes = faces[f];
    if (std::find(nodes.begin(), nodes.end(), a) != nodes.end() &&
        std::find(nodes.begin(), nodes.end(), b) != nodes.end())
      return true;
  }
  return false;
}

// Whether the in-plane \p offset of a node from its nearest point (xi, eta) on the boundary of
// face \p face leaves the face by more than \p tolerance across an edge no candidate shares.
bool crosses_free_edge(const std::vector<std::array<int, 4>>& faces,
                       const std::vector<int>& candidates, int face,
                       const std::array<const double*, 4>& c, double xi, double eta,
                       const Vector& offset, double tolerance) {
  Vector dxi{}, deta{};
  for (int d = 0; d < 3; ++d) {
    dxi[d] = (1 - eta) * (c[1][d] - c[0][d]) + (1 + eta) * (c[2][d] - c[3][d]);
    deta[d] = (1 - xi) * (c[3][d] - c[0][d]) + (1 + xi) * (c[2][d] - c[1][d]);
  }
  const double across_xi = dot(offset, dxi) / norm(dxi);
  const double across_eta = dot(offset, deta) / norm(deta);
  const auto& n = faces[face];
  const double end = 1 - 1e-12;
  // Edges: ξ = +1 (nodes 1, 2), ξ = −1 (0, 3), η = +1 (3, 2), η = −1 (0, 1).
  return (xi >= end && across_xi > tolerance &&
          !edge_shared(faces, candidates, face, n[1], n[2])) ||
         (xi <= -end && -across_xi > tolerance &&
          !edge_shared(faces, candidates, face, n[0], n[3])) ||
         (eta >= end && across_eta > tolerance &&
          !edge_shared(faces, candidates, face, n[3], n[2])) ||
         (eta <= -end && -across_eta > tolerance &&
          !edge_shared(faces, candidates, face, n[0], n[1]));
}

// (mass, stiffness) of the springs of one side, one per cell of a 0.1 % grid in both: the cell's
// smallest mass and largest stiffness (a step from them lies below every member's), so that a
// mesh's repeated faces and nodes count once and a lone spring keeps its own values.
using MassStiffness = std::vector<std::pair<double, double>>;

MassStiffness distinct(const MassStiffness& springs) {
  const double grid = std::log(1.001);
  std::vector<std::pair<std::pair<long long, long long>, std::pair<double, double>>> cells;
  for (const auto& [mass, stiffness] : springs)
    cells.push_back({{std::llround(std::floor(std::log(mass) / grid)),
                      std::llround(std::floor(std::log(stiffness) / grid))},
                     {mass, stiffness}});
  std::sort(cells.begin(), cells.end());
  MassStiffness out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 && cells[i].first == cells[i - 1].first) {
      out.back().first = std::min(out.back().first, cells[i].second.first);
      out.back().second = std::max(out.back().second, cells[i].second.second);
    } else {
      out.push_back(cells[i].second);
    }
  }
  return out;
}

// The smallest 2√(m_r / k) over every slave node on every face: m_r the reduced mass of the two,
// k the face's stiffness or, with slave caps, the smaller of it and the node's.
double smallest_spring_step(const PenaltyPairGeometry& geometry) {
  MassStiffness faces, slaves;
  for (std::size_t f = 0; f < geometry.master_faces.size(); ++f) {
    double mass = 0;
    for (int node : geometry.master_faces[f])
      mass += 0.25 * geometry.mass[node];
    if (geometry.face_stiffness[f] > 0 && mass > 0)
      faces.emplace_back(mass, geometry.face_stiffness[f]);
  }
  for (std::size_t s = 0; s < geometry.slave_nodes.size(); ++s) {
    const double mass = geometry.mass[geometry.slave_nodes[s]];
    if (mass > 0)
      slaves.emplace_back(mass,
                          geometry.slave_stiffness.empty() ? 1e300 : geometry.slave_stiffness[s]);
  }
  if (geometry.slave_stiffness.empty() && !slaves.empty()) {
    // Without caps only the lightest slave node matters.
    slaves = {*std::min_element(slaves.begin(), slaves.end())};
  }
  faces = distinct(faces);
  slaves = distinct(slaves);
  double smallest = 1e300;  // of m_r / k
  for (const auto& [slave_mass, slave_stiffness] : slaves)
    for (const auto& [face_mass, face_stiffness] : faces)
      smallest = std::min(smallest, slave_mass * face_mass / (slave_mass + face_mass) /
                                        std::min(slave_stiffness, face_stiffness));
  return smallest < 1e300 ? 2 * std::sqrt(smallest) : 1e300;
}

}  // namespace

PenaltyContactPair::PenaltyContactPair(PenaltyPairGeometry geometry, PenaltyPairSettings settings)
    : geometry_(std::move(geometry)), settings_(std::move(settings)) {
  const auto n_faces = geometry_.master_faces.size();
  if (geometry_.face_stiffness.size() != n_faces ||
      geometry_.slave_area.size() != geometry_.slave_nodes.size() ||
      (!geometry_.slave_stiffness.empty() &&
       geometry_.slave_stiffness.size() != geometry_.slave_nodes.size()) ||
      geometry_.mass.size() != static_cast<std::size_t>(geometry_.n_surface_nodes))
    throw std::invalid_argument("contact pair '" + settings_.name + "': inconsistent sizes");
  if (settings_.search_interval < 1)
    throw std::invalid_argument("contact pair '" + settings_.name + "': search interval < 1");
  search_ = std::make_unique<BucketSearch>(geometry_.master_faces);
  slaves_.resize(geometry_.slave_nodes.size());
  stable_step_ = smallest_spring_step(geometry_);
  stable_step_ *= damped_step_factor(settings_.damping_fraction);
}

PenaltyContactPair::~PenaltyContactPair() = default;
PenaltyContactPair::PenaltyContactPair(PenaltyContactPair&&) noexcept = default;
PenaltyContactPair& PenaltyContactPair::operator=(PenaltyContactPair&&) noexcept = default;

void PenaltyContactPair::search(const double* x, double dt, double max_speed) {
  // Both surfaces move: their relative motion until the next rebuild is at most twice the
  // largest speed times the interval, and the margin catches what lies just beyond.
  const double motion = 2 * max_speed * dt * settings_.search_interval;
  search_->rebuild(x, settings_.search_margin + 2 * motion);
  capture_left_ = 2 * motion;
  steps_since_search_ = 0;
  window_reach_ = motion;
  window_slaves_.clear();
  window_nodes_.clear();
}

void PenaltyContactPair::add_to_window(int slave, double gap) {
  // Between searches the slave and every point of a master face move at most window_reach_
  // each (the capture runs out first), so its distance to the surface falls by at most twice
  // that: a slave further away cannot touch before the next search. The margin covers the
  // round-off of the projection.
  if (gap <= 2 * window_reach_ * (1 + 1e-6) + 1e-9)
    window_slaves_.push_back(slave);
}

void PenaltyContactPair::close_window(const double* x) {
  // The faces whose grown boxes the window's slaves can enter (each moves at most
  // window_reach_) are those overlapping their bounding box grown by it: candidates() returns
  // no other, and their nodes are all the window needs besides the slaves.
  window_nodes_.clear();
  if (window_slaves_.empty())
    return;
  const double inf = std::numeric_limits<double>::infinity();
  std::array<double, 6> box = {inf, inf, inf, -inf, -inf, -inf};
  for (int s : window_slaves_) {
    const double* position = x + 3 * geometry_.slave_nodes[s];
    window_nodes_.push_back(geometry_.slave_nodes[s]);
    for (int d = 0; d < 3; ++d) {
      box[d] = std::min(box[d], position[d] - window_reach_);
      box[3 + d] = std::max(box[3 + d], position[d] + window_reach_);
    }
  }
  search_->faces_overlapping(box, scratch_);
  for (int f : scratch_)
    window_nodes_.insert(window_nodes_.end(), geometry_.master_faces[f].begin(),
                         geometry_.master_faces[f].end());
  std::sort(window_nodes_.begin(), window_nodes_.end());
  window_nodes_.erase(std::unique(window_nodes_.begin(), window_nodes_.end()), window_nodes_.end());
}

bool PenaltyContactPair::search_due(double dt, double max_speed) const {
  return calls_ == 0 || steps_since_search_ >= settings_.search_interval ||
         2 * max_speed * dt > capture_left_;
}

bool PenaltyContactPair::window_suffices(double dt, double max_speed) const {
  return dt > 0 && window_valid_ && !search_due(dt, max_speed);
}

double PenaltyContactPair::contact_point(int slave, const double* x) {
  SlaveContact& contact = slaves_[slave];
  const double* position = x + 3 * geometry_.slave_nodes[slave];
  const ContactPoint found = find_contact_point(*search_, x, position, scratch_);
  contact.face = -1;
  if (found.face < 0)
    return std::numeric_limits<double>::infinity();
  if (!(found.projection.gap < 0))
    return found.projection.gap;
  const auto& nodes = geometry_.master_faces[found.face];
  const std::array<const double*, 4> corners = {x + 3 * nodes[0], x + 3 * nodes[1],
                                                x + 3 * nodes[2], x + 3 * nodes[3]};
  // A node behind the plane of a face whose nearest point is on the surface's rim is beside
  // the surface, not in it (a block past the end of a plate): it gets no force. Only an offset
  // across a free edge counts: across an edge shared with another face the node is still under
  // the surface (in the valley between two faces, also when it lies on the rim, as the nodes
  // of a one-layer plane-strain slab do).
  if (found.projection.on_boundary) {
    const Vector n = face_normal(corners, found.projection.xi, found.projection.eta);
    Vector offset{};
    for (int d = 0; d < 3; ++d)
      offset[d] = position[d] - found.projection.point[d];
    const double along = dot(offset, n);
    for (int d = 0; d < 3; ++d)
      offset[d] -= along * n[d];
    if (crosses_free_edge(geometry_.master_faces, scratch_, found.face, corners,
                          found.projection.xi, found.projection.eta, offset,
                          1e-3 * std::abs(found.projection.gap) + 1e-12))
      return found.projection.gap;
  }
  contact.face = found.face;
  contact.xi = found.projection.xi;
  contact.eta = found.projection.eta;
  contact.gap = found.projection.gap;
  contact.normal = found.projection.normal;
  contact.point = found.projection.point;
  return found.projection.gap;
}

void PenaltyContactPair::locate(const double* x) {
  search(x, 0, 0);
  for (std::size_t s = 0; s < slaves_.size(); ++s)
    contact_point(static_cast<int>(s), x);
  window_valid_ = false;  // no step: the motion until the next search is unknown
}

void PenaltyContactPair::evaluate(const double* x, const double* du, double dt, double max_speed,
                                  double* force) {
  const bool all_slaves = !window_suffices(dt, max_speed);
  const bool searching = search_due(dt, max_speed);
  if (searching)
    search(x, dt, max_speed);
  // Without a step the motion since the search is not tracked (statics): the window no longer
  // bounds it until the next search.
  window_valid_ = searching || (window_valid_ && dt > 0);
  capture_left_ -= 2 * max_speed * dt;
  ++steps_since_search_;
  ++calls_;

  const double dissipated = totals_.dissipated, frictional = totals_.frictional_work;
  totals_ = PenaltyPairTotals{};
  totals_.dissipated = dissipated;
  totals_.frictional_work = frictional;
  Vector weighted_normal{};
  // Ascending slaves either way, so forces add up in the same order.
  if (all_slaves) {
    for (std::size_t s = 0; s < slaves_.size(); ++s) {
      const double gap = evaluate_slave(s, x, du, dt, weighted_normal, force);
      if (searching)
        add_to_window(static_cast<int>(s), gap);
    }
    if (searching)
      close_window(x);
  } else {
    for (int s : window_slaves_)
      evaluate_slave(static_cast<std::size_t>(s), x, du, dt, weighted_normal, force);
  }
  const double length = norm(weighted_normal);
  if (length > 0)
    for (int d = 0; d < 3; ++d)
      totals_.normal[d] = weighted_normal[d] / length;
}

double PenaltyContactPair::evaluate_slave(std::size_t s, const double* x, const double* du,
                                          double dt, Vector& weighted_normal, double* force) {
  const bool friction = settings_.friction.kind != FrictionLaw::Kind::none;
  SlaveContact& contact = slaves_[s];
  const Vector previous_tangential = contact.tangential_force;
  const double gap = contact_point(static_cast<int>(s), x);
  if (contact.face < 0) {
    contact = SlaveContact{};
    return gap;
  }
  const int slave_node = geometry_.slave_nodes[s];
  const auto& face = geometry_.master_faces[contact.face];
  const std::array<double, 4> shape = quad_shape_functions(contact.xi, contact.eta);
  const double k = stiffness(s, contact.face);
  const Vector& n = contact.normal;

  // Relative increment of the slave over the master point during the step.
  Vector relative{};
  for (int d = 0; d < 3; ++d) {
    relative[d] = du[3 * slave_node + d];
    for (int a = 0; a < 4; ++a)
      relative[d] -= shape[a] * du[3 * face[a] + d];
  }
  const double approach = dot(relative, n);

  double normal_force = -k * contact.gap;
  if (settings_.damping_fraction > 0 && dt > 0) {
    double face_mass = 0;
    for (int a = 0; a < 4; ++a)
      face_mass += shape[a] * geometry_.mass[face[a]];
    const double slave_mass = geometry_.mass[slave_node];
    const double reduced = slave_mass * face_mass / (slave_mass + face_mass);
    const double damping = 2 * settings_.damping_fraction * std::sqrt(k * reduced);
    // No tension: the damper may only lower the force to zero.
    const double damper = std::max(-damping * approach / dt, -normal_force);
    normal_force += damper;
    totals_.dissipated += -damper * approach;
  }

  Vector tangential{};
  contact.slipping = false;
  contact.slip_velocity = {0, 0, 0};
  if (friction) {
    // The previous friction force turned into the new tangent plane, its length kept.
    Vector carried = previous_tangential;
    const double off_plane = dot(carried, n);
    const double length = norm(carried);
    for (int d = 0; d < 3; ++d)
      carried[d] -= off_plane * n[d];
    const double carried_length = norm(carried);
    if (carried_length > 0)
      for (double& value : carried)
        value *= length / carried_length;
    Vector increment{};
    for (int d = 0; d < 3; ++d)
      increment[d] = relative[d] - approach * n[d];
    const double slip_speed = dt > 0 ? norm(increment) / dt : 0.0;
    contact.coefficient = settings_.friction.coefficient(slip_speed);
    Vector trial{};
    for (int d = 0; d < 3; ++d)
      trial[d] = carried[d] - k * increment[d];
    const double trial_length = norm(trial);
    const double bound = contact.coefficient * normal_force;
    tangential = trial;
    if (trial_length > bound) {
      contact.slipping = true;
      const double slip = (trial_length - bound) / k;
      for (int d = 0; d < 3; ++d) {
        tangential[d] = trial[d] * bound / trial_length;
        if (dt > 0)
          contact.slip_velocity[d] = -trial[d] / trial_length * slip / dt;
      }
      totals_.dissipated += bound * slip;
      totals_.frictional_work += bound * slip;
    }
    totals_.friction_bound += bound;
  }
  contact.normal_force = normal_force;
  contact.tangential_force = tangential;

  Vector total{};
  for (int d = 0; d < 3; ++d)
    total[d] = normal_force * n[d] + tangential[d];
  for (int d = 0; d < 3; ++d) {
    force[3 * slave_node + d] += total[d];
    for (int a = 0; a < 4; ++a)
      force[3 * face[a] + d] -= shape[a] * total[d];
    totals_.force[d] += total[d];
    weighted_normal[d] += normal_force * n[d];
  }
  totals_.normal_force += normal_force;
  totals_.area += geometry_.slave_area[s];
  totals_.active += 1;
  totals_.slipping += contact.slipping ? 1 : 0;
  totals_.max_penetration = std::max(totals_.max_penetration, -contact.gap);
  totals_.stored_energy +=
      0.5 * k * contact.gap * contact.gap + (friction ? 0.5 * dot(tangential, tangential) / k : 0);
  return gap;
}

std::vector<double> PenaltyContactPair::state() const {
  std::vector<double> values = {totals_.dissipated, totals_.frictional_work};
  for (const SlaveContact& contact : slaves_)
    values.insert(values.end(), contact.tangential_force.begin(), contact.tangential_force.end());
  return values;
}

bool PenaltyContactPair::restore(const std::vector<double>& values) {
  if (values.size() != 2 + 3 * slaves_.size())
    return false;
  totals_.dissipated = values[0];
  totals_.frictional_work = values[1];
  for (std::size_t s = 0; s < slaves_.size(); ++s)
    std::copy_n(values.begin() + 2 + 3 * static_cast<std::ptrdiff_t>(s), 3,
                slaves_[s].tangential_force.begin());
  calls_ = 0;
  return true;
}

}  // namespace railfe
