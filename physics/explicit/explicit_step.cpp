#include "physics/explicit/explicit_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <sstream>

#include "framework/assembly/dof_map.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/explicit/checkpoint.hpp"
#include "physics/explicit/contact_output.hpp"
#include "physics/explicit/explicit_output.hpp"
#include "physics/explicit/explicit_solver.hpp"

namespace railfe {

namespace {

// "<who> added 3.2 kg to 800 elements, 75 % of the model's mass: it changes the dynamics (lower
// <whose> Mass scaling step)": mass scaling that adds more than 1 % of the model's mass changes
// its dynamics, not only its step.
std::string added_mass_warning(const std::string& who, double added, long long count,
                               const std::string& what, double total_mass,
                               const std::string& whose) {
  std::ostringstream text;
  text.precision(3);
  text << who << " added " << added << " kg to " << count << " " << what << ", "
       << 100 * added / total_mass << " % of the model's mass: it changes the dynamics (lower "
       << whose << " Mass scaling step)";
  return text.str();
}

std::string mass_scaling_warning(const ExplicitSolver& solver) {
  return added_mass_warning("Mass scaling step", solver.mass_scaling().added_mass,
                            solver.mass_scaling().scaled_elements, "elements", solver.total_mass(),
                            "the");
}

// A warning for each contact pair whose Mass scaling step added over 1 % of the model's mass,
// "" where none did.
std::string contact_mass_scaling_warning(const ExplicitSolver& solver) {
  std::string text;
  const auto& scaling = solver.contact().mass_scaling();
  for (std::size_t p = 0; p < scaling.size(); ++p)
    if (scaling[p].added_mass > 0.01 * solver.total_mass())
      text += (text.empty() ? "" : "; ") +
              added_mass_warning(
                  "contact pair '" + solver.contact().specs()[p].name + "': Mass scaling step",
                  scaling[p].added_mass, scaling[p].nodes, "nodes", solver.total_mass(), "its");
  return text;
}

std::string seconds_text(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value << " s";
  return text.str();
}

// The blow-up message: where the run failed, how, and what the step was: \p dt the step asked
// for (not one cut short at the End time), \p stable_step and \p location the limit at the start
// and what set it (what sets it later may be the blow-up itself). \p recorder is null when the
// forces themselves failed (non-finite, or elements turned inside out). A contact pair is named
// even when the solids set the limit: its 2 sqrt(m / k) leaves out the elements that hold its
// nodes, so a pair just above the limit can still set off the blow-up.
std::string blow_up_message(const ExplicitSolver& solver, const ExplicitRecorder* recorder,
                            double dt, double stable_step, const std::string& location,
                            const ExplicitSettings& settings) {
  std::ostringstream text;
  text.precision(4);
  text << "the solution is growing without bound at t = " << solver.time() << " s (step "
       << solver.n_steps() << "): ";
  if (recorder) {
    const EnergyBalance& balance = recorder->last_balance();
    text << "the energy balance failed, energy error " << balance.error << " beyond the limit "
         << settings.energy_error_limit;
    if (recorder->beyond_stable_step())
      text << " at a step above the stable limit";
    else
      text << " and the stored and dissipated energy " << recorder->energy_growth()
           << " x the energy put in, beyond the growth limit " << settings.energy_growth_limit;
    text << " (kinetic " << balance.kinetic << " J, internal " << balance.internal << " J, contact "
         << balance.contact << " J, damping " << balance.damping << " J, friction "
         << balance.friction << " J, external work " << balance.external_work << " J)";
  } else {
    text << "the energy balance failed with non-finite forces or inverted elements";
  }
  text << ". The step " << dt << " s is " << dt / stable_step << " x the stable step "
       << stable_step << " s at the start, set by " << location;
  const ContactPairs& contact = solver.contact();
  if (!contact.empty() && location.find("contact pair") == std::string::npos)
    text << "; contact pair '" << contact.critical_pair() << "' allows " << contact.stable_step()
         << " s (" << dt / contact.stable_step()
         << " x), a 2 sqrt(m / k) that leaves out the elements holding its nodes";
  text << "; nothing after this point was written";
  return text.str();
}

// Throws RunError when a fixed \p step exceeds the stable \p limit set at \p location.
void refuse_unstable_step(double step, double limit, const std::string& location,
                          const std::string& deck, const std::string& path) {
  if (step <= limit * (1 + 1e-12))
    return;
  std::ostringstream problem;
  problem.precision(6);
  problem << deck << ": " << path << "/Time step: " << step << " s is above the stable limit "
          << limit << " s (" << step / limit << " x; set by " << location
          << "); use a step up to the limit, 0 for automatic (Safety factor x limit), or "
             "Allow unstable step true to study the instability";
  throw RunError(problem.str());
}

// A cheap lower estimate of the stable step before anything is assembled: the shortest element
// edge over the fastest dilatational wave speed. It only has to be good to a factor of two for
// the step budget; the run itself uses the exact limit.
double estimated_stable_step(const Mesh& mesh, const MaterialTable& materials) {
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const ElasticMaterial& m = materials.of_block(static_cast<int>(b));
    const double nu = m.poisson;
    const double speed = std::sqrt(m.young * (1 - nu) / (m.density * (1 + nu) * (1 - 2 * nu)));
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      double shortest = std::numeric_limits<double>::infinity();
      for (const auto& edge : edges) {
        const double* a = &mesh.coordinates[3 * static_cast<std::size_t>(nodes[edge[0]])];
        const double* c = &mesh.coordinates[3 * static_cast<std::size_t>(nodes[edge[1]])];
        shortest = std::min(shortest, std::hypot(a[0] - c[0], a[1] - c[1], a[2] - c[2]));
      }
      step = std::min(step, shortest / speed);
    }
  }
  return step;
}

}  // namespace

ExplicitStep::ExplicitStep(const Teuchos::ParameterList& parameters) : parameters_(&parameters) {}

void ExplicitStep::check(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  settings_ = read_explicit_settings(*parameters_, deck, context.path);
  check_explicit_settings(*settings_, mesh, deck, context.path);
  materials_ = solid_materials(context.model, "the explicit step '" + context.step_name + "'");
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (mesh.blocks[b].type != ElementType::hex8)
      throw_input_error(deck, "Mesh",
                        "block '" + mesh.blocks[b].name + "' holds " +
                            element_type_name(mesh.blocks[b].type) +
                            " elements, which the explicit module does not take",
                        "hex8 blocks; masses, rigid bodies and springs go under " + context.path +
                            "/Discrete parts");
    if (!(materials_->of_block(static_cast<int>(b)).density > 0))
      throw_input_error(deck, "Materials", "block '" + mesh.blocks[b].name + "' has no density",
                        "a positive Density for every block of an explicit step");
  }
  // A run that would take more steps than the budget is refused before anything runs, with the
  // figures (End time 2e9 s, or a step of 1e-148 s from a modulus of 1e308).
  const double step_estimate =
      settings_->time_step > 0
          ? settings_->time_step
          : settings_->safety_factor * estimated_stable_step(mesh, *materials_);
  const double steps_needed = settings_->end_time / step_estimate;
  if (!(steps_needed <= settings_->maximum_steps)) {
    std::ostringstream problem;
    problem.precision(3);
    problem << "End time " << settings_->end_time << " s at a step of about " << step_estimate
            << " s needs about " << steps_needed << " steps, more than Maximum steps "
            << settings_->maximum_steps;
    throw_input_error(deck, context.path + "/End time", problem.str(),
                      "a shorter End time, a larger Maximum steps, or material constants and a "
                      "mesh that allow a larger step");
  }
  // Within the budget a run can still take days: say so before it starts, not after. 0.2 us
  // per element-step is this kernel's cost on one core (docs/benchmarks.md), a lower bound.
  const double element_steps = steps_needed * static_cast<double>(mesh.n_elements());
  estimated_hours_ = element_steps * 0.2e-6 / context.model.comm().n_ranks() / 3600;
  if (estimated_hours_ > 24 && context.model.comm().is_root())
    std::fprintf(stderr,
                 "railfe: warning: %s: about %.3g steps of %.3g elements will take at least %.3g "
                 "hours; shorten End time or coarsen the mesh if that is not intended\n",
                 context.path.c_str(), steps_needed, static_cast<double>(mesh.n_elements()),
                 estimated_hours_);
  if (!settings_->start_from.empty()) {
    if (!is_earlier_statics_step(context.model.deck().parameters->sublist("Steps"),
                                 settings_->start_from, context.step_name))
      throw_input_error(deck, context.path + "/Start from",
                        "names '" + settings_->start_from + "', which is no earlier statics step",
                        "the name of a statics step listed before this one");
  }
}

void ExplicitStep::run(StepContext& context) {
  Model& model = context.model;
  const std::string& deck = context.source();
  const std::string& path = context.path;
  const ExplicitSettings& settings = *settings_;
  const Communicator& comm = model.comm();
  const std::string section = "Step " + context.step_name + " (explicit)";
  Stopwatch clock;
  const DofMap& dofs = model.dofs(3);
  ExplicitSolver solver(settings, dofs, *materials_, deck, path);
  const double setup_seconds = clock.seconds();

  const double* start = nullptr;
  Teuchos::RCP<TpetraVector> preload;
  if (!settings.start_from.empty()) {
    preload = model.field(settings.start_from + "/displacement");
    if (preload.is_null())
      throw RunError(path + ": the statics step '" + settings.start_from +
                     "' left no displacement to start from");
    start = preload->getData().getRawPtr();
  }
  // A checkpoint is read before the start is set up: the solver takes the step calibration of the
  // run that wrote it, so a deck that resumes it from another start state steps as that run did.
  const std::string checkpoint_path = context.output.path() + "/" + context.step_name +
                                      ".checkpoint." + std::to_string(comm.rank());
  CheckpointSections checkpoint;
  if (settings.restart && checkpoint_exists(checkpoint_path, comm)) {
    checkpoint = read_checkpoint(checkpoint_path, comm.n_ranks());
    if (checkpoint.size() != 4)
      throw RunError("the checkpoint '" + checkpoint_path + "' has the wrong layout");
    solver.preset_step_calibration(ExplicitSolver::checkpointed_step_calibration(checkpoint[0]));
  }
  solver.initialise(start);
  // total_mass() is collective: every rank builds the text, the root prints it.
  const std::string mass_warning = solver.mass_scaling().added_mass > 0.01 * solver.total_mass()
                                       ? mass_scaling_warning(solver)
                                       : "";
  if (!mass_warning.empty() && comm.is_root())
    std::fprintf(stderr, "railfe: warning: %s: %s\n", path.c_str(), mass_warning.c_str());
  const std::string contact_mass_warning = contact_mass_scaling_warning(solver);
  if (!contact_mass_warning.empty() && comm.is_root())
    std::fprintf(stderr, "railfe: warning: %s: %s\n", path.c_str(), contact_mass_warning.c_str());
  const double initial_stable_step = solver.stable_step();
  if (!(initial_stable_step > 0) || !std::isfinite(initial_stable_step))
    throw RunError(path + ": no stable step could be found (degenerate elements or no mass?)");
  const std::string initial_location = solver.critical_location();
  const bool fixed_step = settings.time_step > 0;
  // A stiff contact can set a step far below the solids' one, which only the assembled model
  // knows: the budget is checked again here, before the first step (like an unstable step).
  if (!fixed_step) {
    const double steps_needed = settings.end_time / (settings.safety_factor * initial_stable_step);
    if (!(steps_needed <= settings.maximum_steps)) {
      std::ostringstream problem;
      problem.precision(3);
      problem << deck << ": " << path << "/End time: End time " << settings.end_time
              << " s at the step " << settings.safety_factor * initial_stable_step << " s set by "
              << solver.critical_location() << " needs about " << steps_needed
              << " steps, more than Maximum steps " << settings.maximum_steps
              << "; use a shorter End time, a larger Maximum steps, or a smaller Penalty factor";
      throw RunError(problem.str());
    }
  }
  // The limit needs the assembled model (its global estimate), so it is checked here.
  if (fixed_step && !settings.allow_unstable_step)
    refuse_unstable_step(settings.time_step, initial_stable_step, initial_location, deck, path);

  ExplicitRecorder recorder(settings, solver, dofs.partition(), context.output, context.step_name,
                            model.deck().parameters->get<std::string>("Title"),
                            model.deck().parameters->sublist("Output").get<bool>("Exodus"));
  const bool restarted = !checkpoint.empty();
  if (restarted) {
    solver.restore({checkpoint[0], checkpoint[1], checkpoint[2]});
    recorder.restore(checkpoint[3]);
  } else {
    if (!recorder.record(true))
      throw RunError(path + ": the initial state has a non-finite energy");
    recorder.snapshot(false);
  }

  Progress progress = context.progress("time", settings.end_time);
  if (restarted)
    progress.start_at(solver.time());
  Stopwatch loop_clock;
  const std::clock_t loop_cpu_start = std::clock();
  const long long first_step = solver.n_steps();
  double nominal = 0;  // the step asked for, before the last one is cut to the End time
  while (solver.time() < settings.end_time * (1 - 1e-12)) {
    nominal = fixed_step ? settings.time_step : settings.safety_factor * solver.stable_step();
    double dt = nominal;
    const double remaining = settings.end_time - solver.time();
    if (dt > remaining || remaining - dt < 1e-6 * dt)
      dt = remaining;
    solver.step(dt);
    if (!(solver.stable_step() > 0) || !std::isfinite(solver.stable_step()))
      throw RunError(path + ": " +
                     blow_up_message(solver, nullptr, nominal, initial_stable_step,
                                     initial_location, settings));
    // A step that has shrunk a thousandfold means elements are being crushed (a prescribed
    // motion or load far beyond the model): the run would crawl on without end.
    if (!fixed_step && solver.stable_step() < 1e-3 * initial_stable_step)
      throw RunError(path + ": the stable step fell to " + seconds_text(solver.stable_step()) +
                     ", below 1/1000 of its start value " + seconds_text(initial_stable_step) +
                     ", at t = " + seconds_text(solver.time()) +
                     ": elements are being crushed; check the prescribed motions and loads for "
                     "values far beyond the model");
    if (!recorder.record(false))
      throw RunError(path + ": " +
                     blow_up_message(solver, &recorder, nominal, initial_stable_step,
                                     initial_location, settings));
    recorder.snapshot(false);
    const long long n = solver.n_steps();
    if (settings.checkpoint_interval > 0 && n % settings.checkpoint_interval == 0) {
      const SolverState state = solver.state();
      write_checkpoint(checkpoint_path, comm.n_ranks(),
                       {state.scalars, state.arrays, state.discrete, recorder.state()});
    }
    if (static_cast<double>(n) >= settings.maximum_steps &&
        solver.time() < settings.end_time * (1 - 1e-12))
      throw RunError(path + ": reached Maximum steps (" + std::to_string(n) +
                     ") at t = " + seconds_text(solver.time()) + " of End time " +
                     seconds_text(settings.end_time) +
                     "; the stable step shrank as the mesh deformed, or the budget is too small");
    if (settings.stop_after_steps > 0 && n - first_step >= settings.stop_after_steps)
      throw RunError(path + ": stopped after " + std::to_string(settings.stop_after_steps) +
                     " steps as Checkpoint/Stop after steps asks; resume with Checkpoint/Restart "
                     "true");
    progress.update(solver.time());
  }
  progress.finish();
  const double loop_seconds = loop_clock.seconds();
  // Processor time of this rank (root's figure in the summary): fairer than wall time on a
  // shared machine.
  const double loop_cpu_seconds =
      static_cast<double>(std::clock() - loop_cpu_start) / CLOCKS_PER_SEC;
  if (!recorder.record(true))
    throw RunError(path + ": " +
                   blow_up_message(solver, &recorder, nominal, initial_stable_step,
                                   initial_location, settings));
  recorder.snapshot(true);
  recorder.finish();

  RunSummary& summary = context.summary;
  const Mesh& mesh = model.mesh();
  const long long steps_taken = solver.n_steps() - first_step;
  const double element_steps =
      static_cast<double>(mesh.n_elements()) * static_cast<double>(std::max(1LL, steps_taken));
  summary.add(section, "elements", static_cast<double>(mesh.n_elements()));
  summary.add(section, "nodes", static_cast<double>(dofs.partition().n_active_nodes()));
  summary.add(section, "rigid bodies", static_cast<double>(settings.bodies.size()));
  summary.add(section, "spring-dampers", static_cast<double>(settings.springs.size()));
  summary.add(section, "total mass", solver.total_mass(), "kg");
  if (settings.mass_scaling_step > 0) {
    summary.add(section, "mass scaling: elements made heavier",
                static_cast<double>(solver.mass_scaling().scaled_elements));
    summary.add(section, "mass scaling: mass added", solver.mass_scaling().added_mass, "kg");
    if (!mass_warning.empty())
      summary.add(section, "warning", mass_warning);
  }
  summary.add(
      section, "formulation",
      std::string(settings.kernel.full_integration ? "hex8 full integration" : "hex8 one point") +
          ", total-Lagrangian St. Venant-Kirchhoff");
  summary.add(section, "stable step at start", initial_stable_step, "s");
  if (!settings.contact_pairs.empty()) {
    summary.add(section, "contact pairs", static_cast<double>(settings.contact_pairs.size()));
    summary.add(section, "solids' stable step at end", solver.solid_stable_step(), "s");
    summary.add(section, "contact critical step", solver.contact_stable_step(), "s");
    const auto& scaling = solver.contact().mass_scaling();
    for (std::size_t p = 0; p < scaling.size(); ++p) {
      if (!(scaling[p].step_before > 0))
        continue;
      const std::string name = "contact " + settings.contact_pairs[p].name + ": mass scaling: ";
      summary.add(section, name + "critical step before", scaling[p].step_before, "s");
      summary.add(section, name + "nodes made heavier", static_cast<double>(scaling[p].nodes));
      summary.add(section, name + "mass added", scaling[p].added_mass, "kg");
    }
    if (!contact_mass_warning.empty())
      summary.add(section, "warning", contact_mass_warning);
    for (const auto& [csv, png] : recorder.contact().patch_charts())
      draw_chart(context, section, "contact_patch_map.py", {csv, png});
    for (const std::string& warning : recorder.contact().summarise(summary, section)) {
      summary.add(section, "warning", warning);
      if (comm.is_root())
        std::fprintf(stderr, "railfe: warning: %s: %s\n", path.c_str(), warning.c_str());
    }
  }
  // A balance that failed without growing past the limit is not stopped: an undamped stable
  // step near its limit oscillates the measured energy (no warning), but dampers and friction
  // can also eat what an instability creates; then say so rather than pass the results off.
  const EnergyBalance& balance = recorder.last_balance();
  const double put_in = recorder.energy_put_in();
  const double dissipated = balance.damping + balance.friction;
  if (!(std::abs(balance.error) <= settings.energy_error_limit) &&
      dissipated > settings.energy_error_limit * put_in) {
    std::ostringstream warning;
    warning.precision(3);
    warning << "the energy balance did not close: energy error " << balance.error
            << " at the end, beyond the Energy error limit " << settings.energy_error_limit
            << ", while damping and friction dissipated " << dissipated / put_in
            << " x the energy put in: energy that an instability created may have been absorbed "
               "(stored and dissipated energy "
            << recorder.energy_growth() << " x, below the Energy growth limit "
            << settings.energy_growth_limit
            << ", so the run went on); check energy_error, and use a smaller step";
    if (!settings.contact_pairs.empty())
      warning << " or Penalty factor";
    summary.add(section, "warning", warning.str());
    if (comm.is_root())
      std::fprintf(stderr, "railfe: warning: %s: %s\n", path.c_str(), warning.str().c_str());
  }
  summary.add(section, "stable step set by", solver.critical_location());
  summary.add(section, "stable step calibration (Lanczos / L over c_P)", solver.step_calibration());
  summary.add(section, "step",
              fixed_step ? "fixed " + seconds_text(settings.time_step)
                         : "automatic, safety factor " + std::to_string(settings.safety_factor));
  summary.add(section, "steps", static_cast<double>(solver.n_steps()));
  if (estimated_hours_ > 24)
    summary.add(section, "warning",
                "estimated at least " + std::to_string(estimated_hours_) + " hours before it ran");
  if (restarted)
    summary.add(section, "resumed from checkpoint at step", static_cast<double>(first_step));
  summary.add(section, "energy error at end", recorder.last_balance().error);
  summary.add(section, "stored and dissipated energy / energy put in, at end",
              recorder.energy_growth());
  summary.add(section, "time: setup", setup_seconds, "s");
  summary.add(section, "time: stepping", loop_seconds, "s");
  summary.add(section, "time: stepping, CPU of rank 0", loop_cpu_seconds, "s");
  summary.add(section, "solid kernel", solid_kernel_name(settings.kernel));
  summary.add(section, "time per element-step (wall x ranks)",
              1e6 * loop_seconds * comm.n_ranks() / element_steps, "us");
  if (!settings.contact_pairs.empty()) {
    // Rank 0's share: every rank evaluates the whole contact, so it is the same on each.
    const double contact_seconds = solver.contact().seconds();
    std::size_t slaves = 0;
    for (const PenaltyContactPair& pair : solver.contact().pairs())
      slaves += pair.slaves().size();
    summary.add(section, "time: contact (exchange, search, forces)", contact_seconds, "s");
    summary.add(section, "contact share of stepping",
                contact_seconds / std::max(loop_seconds, 1e-9));
    summary.add(section, "slave nodes", static_cast<double>(slaves));
    summary.add(section, "contact time per slave node-step",
                1e9 * contact_seconds /
                    std::max(1.0, static_cast<double>(slaves) * static_cast<double>(steps_taken)),
                "ns");
  }
  summary.add(section, "peak memory per rank",
              static_cast<double>(peak_resident_bytes()) / 1048576.0, "MiB");
}

}  // namespace railfe
