#include "physics/implicit/implicit_step.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>
#include <cstdio>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/output/csv_writer.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/common/structural_assembly.hpp"
#include "physics/implicit/beam_paths.hpp"
#include "physics/implicit/constrained_stepper.hpp"
#include "physics/implicit/implicit_output.hpp"
#include "physics/implicit/implicit_system.hpp"

namespace railfe {

namespace {

// Refuses the solid conditions this module does not apply, naming the parameter.
void refuse_unsupported(const SolidConditions& conditions, const std::string& deck,
                        const std::string& path) {
  for (const auto& condition : conditions.displacements)
    if (condition.value != 0.0 || !condition.expression.empty())
      throw_input_error(deck, path + "/Displacements/" + condition.name,
                        "prescribes a non-zero displacement; the implicit module holds "
                        "Displacements fixed at zero",
                        "Value 0 and no Expression (supports), or a statics step");
  if (!conditions.ties.empty())
    throw_input_error(deck, path + "/Ties/" + conditions.ties.front().name,
                      "is not supported by the implicit module yet",
                      "merge the meshes' coincident nodes, or use a statics step");
  if (!conditions.centrifugal_loads.empty())
    throw_input_error(deck,
                      path + "/Centrifugal loads/" + conditions.centrifugal_loads.front().name,
                      "is a static preload for explicit rolling; the implicit module has no "
                      "rotating frame",
                      "remove it (use it in a statics step)");
  if (!conditions.probes.empty())
    throw_input_error(deck, path + "/Probes/" + conditions.probes.front().name,
                      "is a statics output; an implicit step records Output/Histories",
                      "an Output/Histories entry with the same Node set");
}

// Owned local DOFs held at zero by the Displacements.
std::vector<LocalIndex> fixed_dofs(const SolidConditions& conditions, const DofMap& dofs) {
  const MeshPartition& partition = dofs.partition();
  std::vector<char> is_fixed(static_cast<std::size_t>(dofs.n_owned_dofs()), 0);
  for (const auto& condition : conditions.displacements)
    for (GlobalIndex node : partition.mesh().node_set(condition.node_set, "", "").nodes) {
      const LocalIndex local = partition.local_node(node);
      if (local < 0 || local >= partition.n_owned_nodes())
        continue;
      for (int component : condition.components)
        is_fixed[dofs.local_dof(local, component)] = 1;
    }
  std::vector<LocalIndex> fixed;
  for (std::size_t dof = 0; dof < is_fixed.size(); ++dof)
    if (is_fixed[dof])
      fixed.push_back(static_cast<LocalIndex>(dof));
  return fixed;
}

// The initial displacement (a statics step's, or zero) and velocity.
void initial_state(const ImplicitSettings& settings, Model& model, const DofMap& dofs,
                   std::vector<double>& u, std::vector<double>& v) {
  if (!settings.start_from.empty()) {
    const auto field = model.field(settings.start_from + "/displacement");
    const auto data = field->getData();
    std::copy_n(data.getRawPtr(), u.size(), u.begin());
  }
  const MeshPartition& partition = dofs.partition();
  for (const ImplicitInitialVelocity& initial : settings.initial_velocities) {
    std::vector<LocalIndex> nodes;
    if (initial.node_set.empty()) {
      for (LocalIndex node = 0; node < partition.n_owned_nodes(); ++node)
        nodes.push_back(node);
    } else {
      for (GlobalIndex node : partition.mesh().node_set(initial.node_set, "", "").nodes) {
        const LocalIndex local = partition.local_node(node);
        if (local >= 0 && local < partition.n_owned_nodes())
          nodes.push_back(local);
      }
    }
    for (LocalIndex node : nodes)
      for (int d = 0; d < 3; ++d)
        v[dofs.local_dof(node, d)] = initial.translation[d];
  }
}

// Stops the run when the stored energy (kinetic + strain) exceeds ten times the largest energy
// put in so far (initial energy and work of the loads). Unconditionally stable members of the
// family cannot do that on a linear model, so this is a conditionally stable scheme (2β < γ)
// above its stable step, whose results would grow without bound. (The created energy itself is
// no test: the work of the loads is integrated by the trapezoidal rule, which only the
// average-acceleration scheme matches exactly.)
void check_energy_bounded(const ImplicitEnergy& energy, double largest_input, double time,
                          const NewmarkScheme& scheme, const std::string& path) {
  const double stored = energy.kinetic + energy.strain;
  if (stored <= 10 * largest_input + 1e-12 && std::isfinite(stored))
    return;
  throw RunError(
      path + ": the solution grows without bound: at t = " + CsvWriter::format(time) +
      " s the stored energy is " + CsvWriter::format(stored) + " J against at most " +
      CsvWriter::format(largest_input) + " J put in, so the integration is unstable" +
      (2 * scheme.beta < scheme.gamma
           ? " (Newmark with 2 Beta < Gamma is only conditionally stable: use HHT-alpha, Beta "
             ">= Gamma/2, or a smaller Time step)"
           : "") +
      ". Rows up to the last step are kept.");
}

// Whether any spring-damper section of \p sections damps.
bool has_structural_damping(const SectionTable& sections) {
  for (const StructuralSection& section : sections.sections())
    if (section.kind == StructuralKind::spring)
      for (double c : section.spring.damping)
        if (c > 0)
          return true;
  return false;
}

double dot_difference(const std::vector<double>& f0, const std::vector<double>& f1,
                      const std::vector<double>& u0, const std::vector<double>& u1) {
  double sum = 0;
  for (std::size_t i = 0; i < u0.size(); ++i)
    sum += 0.5 * (f0[i] + f1[i]) * (u1[i] - u0[i]);
  return sum;
}

}  // namespace

ImplicitStep::ImplicitStep(const Teuchos::ParameterList& parameters) : parameters_(&parameters) {}

void ImplicitStep::check(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  settings_ = read_implicit_settings(*parameters_, deck, context.path);
  conditions_ = read_solid_conditions(*parameters_, deck, context.path);
  check_solid_conditions(conditions_, mesh, deck, context.path);
  refuse_unsupported(conditions_, deck, context.path);
  const std::string step = "the implicit step '" + context.step_name + "'";
  materials_ = solid_materials(context.model, step, EnhancedStrainSupport::supported);
  sections_.reset();
  dofs_per_node_ = 3;
  if (has_structural_blocks(mesh)) {
    if (has_solid_blocks(mesh))
      throw_input_error(deck, "Mesh",
                        "has both solid (hex8) and beam, spring or point-mass blocks: " + step +
                            " needs mixed DOFs per node, which the implicit module does not take "
                            "yet (statics and modal do)",
                        "a model of solids alone, or of beams, springs and point masses alone");
    sections_ = structural_sections(context.model, step);
    dofs_per_node_ = 6;
    check_structural_conditions(conditions_, deck, context.path);
  } else {
    refuse_rotations(conditions_, deck, context.path, "a model of solids");
  }
  moving_loads_ = read_moving_loads(*parameters_, deck, context.path);
  for (const MovingLoadSpec& load : moving_loads_) {
    const std::string where = context.path + "/Moving loads/" + load.name + "/Path";
    if (!sections_)
      throw_input_error(deck, where, "needs beams, and the model has none",
                        "a model of beams (Mesh Type line and Sections)");
    chain_of_blocks(mesh, load.blocks, deck, where);
  }
  contacts_ = read_moving_contacts(*parameters_, context.model.deck(), context.path);
  if (!contacts_.empty()) {
    if (!sections_)
      throw_input_error(deck, context.path + "/Moving contacts/" + contacts_.front().name,
                        "needs beams to run on, and the model has none",
                        "a model of beams, springs and point masses (Mesh Type line, Sections)");
    check_moving_contacts(contacts_, mesh, settings_.end_time, deck, context.path);
  } else if (!parameters_->getEntry("Constraint solver").isDefault()) {
    throw_input_error(deck, context.path + "/Constraint solver",
                      "is used only with Moving contacts, and the step has none",
                      "remove it, or add a moving contact");
  }
  if (!settings_.start_from.empty() &&
      !is_earlier_statics_step(context.model.deck().parameters->sublist("Steps"),
                               settings_.start_from, context.step_name))
    throw_input_error(deck, context.path + "/Start from",
                      "names '" + settings_.start_from + "', which is no earlier statics step",
                      "the name of a statics step listed before this one");
  for (const ImplicitInitialVelocity& initial : settings_.initial_velocities)
    if (!initial.node_set.empty())
      mesh.node_set(initial.node_set, deck, context.path + "/Initial velocity");
  for (const ImplicitHistory& history : settings_.histories) {
    const std::string path = context.path + "/Output/Histories/" + history.name;
    const auto& nodes = mesh.node_set(history.node_set, deck, path + "/Node set").nodes;
    if (nodes.empty())
      throw_input_error(deck, path + "/Node set", "is empty", "a node set with nodes");
    if (history.component >= dofs_per_node_)
      throw_input_error(deck, path + "/Component",
                        "is a rotation, but the nodes of this model carry translations only",
                        "x, y or z");
  }
}

void ImplicitStep::run(StepContext& context) {
  Model& model = context.model;
  const DofMap& dofs = model.dofs(dofs_per_node_);
  const Communicator& comm = model.comm();
  const std::string section = "Step " + context.step_name + " (implicit)";
  const ImplicitSettings& settings = settings_;
  Stopwatch clock;

  FeMatrix stiffness(dofs), mass(dofs);
  auto load = Teuchos::rcp(new TpetraVector(dofs.owned_map()));
  Teuchos::RCP<TpetraMatrix> damping_matrix;
  std::unique_ptr<FeMatrix> damping;
  if (sections_) {
    assemble_structural_stiffness(stiffness, *sections_);
    assemble_structural_mass(mass, *sections_, settings.lumped_mass);
    assemble_structural_loads(conditions_, *sections_, dofs, *load);
    if (has_structural_damping(*sections_)) {
      damping = std::make_unique<FeMatrix>(dofs);
      assemble_structural_damping(*damping, *sections_);
      damping_matrix = damping->matrix();
    }
  } else {
    assemble_elastic_stiffness(stiffness, *materials_);
    assemble_mass(mass, *materials_, settings.lumped_mass);
    assemble_solid_loads(conditions_, *materials_, dofs, *load);
  }
  if (!std::isfinite(load->norm1()))
    throw RunError(context.path +
                   ": the assembled load is not finite (NaN or inf): check "
                   "Gravity with the materials' Density and every load's values");
  const std::vector<LocalIndex> fixed = fixed_dofs(conditions_, dofs);
  ImplicitSystem system(
      dofs, {stiffness.matrix(), mass.matrix(), damping_matrix, load}, fixed,
      Expression(settings.load_function, context.source(), context.path + "/Load function"),
      create_linear_solver(parameters_->sublist("Linear solver")), elasticity_traits(dofs));
  std::unique_ptr<MovingLoads> moving;
  if (!moving_loads_.empty()) {
    const MeshPartition& partition = dofs.partition();
    auto owned_dof = [&](GlobalIndex node, int component) -> long {
      const LocalIndex local = partition.local_node(node);
      return local < 0 || local >= partition.n_owned_nodes() ? -1
                                                             : dofs.local_dof(local, component);
    };
    moving = std::make_unique<MovingLoads>(moving_loads_, partition.mesh(), *sections_, owned_dof,
                                           context.source(), context.path);
    system.add_time_load([&moving](double t, double* f) { moving->add(t, f); });
  }
  const double assembly_seconds = clock.seconds();

  const std::size_t n = system.n_unknowns();
  std::vector<double> u(n, 0.0), v(n, 0.0), a(n, 0.0);
  initial_state(settings, model, dofs, u, v);
  for (LocalIndex dof : fixed)
    u[dof] = v[dof] = 0.0;

  HhtIntegrator integrator(settings.scheme, system, settings.newton, settings.rayleigh,
                           settings.cut_back);
  std::unique_ptr<ImplicitStepper> stepper;
  ConstrainedStepper* constrained = nullptr;
  if (contacts_.empty()) {
    stepper = std::make_unique<DistributedStepper>(integrator);
  } else {
    const LinearModelMatrices matrices{stiffness.matrix(), mass.matrix(), damping_matrix, load};
    ConstrainedSetup setup;
    setup.dofs = &dofs;
    setup.matrices = &matrices;
    setup.fixed = &fixed;
    setup.load_function = settings.load_function;
    setup.moving_loads = &moving_loads_;
    setup.contacts = &contacts_;
    setup.sections = &*sections_;
    setup.settings = &settings;
    setup.solver = parameters_->get<std::string>("Constraint solver");
    setup.deck = context.source();
    setup.path = context.path;
    auto owned = std::make_unique<ConstrainedStepper>(setup);
    constrained = owned.get();
    stepper = std::move(owned);
    constrained->open_contact_file(
        context.output.staging_path(context.step_name + "_contacts.csv"));
  }
  const bool root = comm.is_root();
  const std::string path = context.path;
  integrator.on_cut_back([&](const CutBack& cut) {
    if (root)
      std::fprintf(stderr,
                   "railfe: warning: %s: the step from t = %.9g s with dt = %.6g s did not "
                   "converge (%s); retrying with dt = %.6g s\n",
                   path.c_str(), cut.time, cut.failed_step, cut.reason.c_str(), cut.next_step);
  });
  if (root && 2 * settings.scheme.beta < settings.scheme.gamma)
    std::fprintf(stderr,
                 "railfe: warning: %s: Newmark with Beta %.6g < Gamma/2 is only conditionally "
                 "stable; the run stops (exit status 2) if the energy balance shows it diverging\n",
                 path.c_str(), settings.scheme.beta);
  stepper->initialize(0.0, u.data(), v.data(), a.data());
  if (constrained)
    constrained->write_contacts(0.0);

  ImplicitRecorder recorder(settings, dofs, context.output, context.step_name,
                            model.deck().parameters->get<std::string>("Title"),
                            model.deck().parameters->sublist("Output").get<bool>("Exodus"));
  // Damping force g = (a_R M + b_R K + C) v, for the dissipated work.
  std::vector<double> scratch(n);
  auto damping_force = [&](const std::vector<double>& velocity, std::vector<double>& g) {
    std::fill(g.begin(), g.end(), 0.0);
    if (settings.rayleigh.mass != 0) {
      system.apply_mass(velocity.data(), scratch.data());
      for (std::size_t i = 0; i < n; ++i)
        g[i] += settings.rayleigh.mass * scratch[i];
    }
    if (settings.rayleigh.stiffness != 0) {
      system.apply_rayleigh_stiffness(velocity.data(), scratch.data());
      for (std::size_t i = 0; i < n; ++i)
        g[i] += settings.rayleigh.stiffness * scratch[i];
    }
  };
  const bool damped = settings.rayleigh.mass != 0 || settings.rayleigh.stiffness != 0;
  ImplicitEnergy energy;
  energy.kinetic = system.kinetic_energy(v.data());
  energy.strain = system.strain_energy(u.data());
  energy.initial = energy.kinetic + energy.strain;
  std::vector<double> force(n), next_force(n), g(n, 0.0), next_g(n, 0.0), u_old(n);
  system.external_force(0.0, force.data());
  if (damped)
    damping_force(v, g);
  recorder.sample({0.0, u.data(), v.data(), a.data()}, true);
  recorder.write_energy(0.0, energy);
  recorder.snapshot({0.0, u.data(), v.data(), a.data()}, false);

  const long n_steps = static_cast<long>(std::ceil(settings.end_time / settings.time_step - 1e-9));
  Progress progress = context.progress("time stepping", static_cast<double>(n_steps));
  double time = 0, largest_dissipation = 0, largest_input = energy.initial;
  std::size_t iterations_before = 0;
  int most_substeps = 1;
  Stopwatch stepping;
  for (long step = 1; step <= n_steps; ++step) {
    // Every step but a shorter last one takes exactly Time step, so a linear model's factor is
    // reused (a Δt that differs in the last bit would refactor).
    const double remaining = settings.end_time - time;
    const double step_size =
        step < n_steps || std::abs(remaining - settings.time_step) <= 1e-9 * settings.time_step
            ? settings.time_step
            : remaining;
    const double next_time = step == n_steps ? settings.end_time : time + step_size;
    u_old = u;
    int substeps = 0;
    try {
      substeps = stepper->advance(time, step_size, u.data(), v.data(), a.data());
    } catch (const StepNotConverged& failure) {
      std::string history;
      for (double r : failure.residuals)
        history += (history.empty() ? "" : ", ") + CsvWriter::format(r);
      throw RunError(
          path + ": step " + std::to_string(step) + " from t = " + CsvWriter::format(failure.time) +
          " s (dt = " + CsvWriter::format(failure.step) +
          " s) did not converge: " + failure.what() + "; residual norms (N): " + history +
          ". Results up to the last converged step are kept.");
    }
    most_substeps = std::max(most_substeps, substeps);
    const double dt = step_size;
    time = next_time;
    if (constrained)
      constrained->write_contacts(next_time);
    const NewtonStatistics statistics = stepper->statistics();
    const int iterations = static_cast<int>(statistics.iterations - iterations_before);
    iterations_before = statistics.iterations;
    system.external_force(time, next_force.data());
    energy.external_work += comm.sum(dot_difference(force, next_force, u_old, u));
    force.swap(next_force);
    if (damped) {
      damping_force(v, next_g);
      energy.damping_work += comm.sum(dot_difference(g, next_g, u_old, u));
      g.swap(next_g);
    }
    const bool last = step == n_steps;
    const ImplicitState state{time, u.data(), v.data(), a.data()};
    recorder.sample(state, step % settings.history_interval == 0 || last);
    recorder.write_newton(step, time, dt, substeps, iterations, statistics.last_residuals);
    energy.kinetic = system.kinetic_energy(v.data());
    energy.strain = system.strain_energy(u.data());
    largest_dissipation = std::max(largest_dissipation, std::abs(energy.balance()));
    largest_input = std::max(largest_input, energy.initial + std::abs(energy.external_work));
    check_energy_bounded(energy, largest_input, time, settings.scheme, path);
    if (step % settings.energy_interval == 0 || last)
      recorder.write_energy(time, energy);
    recorder.snapshot(state, last);
    progress.update(static_cast<double>(step));
  }
  progress.finish();
  recorder.finish();
  const double stepping_seconds = stepping.seconds();

  const NewtonStatistics statistics = stepper->statistics();
  const double separations = constrained ? constrained->write_events(context.output.staging_path(
                                               context.step_name + "_contact_events.csv"))
                                         : 0.0;
  const double scale = std::max(
      {energy.initial + std::abs(energy.external_work), energy.kinetic + energy.strain, 1e-300});
  context.summary.add(section, "degrees of freedom", static_cast<double>(dofs.n_global_dofs()));
  context.summary.add(section, "fixed DOFs", comm.sum(static_cast<double>(fixed.size())));
  context.summary.add(section, "steps", static_cast<double>(n_steps));
  context.summary.add(section, "scheme alpha", settings.scheme.alpha);
  context.summary.add(section, "scheme beta", settings.scheme.beta);
  context.summary.add(section, "scheme gamma", settings.scheme.gamma);
  context.summary.add(section, "Newton iterations", static_cast<double>(statistics.iterations));
  context.summary.add(section, "most iterations in a step",
                      static_cast<double>(statistics.most_iterations));
  context.summary.add(section, "factorizations", static_cast<double>(statistics.factorizations));
  context.summary.add(section, "cut-backs", static_cast<double>(stepper->n_cut_backs()));
  context.summary.add(section, "most sub-steps in a step", static_cast<double>(most_substeps));
  if (constrained) {
    context.summary.add(section, "moving contacts", static_cast<double>(contacts_.size()));
    context.summary.add(section, "separations", separations);
    context.summary.add(section, "structure factorizations",
                        constrained->structure_factorizations());
    context.summary.add(section, "constraint solver",
                        parameters_->get<std::string>("Constraint solver"));
  } else {
    context.summary.add(section, "solver", system.last_solve().method);
  }
  context.summary.add(section, "backward error (last solve)", system.last_solve().backward_error);
  context.summary.add(section, "largest |numerical dissipation| / energy",
                      largest_dissipation / scale);
  context.summary.add(section, "time: assembly", assembly_seconds, "s");
  context.summary.add(section, "time: factorizations and solves", system.factor_seconds(), "s");
  context.summary.add(section, "time: stepping", stepping_seconds, "s");
  context.summary.add(section, "time per step", stepping_seconds / n_steps, "s");

  auto final_u = Teuchos::rcp(new TpetraVector(dofs.owned_map()));
  {
    auto data = final_u->getDataNonConst();
    std::copy(u.begin(), u.end(), data.getRawPtr());
  }
  model.set_field("displacement", final_u);
  model.set_field(context.step_name + "/displacement", final_u);
}

}  // namespace railfe
