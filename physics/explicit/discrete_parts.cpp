#include "physics/explicit/discrete_parts.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "framework/base/error.hpp"
#include "framework/mesh/nearest_nodes.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/explicit/nodal_conditions.hpp"

namespace railfe {

namespace {

Eigen::Vector3d vector_of(const std::array<double, 3>& values) {
  return {values[0], values[1], values[2]};
}

// Values per body in state(): U, V, A, ω, ω̇, previous own force and moment, ΔU, R, work; then
// L and M (absent from checkpoints written before the momentum scheme).
constexpr std::size_t kOldStateSize = 8 * 3 + 9 + 1;
constexpr std::size_t kStateSize = kOldStateSize + 6;

// The largest 1/m_a + n_b/m_b over the pairs of a spring between node sets, n_b the springs
// that meet at node b: a node b with n_b equal springs from nodes a has the pairs' frequency
// ω² = k (1/m_a + n_b/m_b). The nodes' masses may live on other ranks: summed from their owners.
double paired_inverse_mass(const MeshPartition& partition, const std::vector<double>& nodal_mass,
                           const std::vector<std::pair<GlobalIndex, GlobalIndex>>& pairs) {
  std::vector<double> masses(2 * pairs.size(), 0.0);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    for (int end = 0; end < 2; ++end) {
      const LocalIndex local = partition.local_node(end == 0 ? pairs[p].first : pairs[p].second);
      if (local >= 0 && local < partition.n_owned_nodes())
        masses[2 * p + end] = nodal_mass[local];
    }
  }
  partition.comm().sum_in_place(masses);
  std::map<GlobalIndex, int> springs_at;
  for (const auto& pair : pairs)
    ++springs_at[pair.second];
  double largest = 0;
  for (std::size_t p = 0; p < pairs.size(); ++p)
    largest =
        std::max(largest, 1 / masses[2 * p] + springs_at[pairs[p].second] / masses[2 * p + 1]);
  return largest;
}

}  // namespace

DiscreteParts::DiscreteParts(const ExplicitSettings& settings, const MeshPartition& partition,
                             const std::vector<double>& nodal_mass, const std::string& deck,
                             const std::string& path)
    : comm_(partition.comm()),
      body_of_node_(partition.n_owned_nodes(), -1),
      moments_(settings.moments) {
  const Communicator& comm = partition.comm();
  for (const RigidBodySpec& spec : settings.bodies) {
    const std::string where = path + "/Rigid bodies/" + spec.name;
    RigidBody body;
    body.name = spec.name;
    body.extra_mass = spec.mass;
    body.fixed = spec.fixed;
    body.weighs = spec.weighs;
    if (!spec.node_set.empty())
      body.nodes = owned_set_nodes(partition, spec.node_set);
    // Mass and centroid of the carried nodes, summed over ranks.
    std::vector<double> sums(4, 0.0);
    for (LocalIndex node : body.nodes) {
      const double m = nodal_mass[node];
      sums[0] += m;
      for (int d = 0; d < 3; ++d)
        sums[1 + d] += m * partition.coordinates(node)[d];
      if (body_of_node_[node] >= 0)
        throw_input_error(deck, where + "/Node set",
                          "shares nodes with body '" + bodies_[body_of_node_[node]].name + "'",
                          "node sets that do not overlap");
      body_of_node_[node] = static_cast<int>(bodies_.size());
    }
    comm.sum_in_place(sums);
    body.mass = spec.mass + sums[0];
    body.reference = spec.reference ? vector_of(*spec.reference)
                                    : Eigen::Vector3d(sums[1], sums[2], sums[3]) / sums[0];
    std::vector<double> inertia(6, 0.0);
    for (LocalIndex node : body.nodes) {
      const Eigen::Vector3d r =
          Eigen::Vector3d(partition.coordinates(node)[0], partition.coordinates(node)[1],
                          partition.coordinates(node)[2]) -
          body.reference;
      body.offsets.push_back(r);
      const Eigen::Matrix3d J =
          nodal_mass[node] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
      const double entries[6] = {J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(1, 2), J(0, 2)};
      for (int k = 0; k < 6; ++k)
        inertia[k] += entries[k];
    }
    comm.sum_in_place(inertia);
    body.inertia << inertia[0], inertia[3], inertia[5], inertia[3], inertia[1], inertia[4],
        inertia[5], inertia[4], inertia[2];
    body.inertia += vector_of(spec.inertia).asDiagonal();
    body.rotates = !(spec.node_set.empty() && spec.inertia == std::array<double, 3>{});
    if (body.rotates) {
      // A free rotation needs inertia about every free axis.
      const Eigen::Vector3d principal =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(body.inertia).eigenvalues();
      const bool all_locked = body.fixed[3] && body.fixed[4] && body.fixed[5];
      if (!all_locked && principal.minCoeff() <= 1e-12 * std::max(principal.maxCoeff(), 1e-300))
        throw_input_error(deck, where + "/Inertia",
                          "leaves the body without inertia about some axis (its nodes lie on a "
                          "line or point)",
                          "Inertia > 0 about that axis, or Fixed rotations");
    }
    body.velocity = vector_of(spec.velocity);
    body.angular_velocity =
        body.rotates ? vector_of(spec.angular_velocity) : Eigen::Vector3d::Zero();
    for (int d = 0; d < 3; ++d) {
      if (body.fixed[d])
        body.velocity[d] = 0;
      if (body.fixed[3 + d])
        body.angular_velocity[d] = 0;
    }
    for (int d = 0; d < 3; ++d) {
      if (spec.motion[d].empty())
        continue;
      body.motion[d] = static_cast<int>(motion_functions_.size());
      motion_functions_.emplace_back(spec.motion[d], deck,
                                     where + "/Motion " + std::string(1, "xyz"[d]));
      motion_start_.push_back(motion_functions_.back()(0, 0, 0, 0));
      body.velocity[d] = motion_at(body.motion[d], 0, 0)[1];
    }
    const std::array<bool, 3> locked =
        body.rotates ? std::array<bool, 3>{body.fixed[3], body.fixed[4], body.fixed[5]}
                     : std::array<bool, 3>{true, true, true};
    rotations_.emplace_back(body.inertia, locked);
    body.angular_momentum = rotations_.back().momentum(body.rotation, body.angular_velocity);
    bodies_.push_back(std::move(body));
  }

  auto body_index = [&](const std::string& name) {
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      if (bodies_[b].name == name)
        return static_cast<int>(b);
    return -1;
  };
  for (const SpringSpec& spec : settings.springs) {
    Spring spring;
    spring.name = spec.name;
    auto make_end = [&](const std::string& name) {
      SpringEnd end;
      if (name == "ground")
        return end;
      end.body = body_index(name);
      if (end.body < 0) {
        end.nodes = owned_set_nodes(partition, name);
        end.share = 1.0 / static_cast<double>(comm.sum(static_cast<long long>(end.nodes.size())));
      }
      return end;
    };
    spring.a = make_end(spec.end_a);
    spring.b = make_end(spec.end_b);
    if (spring.a.body >= 0 && spring.b.share > 0)
      std::swap(spring.a, spring.b);
    std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;  // between two node sets
    if (spring.a.share > 0 && spring.b.share > 0)
      pairs = nearest_node_pairs(partition, spec.end_a, spec.end_b, deck,
                                 path + "/Springs/" + spec.name + "/End B");
    // Critical step of the spring on the masses it joins (central difference with damping).
    auto end_mass = [&](const SpringEnd& end) {
      if (end.body >= 0)
        return bodies_[end.body].mass;
      if (end.share == 0)
        return 1e300;
      double lightest = 1e300;
      for (LocalIndex node : end.nodes)
        lightest = std::min(lightest, nodal_mass[node]);
      return comm.min(lightest);
    };
    // A node-set end shares the spring equally among its nodes: each node gets its share.
    const double share = spring.a.share > 0 ? spring.a.share : 1.0;
    for (int d = 0; d < 3; ++d) {
      spring.element.stiffness[d] = share * spec.stiffness[d];
      spring.element.damping[d] = share * spec.damping[d];
    }
    double inverse_mass = 1 / end_mass(spring.a) + 1 / end_mass(spring.b);
    if (!pairs.empty())
      inverse_mass = paired_inverse_mass(partition, nodal_mass, pairs);
    spring.pairs = std::move(pairs);
    for (int d = 0; d < 3; ++d) {
      const double k = spring.element.stiffness[d], c = spring.element.damping[d];
      if (k <= 0)
        continue;
      const double omega = std::sqrt(k * inverse_mass);
      const double xi = 0.5 * c * inverse_mass / omega;
      stable_step_ = std::min(stable_step_, 2 / omega * (std::sqrt(1 + xi * xi) - xi));
    }
    springs_.push_back(std::move(spring));
  }
  number_gathered_nodes(partition);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  previous_own_force_.assign(bodies_.size(), zero);
  previous_own_moment_.assign(bodies_.size(), zero);
  body_step_.assign(bodies_.size(), zero);
  for (const BodyMoment& moment : moments_)
    moment_functions_.emplace_back(moment.function, deck, path + "/Moments/" + moment.name);
}

void DiscreteParts::initialise_nodes(NodalArrays& nodes) const {
  for (const RigidBody& body : bodies_) {
    for (std::size_t i = 0; i < body.nodes.size(); ++i) {
      const Eigen::Vector3d r = body.rotation * body.offsets[i];
      const Eigen::Vector3d v = body.velocity + body.angular_velocity.cross(r);
      for (int d = 0; d < 3; ++d)
        nodes.v[3 * body.nodes[i] + d] = v[d];
    }
  }
}

void DiscreteParts::predict(double dt, NodalArrays& nodes) {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    RigidBody& body = bodies_[b];
    Eigen::Vector3d step = dt * body.velocity + 0.5 * dt * dt * body.acceleration;
    body.velocity += 0.5 * dt * body.acceleration;
    for (int d = 0; d < 3; ++d) {
      if (body.motion[d] < 0)
        continue;
      const auto next = motion_at(body.motion[d], time_ + dt, dt);
      step[d] =
          body.motion_origin[d] + next[0] - motion_start_[body.motion[d]] - body.displacement[d];
      body.velocity[d] = next[1];
    }
    body.displacement += step;
    body_step_[b] = step;
    if (body.rotates) {
      // Kick with the last step's moment, then the free rotation; the nodes move with the
      // angular velocity of the kicked momentum at the new orientation.
      const RigidRotation& rotation = rotations_[b];
      const Eigen::Vector3d before = body.angular_velocity;
      rotation.kick(0.5 * dt * body.moment, body.angular_momentum);
      const Eigen::Vector3d after = rotation.angular_velocity(body.rotation, body.angular_momentum);
      // The kick changes the kinetic energy by ½Δt M·½(ω_before + ω_after) exactly.
      body.work += 0.25 * dt * previous_own_moment_[b].dot(before + after);
      rotation.drift(dt, body.angular_momentum, body.rotation);
      body.angular_velocity = rotation.angular_velocity(body.rotation, body.angular_momentum);
    }
    body.force.setZero();
    body.moment.setZero();
    for (std::size_t i = 0; i < body.nodes.size(); ++i) {
      const LocalIndex node = body.nodes[i];
      const Eigen::Vector3d r = body.rotation * body.offsets[i];
      const Eigen::Vector3d u = body.displacement + r - body.offsets[i];
      const Eigen::Vector3d v = body.velocity + body.angular_velocity.cross(r);
      for (int d = 0; d < 3; ++d) {
        // The predictor has already advanced u by du: the step is measured from u_n.
        const double previous = nodes.u[3 * node + d] - nodes.du[3 * node + d];
        nodes.du[3 * node + d] = u[d] - previous;
        nodes.u[3 * node + d] = u[d];
        nodes.v[3 * node + d] = v[d];
      }
    }
  }
}

void DiscreteParts::number_gathered_nodes(const MeshPartition& partition) {
  for (const Spring& spring : springs_)
    for (const auto& [a, b] : spring.pairs)
      gathered_nodes_.insert(gathered_nodes_.end(), {a, b});
  std::sort(gathered_nodes_.begin(), gathered_nodes_.end());
  gathered_nodes_.erase(std::unique(gathered_nodes_.begin(), gathered_nodes_.end()),
                        gathered_nodes_.end());
  for (GlobalIndex node : gathered_nodes_) {
    const LocalIndex local = partition.local_node(node);
    gathered_owned_.push_back(local >= 0 && local < partition.n_owned_nodes() ? local : -1);
  }
  auto slot = [&](GlobalIndex node) {
    return static_cast<int>(std::lower_bound(gathered_nodes_.begin(), gathered_nodes_.end(), node) -
                            gathered_nodes_.begin());
  };
  for (Spring& spring : springs_)
    for (const auto& [a, b] : spring.pairs)
      spring.pair_slots.push_back({slot(a), slot(b)});
  gathered_.assign(6 * gathered_nodes_.size(), 0.0);
}

void DiscreteParts::gather_paired_motion(const NodalArrays& nodes) {
  std::fill(gathered_.begin(), gathered_.end(), 0.0);
  for (std::size_t i = 0; i < gathered_nodes_.size(); ++i) {
    const LocalIndex node = gathered_owned_[i];
    if (node < 0)
      continue;
    for (int d = 0; d < 3; ++d) {
      gathered_[6 * i + d] = nodes.u[3 * node + d];
      gathered_[6 * i + 3 + d] = nodes.v[3 * node + d];
    }
  }
  if (comm_.n_ranks() > 1)
    comm_.sum_in_place(gathered_);
}

double DiscreteParts::add_paired_spring_forces(const Spring& spring, const NodalArrays& nodes,
                                               double& energy) {
  double power = 0;
  for (const auto& [a, b] : spring.pair_slots) {
    const Eigen::Map<const Eigen::Vector3d> u_a(&gathered_[6 * a]), v_a(&gathered_[6 * a + 3]),
        u_b(&gathered_[6 * b]), v_b(&gathered_[6 * b + 3]);
    const Eigen::Vector3d stretch = u_b - u_a, rate = v_b - v_a;
    const Eigen::Vector3d force = spring_translational_force(spring.element, stretch, rate);
    if (const LocalIndex node = gathered_owned_[a]; node >= 0) {
      for (int d = 0; d < 3; ++d)
        nodes.residual[3 * node + d] += force[d];
      // Counted once, by the rank that owns the A node.
      energy += spring_translational_energy(spring.element, stretch);
      power += spring_translational_power(spring.element, rate);
    }
    if (const LocalIndex node = gathered_owned_[b]; node >= 0)
      for (int d = 0; d < 3; ++d)
        nodes.residual[3 * node + d] -= force[d];
  }
  return power;
}

double DiscreteParts::add_spring_forces(const NodalArrays& nodes, double& energy) {
  double power = 0;
  if (!gathered_nodes_.empty())
    gather_paired_motion(nodes);
  for (const Spring& spring : springs_) {
    if (!spring.pair_slots.empty()) {
      power += add_paired_spring_forces(spring, nodes, energy);
      continue;
    }
    if (spring.a.share > 0) {
      // One spring per owned node, to the ground or to a body's reference point.
      Eigen::Vector3d u_b = Eigen::Vector3d::Zero(), v_b = Eigen::Vector3d::Zero();
      if (spring.b.body >= 0) {
        u_b = bodies_[spring.b.body].displacement;
        v_b = bodies_[spring.b.body].velocity;
      }
      for (LocalIndex node : spring.a.nodes) {
        const Eigen::Vector3d stretch = u_b - Eigen::Map<const Eigen::Vector3d>(&nodes.u[3 * node]);
        const Eigen::Vector3d rate = v_b - Eigen::Map<const Eigen::Vector3d>(&nodes.v[3 * node]);
        const Eigen::Vector3d force = spring_translational_force(spring.element, stretch, rate);
        for (int d = 0; d < 3; ++d)
          nodes.residual[3 * node + d] += force[d];
        energy += spring_translational_energy(spring.element, stretch);
        power += spring_translational_power(spring.element, rate);
        if (spring.b.body >= 0)
          bodies_[spring.b.body].force -= force;
      }
    }
  }
  return power;
}

void DiscreteParts::add_body_force(const Spring& spring, const Eigen::Vector3d& force_on_a,
                                   bool to_b) {
  bodies_[spring.a.body].force += force_on_a;
  if (to_b)
    bodies_[spring.b.body].force -= force_on_a;
}

std::array<double, 3> DiscreteParts::motion_at(int f, double t, double dt) const {
  // Derivatives by central differences: the rate over a step well below the time step (or
  // 1e-7 s), the acceleration over the time step itself (or 1e-7 s). A second difference over
  // 1e-3 dt is round-off: eps |u| / h² reached 2.6 m/s² for an axle box's 0.1 mm sideways motion
  // at 86 ns, and differed between rank counts.
  const double h = dt > 0 ? 1e-3 * dt : 1e-7, h2 = dt > 0 ? dt : 1e-7;
  const Expression& motion = motion_functions_[f];
  const double at = motion(0, 0, 0, t);
  const double rate = (motion(0, 0, 0, t + h) - motion(0, 0, 0, t - h)) / (2 * h);
  return {at, rate, (motion(0, 0, 0, t + h2) - 2 * at + motion(0, 0, 0, t - h2)) / (h2 * h2)};
}

void DiscreteParts::correct(double time, double dt, const std::array<double, 3>& gravity,
                            NodalArrays& nodes, const Communicator& comm) {
  time_ = time;
  if (bodies_.empty())
    return;
  // Springs between bodies, or from a body to the ground, are added once (on rank 0) before the
  // sum over ranks.
  double body_spring_energy = 0, body_spring_power = 0;
  if (comm.is_root()) {
    for (const Spring& spring : springs_) {
      if (spring.a.body < 0)
        continue;
      const RigidBody& a = bodies_[spring.a.body];
      Eigen::Vector3d u_b = Eigen::Vector3d::Zero(), v_b = Eigen::Vector3d::Zero();
      if (spring.b.body >= 0) {
        u_b = bodies_[spring.b.body].displacement;
        v_b = bodies_[spring.b.body].velocity;
      }
      const Eigen::Vector3d stretch = u_b - a.displacement, rate = v_b - a.velocity;
      const Eigen::Vector3d force = spring_translational_force(spring.element, stretch, rate);
      add_body_force(spring, force, spring.b.body >= 0);
      body_spring_energy += spring_translational_energy(spring.element, stretch);
      body_spring_power += spring_translational_power(spring.element, rate);
    }
  }
  spring_energy_ = body_spring_energy;
  spring_power_ = body_spring_power;
  std::vector<double>& sums = body_sums_;
  sums.clear();
  for (RigidBody& body : bodies_) {
    for (std::size_t i = 0; i < body.nodes.size(); ++i) {
      const LocalIndex node = body.nodes[i];
      const Eigen::Vector3d f(nodes.residual[3 * node], nodes.residual[3 * node + 1],
                              nodes.residual[3 * node + 2]);
      body.force += f;
      body.moment += (body.rotation * body.offsets[i]).cross(f);
    }
    sums.insert(sums.end(), body.force.data(), body.force.data() + 3);
    sums.insert(sums.end(), body.moment.data(), body.moment.data() + 3);
  }
  comm.sum_in_place(sums);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    RigidBody& body = bodies_[b];
    body.force = Eigen::Vector3d(sums[6 * b], sums[6 * b + 1], sums[6 * b + 2]);
    body.moment = Eigen::Vector3d(sums[6 * b + 3], sums[6 * b + 4], sums[6 * b + 5]);
    // Loads on the body itself: gravity on its extra mass and applied moments.
    Eigen::Vector3d own_force = body.weighs ? Eigen::Vector3d(body.extra_mass * vector_of(gravity))
                                            : Eigen::Vector3d::Zero();
    Eigen::Vector3d own_moment = Eigen::Vector3d::Zero();
    for (std::size_t m = 0; m < moments_.size(); ++m)
      if (moments_[m].body == body.name)
        own_moment += moment_functions_[m](0, 0, 0, time) * vector_of(moments_[m].moment);
    body.force += own_force;
    body.moment += own_moment;

    body.work += 0.5 * (own_force + previous_own_force_[b]).dot(body_step_[b]);
    previous_own_force_[b] = own_force;
    previous_own_moment_[b] = own_moment;

    body.acceleration = body.force / body.mass;
    for (int d = 0; d < 3; ++d) {
      if (body.fixed[d])
        body.acceleration[d] = 0;
      if (body.motion[d] < 0)
        continue;
      // The motion's own acceleration; the force that drives it does work over the step.
      const auto now = motion_at(body.motion[d], time, dt);
      body.acceleration[d] = now[2];
      const double reaction = body.mass * now[2] - body.force[d];
      body.work += 0.5 * (reaction + body.motion_reaction[d]) * body_step_[b][d];
      body.motion_reaction[d] = reaction;
    }
    body.velocity += 0.5 * dt * body.acceleration;
    if (body.rotates) {
      // Second kick, with the moment at the new orientation (its work exact, as in predict()).
      const RigidRotation& rotation = rotations_[b];
      const Eigen::Vector3d before = body.angular_velocity;
      rotation.kick(0.5 * dt * body.moment, body.angular_momentum);
      body.angular_velocity = rotation.angular_velocity(body.rotation, body.angular_momentum);
      body.work += 0.25 * dt * own_moment.dot(before + body.angular_velocity);
      // About locked axes L is whatever the reaction makes it: I_s ω (a free body keeps its L
      // untouched, so that it is conserved to the last bit without moments).
      if (body.fixed[3] || body.fixed[4] || body.fixed[5])
        body.angular_momentum = rotation.momentum(body.rotation, body.angular_velocity);
      body.angular_acceleration =
          rotation.angular_acceleration(body.rotation, body.angular_velocity, body.moment);
    }
    for (std::size_t i = 0; i < body.nodes.size(); ++i) {
      const LocalIndex node = body.nodes[i];
      const Eigen::Vector3d r = body.rotation * body.offsets[i];
      const Eigen::Vector3d& w = body.angular_velocity;
      const Eigen::Vector3d v = body.velocity + w.cross(r);
      const Eigen::Vector3d a =
          body.acceleration + body.angular_acceleration.cross(r) + w.cross(w.cross(r));
      for (int d = 0; d < 3; ++d) {
        nodes.v[3 * node + d] = v[d];
        nodes.a[3 * node + d] = a[d];
      }
    }
  }
}

double DiscreteParts::kinetic_energy() const {
  double energy = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& body = bodies_[b];
    energy += 0.5 * body.mass * body.velocity.squaredNorm() +
              rotations_[b].kinetic_energy(body.rotation, body.angular_velocity);
  }
  return energy;
}

double DiscreteParts::external_work() const {
  double work = 0;
  for (const RigidBody& body : bodies_)
    work += body.work;
  return work;
}

std::vector<double> DiscreteParts::state() const {
  std::vector<double> values;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& body = bodies_[b];
    for (const auto* vector : {&body.displacement, &body.velocity, &body.acceleration,
                               &body.angular_velocity, &body.angular_acceleration,
                               &previous_own_force_[b], &previous_own_moment_[b], &body_step_[b]})
      values.insert(values.end(), vector->data(), vector->data() + 3);
    values.insert(values.end(), body.rotation.data(), body.rotation.data() + 9);
    values.push_back(body.work);
    values.insert(values.end(), body.angular_momentum.data(), body.angular_momentum.data() + 3);
    values.insert(values.end(), body.moment.data(), body.moment.data() + 3);
  }
  return values;
}

void DiscreteParts::restore(const std::vector<double>& values) {
  const bool old = values.size() == kOldStateSize * bodies_.size();
  if (!old && values.size() != kStateSize * bodies_.size())
    throw RunError("the checkpoint's rigid bodies do not fit this model (" +
                   std::to_string(values.size()) + " values for " + std::to_string(bodies_.size()) +
                   " bodies)");
  std::size_t k = 0;
  auto read = [&](Eigen::Vector3d& vector) {
    for (int d = 0; d < 3; ++d)
      vector[d] = values[k++];
  };
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    RigidBody& body = bodies_[b];
    for (auto* vector : {&body.displacement, &body.velocity, &body.acceleration,
                         &body.angular_velocity, &body.angular_acceleration,
                         &previous_own_force_[b], &previous_own_moment_[b], &body_step_[b]})
      read(*vector);
    for (int i = 0; i < 9; ++i)
      body.rotation.data()[i] = values[k++];
    body.work = values[k++];
    if (old) {
      // The former scheme kept ω̇ = I_s⁻¹ (M − ω × I_s ω): M from it (exact on free axes).
      const Eigen::Matrix3d inertia = body.rotation * body.inertia * body.rotation.transpose();
      const Eigen::Vector3d& w = body.angular_velocity;
      body.angular_momentum = rotations_[b].momentum(body.rotation, w);
      body.moment = inertia * body.angular_acceleration + w.cross(inertia * w);
      continue;
    }
    read(body.angular_momentum);
    read(body.moment);
  }
}

}  // namespace railfe
