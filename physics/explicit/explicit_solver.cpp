#include "physics/explicit/explicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/assembly/dof_map.hpp"
#include "framework/base/error.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/elements/hex8.hpp"
#include "physics/explicit/convected_start.hpp"
#include "physics/explicit/ghost_exchange.hpp"
#include "physics/explicit/lanczos.hpp"
#include "physics/explicit/nodal_conditions.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {

namespace {

// time, steps, four energy accumulators, stable step, strain, hourglass and spring energy, and
// the step calibration (checkpoint format 3).
constexpr std::size_t kStateScalars = 11;

// Lumped (row-sum) masses of the hex8 elements, 3 entries per local node (local sums only),
// each element's density times its factor in \p density_scale (by the partition's element order).
std::vector<double> element_masses(const MeshPartition& partition, const MaterialTable& materials,
                                   const std::vector<double>& density_scale) {
  std::vector<double> masses(3 * static_cast<std::size_t>(partition.n_local_nodes()), 0.0);
  double x[8][3], mass[24 * 24];
  LocalIndex index = 0;
  for (const LocalBlock& block : partition.blocks()) {
    if (partition.mesh().blocks[block.block].type != ElementType::hex8) {
      index += block.n_elements();
      continue;
    }
    const double density = materials.of_block(block.block).density;
    for (LocalIndex e = 0; e < block.n_elements(); ++e, ++index) {
      element_coordinates(partition, block, e, x);
      hex8_mass(x, density * density_scale[index], true, mass);
      const LocalIndex* nodes = &block.connectivity[block.offsets[e]];
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d)
          masses[3 * nodes[a] + d] += mass[(3 * a + d) * 25];
    }
  }
  return masses;
}

}  // namespace

ExplicitSolver::ExplicitSolver(const ExplicitSettings& settings, const DofMap& dofs,
                               const MaterialTable& materials, const std::string& deck,
                               const std::string& path)
    : settings_(settings), dofs_(dofs), comm_(dofs.partition().comm()), deck_(deck) {
  dofs.require_uniform(3, "the explicit solver (its kernels index 3 x node)");
  const MeshPartition& partition = dofs.partition();
  n_owned_ = partition.n_owned_nodes();
  n_owned_dofs_ = 3 * static_cast<std::size_t>(n_owned_);
  const std::size_t n_local = 3 * static_cast<std::size_t>(partition.n_local_nodes());
  x_.resize(n_local);
  for (LocalIndex node = 0; node < partition.n_local_nodes(); ++node)
    std::copy_n(partition.coordinates(node), 3, &x_[3 * node]);
  for (auto* array : {&u_, &v_, &a_, &force_})
    array->assign(n_local, 0.0);
  for (auto* array : {&du_, &residual_, &external_, &applied_})
    array->assign(n_owned_dofs_, 0.0);

  elements_ = build_solid_elements(partition, materials, settings.kernel);
  ghosts_ = std::make_unique<GhostExchange>(dofs);
  const std::vector<double> density_scale = scale_small_elements(settings.mass_scaling_step);
  std::vector<double> masses = element_masses(partition, materials, density_scale);
  ghosts_->sum_into_owners(masses.data());
  mass_.resize(n_owned_);
  for (LocalIndex node = 0; node < n_owned_; ++node)
    mass_[node] = masses[3 * node];
  for (const NodalMass& added : settings.nodal_masses) {
    const auto nodes = owned_set_nodes(partition, added.node_set);
    const double count = static_cast<double>(comm_.sum(static_cast<long long>(nodes.size())));
    for (LocalIndex node : nodes)
      mass_[node] += added.mass / count;
  }

  loads_ = std::make_unique<TimedLoads>(settings, materials, dofs, deck, path);
  std::vector<std::vector<LocalIndex>> motion_nodes;
  for (const PrescribedMotion& motion : settings.motions)
    motion_nodes.push_back(owned_set_nodes(partition, motion.node_set));
  motions_ =
      std::make_unique<PrescribedMotions>(settings, n_owned_, motion_nodes, x_.data(), deck, path);
  discrete_ =
      std::make_unique<DiscreteParts>(settings, partition, mass_, deck, path + "/Discrete parts");
  // A node cannot both follow a body and have its motion prescribed.
  int conflict = 0;
  for (const PrescribedDof& entry : motions_->dofs())
    conflict = std::max(conflict, discrete_->carried(entry.dof / 3) ? 1 : 0);
  if (comm_.max(static_cast<long long>(conflict)) > 0)
    throw_input_error(deck, path + "/Prescribed motion",
                      "prescribes nodes that a rigid body carries",
                      "prescribe the body (Fixed translations / rotations) instead");
  gravity_function_ =
      std::make_unique<Expression>(settings.gravity_function, deck, path + "/Gravity function");
  contact_ =
      std::make_unique<ContactPairs>(settings.contact_pairs, partition, materials, deck, path);
}

ExplicitSolver::~ExplicitSolver() = default;

NodalArrays ExplicitSolver::arrays() {
  NodalArrays nodes;
  nodes.n_owned = n_owned_;
  nodes.x = x_.data();
  nodes.mass = mass_.data();
  nodes.u = u_.data();
  nodes.v = v_.data();
  nodes.a = a_.data();
  nodes.du = du_.data();
  nodes.residual = residual_.data();
  return nodes;
}

void ExplicitSolver::set_gravity(double time) {
  const double scale = (*gravity_function_)(0, 0, 0, time);
  for (int d = 0; d < 3; ++d)
    gravity_now_[d] = scale * settings_.gravity[d];
}

void ExplicitSolver::prepare_forces(double time) {
  set_gravity(time);
  std::fill(force_.begin(), force_.end(), 0.0);
  for (LocalIndex node = 0; node < n_owned_; ++node)
    for (int d = 0; d < 3; ++d)
      applied_[3 * node + d] = mass_[node] * gravity_now_[d];
  loads_->add(time, applied_.data());
}

void ExplicitSolver::evaluate_forces(double dt) {
  totals_ = add_internal_forces(elements_, settings_.kernel, x_.data(), u_.data(), v_.data(),
                                force_.data());
  ghosts_->sum_into_owners(force_.data());
  for (std::size_t k = 0; k < n_owned_dofs_; ++k)
    residual_[k] = applied_[k] - force_[k];
  spring_energy_ = 0;
  NodalArrays nodes = arrays();
  damper_power_ = discrete_->add_spring_forces(nodes, spring_energy_);
  // Before the bodies sum their nodes' forces, so a carried node's contact force moves its body.
  contact_->add_forces(x_.data(), u_.data(), du_.data(), dt, residual_.data());
  solid_stable_step_ =
      std::min(comm_.min(totals_.stable_step) * step_calibration_, discrete_->stable_step());
  stable_step_ = coupled_stable_step(solid_stable_step_, contact_->stable_step());
}

double coupled_stable_step(double solids, double contact) {
  constexpr double kEqualLimits = 0.83;  // the factor where the two limits are equal
  constexpr double kApart = 1.5;         // from this ratio of the larger to the smaller: none
  const double smaller = std::min(solids, contact), larger = std::max(solids, contact);
  if (!(larger < kApart * smaller))
    return smaller;  // also +inf contact (no pairs)
  return smaller * (kEqualLimits + (1 - kEqualLimits) * (larger / smaller - 1) / (kApart - 1));
}

std::vector<double> ExplicitSolver::scale_small_elements(double target) {
  std::vector<double> scale(dofs_.partition().n_local_elements(), 1.0);
  if (!(target > 0))
    return scale;
  double added_volume_mass = 0, scaled = 0;
  for (LocalIndex e = 0; e < elements_.n_elements; ++e) {
    const double step = elements_.stable_step[e];
    if (!(step < target))
      continue;
    // ρ → s ρ: c_P and every hourglass frequency fall by √s, so the step rises by √s to the
    // target; a viscous hourglass force (κ ρ c) grows by √s, a stiffness one is unchanged.
    const double s = (target / step) * (target / step), root = std::sqrt(s);
    added_volume_mass += (s - 1) * elements_.density[e] * elements_.volume[e];
    elements_.density[e] *= s;
    elements_.wave_speed[e] /= root;
    elements_.stable_step[e] *= root;
    if (settings_.kernel.hourglass == HourglassForm::viscous)
      elements_.hourglass_scale[e] *= root;
    scale[elements_.partition_index[e]] = s;
    ++scaled;
  }
  mass_scaling_.added_mass = comm_.sum(added_volume_mass);
  mass_scaling_.scaled_elements = static_cast<long long>(comm_.sum(scaled));
  return scale;
}

double ExplicitSolver::contact_stable_step() const {
  return contact_->stable_step();
}

void ExplicitSolver::calibrate_stable_step() {
  // The operator M^-½ K M^-½ of the solids, K applied as a difference of internal forces about
  // the current state; elastic only (no bulk viscosity, no viscous hourglass forces).
  SolidKernelSettings elastic = settings_.kernel;
  elastic.bulk_linear = elastic.bulk_quadratic = 0;
  if (elastic.hourglass == HourglassForm::viscous)
    elastic.hourglass = HourglassForm::none;
  // Without velocity-dependent forces the kernel ignores v_. Until the first force evaluation
  // a_ and force_ (local) and residual_, applied_ and external_ (owned) hold nothing, so the
  // estimate borrows them and the run's peak memory stays that of its steps.
  std::vector<double>& force = force_;
  std::vector<double>& trial = a_;
  std::vector<double>& base_force = residual_;
  std::fill(force.begin(), force.end(), 0.0);
  add_internal_forces(elements_, elastic, x_.data(), u_.data(), v_.data(), force.data());
  ghosts_->sum_into_owners(force.data());
  std::copy_n(force.begin(), n_owned_dofs_, base_force.begin());
  double shortest = 1e300;
  for (double length : elements_.length)
    shortest = std::min(shortest, length);
  shortest = comm_.min(shortest);
  auto add_product = [&](const double* q, double* w) {
    double largest = 0;
    for (std::size_t k = 0; k < n_owned_dofs_; ++k)
      largest = std::max(largest, std::abs(q[k]) / std::sqrt(mass_[k / 3]));
    // A perturbation of 1e-6 element lengths: linear to 1e-6, far above round-off.
    const double scale = 1e-6 * shortest / comm_.max(largest);
    trial = u_;
    for (std::size_t k = 0; k < n_owned_dofs_; ++k)
      trial[k] += scale * q[k] / std::sqrt(mass_[k / 3]);
    ghosts_->update_ghosts(trial.data(), v_.data());
    std::fill(force.begin(), force.end(), 0.0);
    add_internal_forces(elements_, elastic, x_.data(), trial.data(), v_.data(), force.data());
    ghosts_->sum_into_owners(force.data());
    for (std::size_t k = 0; k < n_owned_dofs_; ++k)
      w[k] += (force[k] - base_force[k]) / scale / std::sqrt(mass_[k / 3]);
  };
  const MeshPartition& partition = dofs_.partition();
  auto global_dof = [&partition](std::size_t k) {
    return 3 * partition.global_node(static_cast<LocalIndex>(k / 3)) +
           static_cast<GlobalIndex>(k % 3);
  };
  const double lambda = largest_eigenvalue(add_product, n_owned_dofs_, global_dof, applied_.data(),
                                           external_.data(), comm_);
  double element_step = 1e300;
  for (double step : elements_.stable_step)
    element_step = std::min(element_step, step);
  element_step = comm_.min(element_step);
  if (lambda > 0 && element_step < 1e300)
    step_calibration_ = 2 / std::sqrt(lambda) / element_step;
}

void ExplicitSolver::initialise(const double* start) {
  const MeshPartition& partition = dofs_.partition();
  if (start) {
    std::copy_n(start, n_owned_dofs_, u_.begin());
    const double scale = (*gravity_function_)(0, 0, 0, 0);
    const std::array<double, 3> gravity = {
        scale * settings_.gravity[0], scale * settings_.gravity[1], scale * settings_.gravity[2]};
    discrete_->start_from_preload(arrays(), gravity, comm_);
  }
  for (const InitialVelocity& initial : settings_.initial_velocities) {
    for (LocalIndex node : owned_set_nodes(partition, initial.node_set)) {
      double r[3];
      for (int d = 0; d < 3; ++d)
        r[d] = x_[3 * node + d] - initial.axis_point[d];
      const auto& w = initial.angular_velocity;
      const double rotation[3] = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2],
                                  w[0] * r[1] - w[1] * r[0]};
      for (int d = 0; d < 3; ++d)
        v_[3 * node + d] = initial.translation[d] + rotation[d];
    }
  }
  if (start && settings_.preload_frame) {
    ghosts_->update_ghosts(u_.data(), v_.data());
    std::vector<bool> skip(n_owned_);
    for (LocalIndex node = 0; node < n_owned_; ++node)
      skip[node] = discrete_->carried(node);
    add_convected_velocity(elements_, u_.data(), *settings_.preload_frame, n_owned_, ghosts_.get(),
                           skip, v_.data());
  }
  motions_->apply(0, 0, u_.data(), du_.data(), v_.data(), a_.data());
  NodalArrays nodes = arrays();
  discrete_->initialise_nodes(nodes);
  ghosts_->update_ghosts(u_.data(), v_.data());
  if (preset_calibration_ > 0)
    step_calibration_ = preset_calibration_;
  else
    calibrate_stable_step();
  // The calibration used a_ as a buffer: the accelerations are set from here on (the other
  // borrowed arrays are overwritten by the first force evaluation).
  std::fill(a_.begin(), a_.end(), 0.0);
  motions_->apply(0, 0, u_.data(), du_.data(), v_.data(), a_.data());
  double element_step = 1e300;
  for (double step : elements_.stable_step)
    element_step = std::min(element_step, step);
  const double solid_step =
      settings_.time_step > 0
          ? settings_.time_step
          : settings_.safety_factor * comm_.min(element_step) * step_calibration_;
  contact_->initialise(mass_, solid_step, x_.data(), u_.data());
  // Heavier contact nodes change the springs' steps, not their stiffness: set them up again.
  if (contact_->scale_masses(mass_))
    contact_->initialise(mass_, solid_step, x_.data(), u_.data());
  prepare_forces(0);
  evaluate_forces(0);
  discrete_->correct(0, 0, gravity_now_, nodes, comm_);
  external_ = applied_;
  for (LocalIndex node = 0; node < n_owned_; ++node) {
    if (discrete_->carried(node))
      continue;
    for (int d = 0; d < 3; ++d) {
      const std::size_t k = 3 * static_cast<std::size_t>(node) + d;
      if (!motions_->prescribed(static_cast<LocalIndex>(k)))
        a_[k] = residual_[k] / mass_[node] - settings_.rayleigh_mass * v_[k];
    }
  }
  previous_reaction_.clear();
  for (const PrescribedDof& entry : motions_->dofs())
    previous_reaction_.push_back(mass_[entry.dof / 3] * a_[entry.dof] - residual_[entry.dof]);
  const EnergyBalance start_balance = energy_balance();
  // A preloaded start stores energy in the penalty springs too.
  initial_energy_ = start_balance.kinetic + start_balance.internal + start_balance.hourglass +
                    start_balance.contact;
}

void ExplicitSolver::step(double dt) {
  const double time_next = time_ + dt;
  const double alpha = settings_.rayleigh_mass;
  const auto& prescribed = motions_->dofs();

  // Predictor on every owned DOF; Rayleigh dissipation takes its first half with v_n, on the
  // DOFs the corrector damps (not those of rigid bodies' nodes nor prescribed ones). The same
  // pass does prepare_forces() for the end of the step (zero internal forces, gravity loads):
  // two passes over the nodal arrays fewer.
  double dissipated = 0;
  set_gravity(time_next);
  for (LocalIndex node = 0; node < n_owned_; ++node) {
    const double m = mass_[node];
    const bool carried = discrete_->carried(node);
    for (int d = 0; d < 3; ++d) {
      const std::size_t k = 3 * static_cast<std::size_t>(node) + d;
      const double step = dt * v_[k] + 0.5 * dt * dt * a_[k];
      if (!carried && !motions_->prescribed(static_cast<LocalIndex>(k)))
        dissipated += 0.5 * alpha * m * v_[k] * step;
      du_[k] = step;
      u_[k] += step;
      v_[k] += 0.5 * dt * a_[k];
      force_[k] = 0;
      applied_[k] = m * gravity_now_[d];
    }
  }
  std::fill(force_.begin() + n_owned_dofs_, force_.end(), 0.0);
  loads_->add(time_next, applied_.data());
  motions_->apply(time_next, dt, u_.data(), du_.data(), v_.data(), a_.data());
  NodalArrays nodes = arrays();
  discrete_->predict(dt, nodes);
  ghosts_->update_ghosts(u_.data(), v_.data());

  evaluate_forces(dt);
  discrete_->correct(time_next, dt, gravity_now_, nodes, comm_);

  // Corrector: a_{n+1} from the diagonal system, v_{n+1}; work of every external force.
  double work = 0;
  const double implicit_damping = 1 / (1 + 0.5 * alpha * dt);
  for (LocalIndex node = 0; node < n_owned_; ++node) {
    const bool carried = discrete_->carried(node);
    const double m = mass_[node];
    for (int d = 0; d < 3; ++d) {
      const std::size_t k = 3 * static_cast<std::size_t>(node) + d;
      double total = applied_[k];
      if (!carried && !motions_->prescribed(static_cast<LocalIndex>(k))) {
        const double a_new = (residual_[k] / m - alpha * v_[k]) * implicit_damping;
        v_[k] += 0.5 * dt * a_new;
        a_[k] = a_new;
        dissipated += 0.5 * alpha * m * v_[k] * du_[k];
      }
      work += 0.5 * du_[k] * (external_[k] + total);
      external_[k] = total;
    }
  }
  // Prescribed DOFs: acceleration from the velocity change, and the support reaction's work.
  for (std::size_t i = 0; i < prescribed.size(); ++i) {
    const LocalIndex k = prescribed[i].dof;
    const double reaction = mass_[k / 3] * a_[k] - residual_[k];
    work += 0.5 * du_[k] * (previous_reaction_[i] + reaction);
    previous_reaction_[i] = reaction;
  }
  external_work_ += work;
  damping_work_ +=
      dissipated + dt * (totals_.viscous_power + damper_power_ + discrete_->body_spring_power());
  hourglass_work_ += dt * totals_.hourglass_power;
  time_ = time_next;
  last_step_ = dt;
  ++n_steps_;
}

double ExplicitSolver::kinetic_energy_local() const {
  double energy = 0;
  for (LocalIndex node = 0; node < n_owned_; ++node) {
    if (discrete_->carried(node))
      continue;
    const double* v = &v_[3 * static_cast<std::size_t>(node)];
    energy += 0.5 * mass_[node] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  return energy;
}

EnergyBalance ExplicitSolver::energy_balance() const {
  std::vector<double> sums = {
      kinetic_energy_local(),
      totals_.strain_energy + spring_energy_ + discrete_->body_spring_energy(),
      totals_.hourglass_energy + hourglass_work_, damping_work_, external_work_};
  comm_.sum_in_place(sums);
  EnergyBalance balance;
  balance.kinetic = sums[0] + discrete_->kinetic_energy();
  balance.internal = sums[1];
  balance.hourglass = sums[2];
  balance.damping = sums[3];
  balance.external_work = sums[4] + discrete_->external_work();
  // Every rank evaluates the whole contact, so its energies are not summed.
  balance.contact = contact_->stored_energy();
  balance.friction = contact_->dissipated();
  const double total = balance.kinetic + balance.internal + balance.hourglass + balance.damping +
                       balance.contact + balance.friction;
  const double scale =
      std::max({std::abs(initial_energy_), std::abs(total), std::abs(balance.external_work)});
  balance.error = scale > 0 ? (total - initial_energy_ - balance.external_work) / scale : 0.0;
  return balance;
}

std::pair<double, double> ExplicitSolver::node_sum(const std::vector<LocalIndex>& nodes,
                                                   int quantity, int component) const {
  const std::vector<double>& field = quantity == 0 ? u_ : quantity == 1 ? v_ : a_;
  double sum = 0;
  for (LocalIndex node : nodes)
    sum += field[3 * static_cast<std::size_t>(node) + component];
  return {sum, static_cast<double>(nodes.size())};
}

double ExplicitSolver::total_mass() const {
  double mass = 0;
  for (double m : mass_)
    mass += m;
  mass = comm_.sum(mass);
  for (const RigidBody& body : discrete_->bodies())
    mass += body.extra_mass;
  return mass;
}

std::string ExplicitSolver::critical_location() const {
  const double contact = contact_->stable_step();
  if (stable_step_ < std::min(contact, solid_stable_step_) * (1 - 1e-12)) {
    std::ostringstream text;
    text.precision(3);
    text << "contact pair '" << contact_->critical_pair() << "' and the solids together (their "
         << "limits " << contact << " and " << solid_stable_step_ << " s are close: the "
         << "coupled limit is taken as " << stable_step_ / std::min(contact, solid_stable_step_)
         << " of the smaller; a Penalty factor that moves the contact's limit away raises it)";
    return text.str();
  }
  if (contact <= stable_step_)
    return "contact pair '" + contact_->critical_pair() +
           "' (2 sqrt(m / k) of its penalty springs; a smaller Penalty factor raises it)";
  if (discrete_->stable_step() <= stable_step_)
    return "a spring-damper of Discrete parts";
  std::ostringstream text;
  text.precision(4);
  text << smallest_step(elements_, dofs_.partition(), elements_.stable_step, x_.data()).second
       << ", L/c_P x " << step_calibration_ << " from the mesh's highest frequency";
  return text.str();
}

double ExplicitSolver::checkpointed_step_calibration(const std::vector<double>& scalars) {
  return scalars.size() == kStateScalars ? scalars[10] : 0.0;
}

SolverState ExplicitSolver::state() const {
  SolverState state;
  state.scalars = {time_,
                   static_cast<double>(n_steps_),
                   initial_energy_,
                   external_work_,
                   damping_work_,
                   hourglass_work_,
                   stable_step_,
                   totals_.strain_energy,
                   totals_.hourglass_energy,
                   spring_energy_,
                   step_calibration_};
  for (const auto* array : {&u_, &v_, &a_, &external_})
    state.arrays.insert(state.arrays.end(), array->begin(), array->end());
  state.arrays.insert(state.arrays.end(), previous_reaction_.begin(), previous_reaction_.end());
  state.discrete = discrete_->state();
  // The contact's friction history rides behind the bodies', its length last.
  const std::vector<double> contact = contact_->state();
  state.discrete.insert(state.discrete.end(), contact.begin(), contact.end());
  state.discrete.push_back(static_cast<double>(contact.size()));
  return state;
}

void ExplicitSolver::restore(const SolverState& state) {
  const std::size_t expected = 3 * u_.size() + external_.size() + previous_reaction_.size();
  if (state.scalars.size() != kStateScalars || state.arrays.size() != expected)
    throw RunError("the checkpoint does not fit this model and partition (" +
                   std::to_string(state.arrays.size()) + " values for " + std::to_string(expected) +
                   ")");
  time_ = state.scalars[0];
  n_steps_ = static_cast<long long>(state.scalars[1]);
  initial_energy_ = state.scalars[2];
  external_work_ = state.scalars[3];
  damping_work_ = state.scalars[4];
  hourglass_work_ = state.scalars[5];
  stable_step_ = state.scalars[6];
  totals_.strain_energy = state.scalars[7];
  totals_.hourglass_energy = state.scalars[8];
  spring_energy_ = state.scalars[9];
  step_calibration_ = state.scalars[10];
  auto it = state.arrays.begin();
  for (auto* array : {&u_, &v_, &a_, &external_}) {
    std::copy_n(it, array->size(), array->begin());
    it += static_cast<std::ptrdiff_t>(array->size());
  }
  std::copy_n(it, previous_reaction_.size(), previous_reaction_.begin());
  const auto contact_size =
      state.discrete.empty() ? std::size_t{0} : static_cast<std::size_t>(state.discrete.back());
  if (state.discrete.empty() || contact_size + 1 > state.discrete.size())
    throw RunError("the checkpoint does not fit this model's contact pairs");
  const auto contact_begin = state.discrete.end() - 1 - static_cast<std::ptrdiff_t>(contact_size);
  discrete_->restore(std::vector<double>(state.discrete.begin(), contact_begin));
  if (!contact_->restore(std::vector<double>(contact_begin, state.discrete.end() - 1)))
    throw RunError("the checkpoint does not fit this model's contact pairs");
  ghosts_->update_ghosts(u_.data(), v_.data());
}

}  // namespace railfe
