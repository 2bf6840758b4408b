#include "physics/modal/modal_step.hpp"

#include <Teuchos_Array.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <tuple>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/mesh_parts.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/common/solid_beam_ties.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/common/structural_assembly.hpp"
#include "physics/modal/krylov_plan.hpp"
#include "physics/modal/mode_normalization.hpp"
#include "physics/modal/shift_invert.hpp"
#include "physics/modal/sturm_count.hpp"

namespace railfe {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// σ from the deck's signed shift frequency.
double shift_eigenvalue(double frequency) {
  const double omega = kTwoPi * frequency;
  return frequency < 0 ? -omega * omega : omega * omega;
}

double frequency_of(double eigenvalue) {
  const double f = std::sqrt(std::abs(eigenvalue)) / kTwoPi;
  return eigenvalue < 0 ? -f : f;
}

std::unique_ptr<LinearSolver> inner_solver(const std::string& method) {
  Teuchos::ParameterList list;
  validate_and_complete(list, *linear_solver_parameters().list(), "", "");
  list.set("Method", method);
  list.set("Preconditioner", std::string("muelu-sa"));
  list.set("Relative tolerance", 1e-12);
  return create_linear_solver(list);
}

// Sets each record's status; returns the number of failed or missing modes.
int judge_modes(const Teuchos::ParameterList& p, const ShiftInvertResult& result,
                std::vector<ModeRecord>& records) {
  const double residual_limit = p.get<double>("Backward error limit");
  const double orthogonality_limit = p.get<double>("Orthogonality limit");
  int n_failed = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    ModeRecord& record = records[i];
    std::ostringstream status;
    if (!(record.check.backward_error <= residual_limit)) {
      status << "failed: backward error " << record.check.backward_error;
    } else if (!(record.check.orthogonality <= orthogonality_limit)) {
      status << "failed: M-orthogonality defect " << record.check.orthogonality;
    } else if (record.rigid) {
      status << "ok (rigid-body mode)";
    } else if (record.shape.nodal_diameters >= 1 && record.check.partner < 0) {
      // A body of revolution has its n >= 1 modes in pairs; a lone one means the solver
      // missed its partner, unless the partner lies just above the last mode computed.
      if (i + 1 < records.size())
        status << "failed: doublet partner missing";
      else
        status << "ok (doublet partner above the last mode)";
    } else {
      status << "ok";
    }
    record.status = status.str();
    n_failed += record.status.rfind("failed", 0) == 0 ? 1 : 0;
  }
  if (!result.converged) {
    n_failed += std::max(0, result.n_requested - static_cast<int>(result.eigenvalues.size()));
  }
  return n_failed;
}

// Adds the modes of a continuation solve to \p result, keeping eigenvalues ascending.
void append_modes(ShiftInvertResult& result, const ShiftInvertResult& next) {
  const std::size_t n_old = result.eigenvalues.size(), n_new = next.eigenvalues.size();
  std::vector<std::pair<double, int>> order;  // (eigenvalue, column in old ++ new)
  for (std::size_t i = 0; i < n_old; ++i)
    order.emplace_back(result.eigenvalues[i], static_cast<int>(i));
  for (std::size_t i = 0; i < n_new; ++i)
    order.emplace_back(next.eigenvalues[i], static_cast<int>(n_old + i));
  std::sort(order.begin(), order.end());
  auto merged = Teuchos::rcp(new TpetraMultiVector(result.vectors->getMap(), n_old + n_new));
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int column = order[k].second;
    const auto source = column < static_cast<int>(n_old)
                            ? result.vectors->getVector(column)
                            : next.vectors->getVector(column - static_cast<int>(n_old));
    merged->getVectorNonConst(k)->update(1.0, *source, 0.0);
  }
  result.eigenvalues.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    result.eigenvalues[k] = order[k].first;
  result.vectors = merged;
  result.n_requested += next.n_requested;
  result.restarts += next.restarts;
  result.operator_applies += next.operator_applies;
  result.iteration_seconds += next.iteration_seconds;
  result.converged = next.converged;
}

// Replaces the modes of \p result by those of \p next, a solve of the whole band from scratch,
// keeping the counts of the work done before.
void replace_modes(ShiftInvertResult& result, const ShiftInvertResult& next) {
  const ShiftInvertResult before = result;
  result = next;
  result.restarts += before.restarts;
  result.operator_applies += before.operator_applies;
  result.iteration_seconds += before.iteration_seconds;
}

// Anasazi may return more converged pairs than asked for, and how many depends on the ranks:
// keep the \p n nearest the shift (ascending, as the result is), so runs agree.
void keep_nearest(ShiftInvertResult& result, int n, double shift) {
  const int n_found = static_cast<int>(result.eigenvalues.size());
  if (n_found <= n)
    return;
  std::vector<int> order(n_found);
  for (int i = 0; i < n_found; ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(result.eigenvalues[a] - shift) < std::abs(result.eigenvalues[b] - shift);
  });
  order.resize(n);
  std::sort(order.begin(), order.end());
  std::vector<double> eigenvalues;
  const std::vector<std::size_t> columns(order.begin(), order.end());
  for (int column : order)
    eigenvalues.push_back(result.eigenvalues[column]);
  result.eigenvalues = eigenvalues;
  result.vectors = result.vectors->subCopy(
      Teuchos::ArrayView<const std::size_t>(columns.data(), columns.size()));
}

// Compares the number of eigenvalues below a point just above \p highest (between it and the
// next returned eigenvalue) with the number returned there; returns the number missed.
int sturm_check(const TpetraMatrix& K, const TpetraMatrix& M,
                const std::vector<double>& eigenvalues, double highest, double rigid_limit,
                const std::string& section, RunSummary& summary) {
  // Rigid-body eigenvalues are round-off around 0: count from above the rigid-body limit.
  highest = std::max(highest, rigid_limit);
  double sigma = highest + 1e-4 * std::abs(highest);
  for (double lambda : eigenvalues) {
    if (lambda > highest) {
      sigma = std::min(sigma, 0.5 * (highest + lambda));
      break;
    }
  }
  const long long expected = count_eigenvalues_below(K, M, sigma);
  long long found = 0;
  for (double lambda : eigenvalues)
    found += lambda < sigma ? 1 : 0;
  summary.add(section,
              "Sturm check: eigenvalues below " + CsvWriter::format(frequency_of(sigma)) + " Hz",
              std::to_string(expected) + " exist, " + std::to_string(found) + " found");
  return static_cast<int>(std::max(0LL, expected - found));
}

}  // namespace

ModalStep::ModalStep(const Teuchos::ParameterList& parameters) : parameters_(&parameters) {}

int ModalStep::first_batch(long long free_dofs) const {
  const int modes = parameters_->get<int>("Modes");
  if (modes > 0)
    return modes;
  return parameters_->get<Teuchos::Array<double>>("Frequency band").empty()
             ? 10
             : automatic_first_batch(free_dofs);
}

std::vector<char> ModalStep::check_blocks_and_supports(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  const std::string& path = context.path;
  const auto& names = parameters_->get<Teuchos::Array<std::string>>("Blocks");
  block_names_.assign(names.begin(), names.end());
  block_mesh_.reset();
  std::string kept = "the mesh";
  if (!block_names_.empty()) {
    std::vector<int> blocks;
    kept = "the Blocks {";
    for (const std::string& name : block_names_) {
      blocks.push_back(mesh.block_index(name, deck, path + "/Blocks"));
      kept += (blocks.size() > 1 ? ", " : "") + name;
    }
    kept += "}";
    block_mesh_ = std::make_unique<Mesh>(mesh_of_blocks(mesh, blocks));
  }
  const std::vector<char> active = used_nodes(block_mesh_ ? *block_mesh_ : mesh);

  supports_.clear();
  const std::vector<int> node_dofs =  // a rotation needs a node that carries one
      mixed_ ? DofMap::mesh_node_dofs(mesh) : std::vector<int>(mesh.n_nodes(), 6);
  const auto& supports = parameters_->sublist("Supports");
  for (auto it = supports.begin(); it != supports.end(); ++it) {
    const std::string name = supports.name(it);
    const auto& list = supports.sublist(name);
    const std::string where = path + "/Supports/" + name;
    const auto letters = list.get<std::string>("Components");
    ModalSupport support{name, list.get<std::string>("Node set"),
                         sections_ ? parse_components(letters, deck, where + "/Components")
                                   : parse_translations(letters, deck, where + "/Components")};
    const auto& nodes = mesh.node_set(support.node_set, deck, where + "/Node set").nodes;
    const bool rotation = std::any_of(support.components.begin(), support.components.end(),
                                      [](int c) { return c >= 3; });
    for (GlobalIndex node : nodes)
      if (rotation && node_dofs[node] == 3)
        throw_input_error(deck, where + "/Components",
                          "fixes a rotation, and node " + std::to_string(node + 1) +
                              " of node set '" + support.node_set +
                              "' is a solid node with translations only",
                          "the letters x, y and z on solid nodes (rx, ry, rz on beam, spring "
                          "and point-mass nodes only)");
    if (std::none_of(nodes.begin(), nodes.end(), [&](GlobalIndex n) { return active[n]; })) {
      throw_input_error(
          deck, where + "/Node set",
          "node set '" + support.node_set + "' has no node in " + kept + ": it would fix nothing",
          "a node set on the elements the modal step computes");
    }
    supports_.push_back(support);
  }
  check_springs(context, active, kept);
  return active;
}

void ModalStep::check_springs(const CheckContext& context, const std::vector<char>& active,
                              const std::string& kept) {
  const std::string& deck = context.source();
  springs_ = read_node_set_springs(*parameters_, context.model.partition(), deck, context.path);
  if (sections_ && !mixed_ && !springs_.empty())
    throw_input_error(deck, context.path + "/Springs/" + springs_.front().name,
                      "acts on solid nodes, and the model has beams, springs and point masses",
                      "a spring-damper section on a one-node block (Sections) for springs to "
                      "the ground");
  for (const NodeSetSpring& spring : springs_) {
    for (const auto& [set, label] :
         {std::pair{spring.node_set, "Node set"}, std::pair{spring.to_node_set, "To node set"}}) {
      if (set.empty())
        continue;
      const auto& nodes = context.model.mesh().node_set(set, deck, "").nodes;
      // A node outside the Blocks carries no unknown, so its share would hold nothing.
      if (std::any_of(nodes.begin(), nodes.end(), [&](GlobalIndex n) { return !active[n]; }))
        throw_input_error(deck, context.path + "/Springs/" + spring.name + "/" + label,
                          "node set '" + set + "' has nodes outside " + kept,
                          "a node set on the elements the modal step computes");
    }
  }
}

const DofMap& ModalStep::step_dofs(Model& model) {
  if (!block_mesh_)
    return mixed_ ? model.mesh_dofs() : model.dofs(dofs_per_node_);
  if (!block_dofs_) {
    block_partition_ =
        std::make_unique<MeshPartition>(*block_mesh_, model.comm(), model.partition_method());
    block_dofs_ = std::make_unique<DofMap>(*block_partition_, 3);
  }
  return *block_dofs_;
}

void ModalStep::check_structural(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  const std::string step = "the modal step '" + context.step_name + "'";
  sections_.reset();
  dofs_per_node_ = 3;
  mixed_ = false;
  std::tie(links_, links_path_) =
      step_rigid_links(*parameters_, mesh, has_structural_blocks(mesh), deck, context.path);
  if (!has_structural_blocks(mesh)) {
    if (context.model.has_section("Sections"))  // checked, though nothing uses it
      structural_sections(context.model, step);
    return;
  }
  mixed_ = has_solid_blocks(mesh);  // 3 DOFs at solid nodes, 6 at the others
  if (mixed_)
    check_mixed_model(SolidConditions{}, mesh, deck, context.path);
  for (const char* name : {"Blocks", "Classification"}) {
    const bool given = std::string(name) == "Blocks"
                           ? !parameters_->get<Teuchos::Array<std::string>>("Blocks").empty()
                           : parameters_->sublist("Classification").get<bool>("Axisymmetric");
    if (given)
      throw_input_error(deck, context.path + "/" + name,
                        "is available for solid models only, and the model has beams, springs "
                        "and point masses",
                        "leave it out");
  }
  sections_ = structural_sections(context.model, step);
  dofs_per_node_ = mixed_ ? 0 : 6;
}

void ModalStep::check(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  const std::string& path = context.path;
  materials_ = solid_materials(context.model, "the modal step '" + context.step_name + "'",
                               EnhancedStrainSupport::supported);
  check_structural(context);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (materials_->has_material(static_cast<int>(b)) &&
        !(materials_->of_block(static_cast<int>(b)).density > 0)) {
      throw_input_error(deck, "Materials", "block '" + mesh.blocks[b].name + "' has no density",
                        "a positive Density for every block of a modal analysis");
    }
  }

  const auto& band = parameters_->get<Teuchos::Array<double>>("Frequency band");
  if (!band.empty() && !(band[0] < band[1])) {
    throw_input_error(deck, path + "/Frequency band", "low end is not below the high end",
                      "{low, high} with low < high (Hz)");
  }

  // Fixed DOFs carry no mass and no eigenvalue: every size limit counts the free ones, of the
  // nodes that carry unknowns (those the kept elements use).
  const std::vector<char> active = check_blocks_and_supports(context);
  // DOFs of each node (3 or 6 on a mixed map), fixed ones and those tied to a rigid link's
  // master, in six slots per node.
  const std::vector<int> node_dofs =
      mixed_ ? DofMap::mesh_node_dofs(mesh) : std::vector<int>(mesh.n_nodes(), dofs_per_node_);
  std::vector<char> fixed(6 * static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (const auto& support : supports_)
    for (GlobalIndex node : mesh.node_set(support.node_set, deck, path).nodes)
      for (int c : support.components)
        fixed[6 * static_cast<std::size_t>(node) + c] = active[node];
  for (const auto& link : links_)
    for (GlobalIndex node : link.slaves)
      for (int c = 0; c < node_dofs[node]; ++c)
        fixed[6 * static_cast<std::size_t>(node) + c] = active[node];
  const long long n_fixed = std::count(fixed.begin(), fixed.end(), 1);
  long long n_dofs = 0;
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node)
    n_dofs += active[node] ? node_dofs[node] : 0;
  // A free DOF without mass (a node on springs alone) gives no finite eigenvalue either; solid
  // nodes (3 DOFs) have the hex8 mass.
  massless_dofs_ = 0;
  if (sections_) {
    const std::vector<char> massless = massless_components(mesh, *sections_);
    for (std::size_t i = 0; i < fixed.size(); ++i)
      massless_dofs_ += active[i / 6] && node_dofs[i / 6] == 6 && !fixed[i] && massless[i];
  }
  free_dofs_ = n_dofs - n_fixed - massless_dofs_;
  if (free_dofs_ == 0) {
    throw_input_error(deck, path + "/Supports",
                      "fix every DOF of the model that has mass: nothing can vibrate",
                      "supports that leave some DOFs with mass free");
  }
  const KrylovPlan plan =
      plan_krylov_space(first_batch(free_dofs_), parameters_->get<int>("Block size"),
                        parameters_->get<int>("Krylov blocks"), free_dofs_, 0, 0,
                        parameters_->get<std::string>("Inner solver") == "cholmod");
  if (!plan.problem.empty()) {
    throw_input_error(
        deck, path + "/" + plan.parameter,
        plan.problem + " (" + std::to_string(n_dofs) + " DOFs, " + std::to_string(n_fixed) +
            " fixed" +
            (massless_dofs_ > 0 ? ", " + std::to_string(massless_dofs_) + " without mass"
                                : std::string()) +
            ")",
        plan.allowed);
  }

  const auto& classification = parameters_->sublist("Classification");
  classify_ = classification.get<bool>("Axisymmetric");
  const auto& origin = classification.get<Teuchos::Array<double>>("Axis origin");
  const auto& axis = classification.get<Teuchos::Array<double>>("Axis direction");
  const auto& web = classification.get<Teuchos::Array<double>>("Web radii");
  frame_.origin = {origin[0], origin[1], origin[2]};
  frame_.axis = {axis[0], axis[1], axis[2]};
  if (std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) == 0) {
    throw_input_error(deck, path + "/Classification/Axis direction", "is the zero vector",
                      "a non-zero direction, e.g. {0, 1, 0}");
  }
  classifier_.rim_fraction = classification.get<double>("Rim fraction");
  classifier_.web_inner_radius = web[0];
  classifier_.web_outer_radius = web[1];
  classifier_.dominance = classification.get<double>("Dominance");
  classifier_.family_dominance = classification.get<double>("Family dominance");
  classifier_.noise_fraction = classification.get<double>("Noise fraction");

  references_.clear();
  const auto& references = parameters_->sublist("References");
  for (auto it = references.begin(); it != references.end(); ++it) {
    const std::string name = references.name(it);
    const auto& list = references.sublist(name);
    references_.push_back({name, list.get<std::string>("Family"), list.get<int>("Nodal circles"),
                           list.get<int>("Nodal diameters"), list.get<double>("Frequency")});
  }
  if (!references_.empty() && !classify_) {
    throw_input_error(deck, path + "/References",
                      "needs classified modes to find the computed mode of each reference",
                      "Classification/Axisymmetric = true");
  }
}

Teuchos::RCP<TpetraMatrix> ModalStep::with_springs(FeMatrix& stiffness, const DofMap& dofs,
                                                   const StepContext& context) {
  if (springs_.empty())
    return stiffness.matrix();
  // Read again on the step's own partition (the Blocks'), whose DOFs the pairs index.
  springs_ = read_node_set_springs(*parameters_, dofs.partition(), context.source(), context.path);
  return stiffness_with_springs(stiffness, springs_, dofs);
}

void ModalStep::run(StepContext& context) {
  Model& model = context.model;
  const DofMap& dofs = step_dofs(model);
  const MeshPartition& partition = dofs.partition();
  const Communicator& comm = model.comm();
  const std::string section = "Step " + context.step_name + " (modal)";
  RunSummary& summary = context.summary;
  const Teuchos::ParameterList& p = *parameters_;

  Stopwatch clock;
  FeMatrix stiffness(dofs);
  FeMatrix mass(dofs);
  const bool lumped = p.get<std::string>("Mass") == "lumped";
  if (mixed_) {  // solids and structural elements in one matrix each
    stiffness.begin_assembly();
    add_elastic_stiffness(stiffness, *materials_);
    add_structural_stiffness(stiffness, *sections_);
    stiffness.end_assembly();
    mass.begin_assembly();
    add_mass(mass, *materials_, lumped);
    add_structural_mass(mass, *sections_, lumped);
    mass.end_assembly();
  } else if (sections_) {
    assemble_structural_stiffness(stiffness, *sections_);
    assemble_structural_mass(mass, *sections_, lumped);
  } else {
    assemble_elastic_stiffness(stiffness, *materials_);
    assemble_mass(mass, *materials_, lumped);
  }
  LinearConstraints constraints(dofs, context.source());
  for (const auto& support : supports_) {
    for (GlobalIndex node : model.mesh().node_set(support.node_set, "", "").nodes) {
      if (partition.node_ranks()[node] != comm.rank())
        continue;
      const LocalIndex local = partition.local_node(node);
      for (int c : support.components)
        constraints.prescribe(dofs.owned_map()->getGlobalElement(dofs.local_dof(local, c)), 0.0);
    }
  }
  add_rigid_links(links_, dofs, constraints, context.source(), links_path_);
  constraints.finalize();
  TpetraVector no_load(dofs.owned_map());
  const Teuchos::RCP<const TpetraMatrix> K =
      constraints.apply(with_springs(stiffness, dofs, context), no_load);
  // Tᵀ M T: a tied or linked node's inertia moves to its master.
  const Teuchos::RCP<const TpetraMatrix> M = constraints.constrained_mass(mass.matrix());
  const double assembly_seconds = clock.seconds();

  const auto inner = inner_solver(p.get<std::string>("Inner solver"));
  // Every returned eigenpair is checked against K and M below; checking each inner solve as
  // well would cost a third of the iterations.
  inner->check_solutions(false);
  Progress factor_progress = context.progress("factorization of K - sigma M", 1);
  const double shift = shift_eigenvalue(p.get<double>("Shift"));
  std::optional<ShiftInvertEigensolver> solver;
  try {
    solver.emplace(K, M, *inner, elasticity_traits(dofs), shift);
  } catch (const RunError& error) {
    if (p.get<std::string>("Inner solver") != "cholmod")
      throw;
    throw RunError(
        "the shift " + CsvWriter::format(p.get<double>("Shift")) +
        " Hz could not be used: K - sigma M must be positive definite for the "
        "Cholesky inner solver, so the shift must lie below the lowest natural "
        "frequency (negative for a free body, e.g. -1 Hz). CHOLMOD said: " +
        std::string(error.what()).substr(0, std::string(error.what()).find(": the model is")));
  }
  const ShiftInvertEigensolver& eigensolver = *solver;
  factor_progress.finish();

  const long long free_dofs = dofs.n_global_dofs() - constraints.n_prescribed() -
                              constraints.n_multipoint() - massless_dofs_;
  ShiftInvertSettings settings;
  settings.n_modes = first_batch(free_dofs);
  settings.block_size = p.get<int>("Block size");
  settings.krylov_blocks = p.get<int>("Krylov blocks");
  settings.maximum_restarts = p.get<int>("Maximum restarts");
  settings.tolerance = p.get<double>("Tolerance");
  settings.free_dofs = free_dofs;
  settings.allow_dense = p.get<std::string>("Inner solver") == "cholmod";
  const auto& band = p.get<Teuchos::Array<double>>("Frequency band");
  if (!band.empty())
    settings.minimum_space = band_space(settings.n_modes);
  ShiftInvertResult result;
  int batches = 1;
  std::string block_sizes, krylov_spaces;
  {
    Progress progress =
        context.progress("Krylov-Schur, " + std::to_string(settings.n_modes) + " modes", 1);
    result = eigensolver.solve(settings, &progress);
    if (band.empty())
      keep_nearest(result, settings.n_modes, shift);
    progress.finish();
    block_sizes = std::to_string(result.block_size);
    krylov_spaces = std::to_string(result.krylov_dimension);
  }
  // A band holds an unknown number of modes. The modes nearest the shift come first, so the
  // band is covered once the farthest found lies beyond both of its ends (or beyond the upper
  // end with the shift below the band). Until then: the second batch solves the whole band as
  // extrapolated from the first (krylov_plan.hpp) from scratch, in one Krylov space, as a deck
  // that knew the count would; should that still fall short, later batches continue
  // M-orthogonal to the modes found, in a space sized for the whole band.
  const auto band_covered = [&](const std::vector<double>& eigenvalues) {
    double reach = 0;
    for (double lambda : eigenvalues)
      reach = std::max(reach, std::abs(lambda - shift));
    return shift + reach > shift_eigenvalue(band[1]) &&
           (shift - reach < shift_eigenvalue(band[0]) || shift <= shift_eigenvalue(band[0]));
  };
  while (!band.empty() && result.converged && !result.complete && !result.eigenvalues.empty() &&
         !band_covered(result.eigenvalues)) {
    const long long n_found = static_cast<long long>(result.eigenvalues.size());
    std::vector<double> frequencies;
    for (double lambda : result.eigenvalues)
      frequencies.push_back(std::max(0.0, frequency_of(lambda)));
    const int block = std::max(1, settings.block_size);
    const int rest = next_band_batch(frequencies, band[1], std::max(8, block));
    // Measured on the wheel (128 modes below 10 kHz): 16 modes, then all 134 estimated from
    // scratch, take 66 + 416 operator applications; 118 more M-orthogonal to the 16 take as
    // many, but the deflated batch depends on the first batch's accuracy (one such run, after
    // a first batch in 80 vectors, failed the backward-error check on 111 of its modes).
    const bool from_scratch =
        batches == 1 && n_found + rest <= largest_batch(settings.block_size, free_dofs);
    settings.n_modes =
        from_scratch ? static_cast<int>(n_found) + rest
                     : std::min(rest, largest_batch(settings.block_size, free_dofs - n_found));
    settings.minimum_space =
        band_space(settings.n_modes + (from_scratch ? 0 : static_cast<int>(n_found)));
    if (settings.n_modes < 1 || batches >= kMaximumBandBatches) {
      throw RunError("Frequency band: the band up to " + CsvWriter::format(band[1]) +
                     " Hz holds more modes " + "than the model can resolve in " +
                     std::to_string(kMaximumBandBatches) + " batches with its " +
                     std::to_string(free_dofs) + " free DOFs (" + std::to_string(n_found) +
                     " found up to " + CsvWriter::format(frequency_of(result.eigenvalues.back())) +
                     " Hz); lower the upper end of the Frequency band or refine the mesh");
    }
    const long long first = from_scratch ? 1 : n_found + 1;
    Progress progress = context.progress("Krylov-Schur, modes " + std::to_string(first) + " to " +
                                             std::to_string(first - 1 + settings.n_modes),
                                         1);
    const ShiftInvertResult next =
        eigensolver.solve(settings, &progress,
                          from_scratch ? Teuchos::RCP<const TpetraMultiVector>()
                                       : Teuchos::RCP<const TpetraMultiVector>(result.vectors));
    block_sizes += ", " + std::to_string(next.block_size);
    krylov_spaces += ", " + std::to_string(next.krylov_dimension);
    if (from_scratch)
      replace_modes(result, next);
    else
      append_modes(result, next);
    progress.finish();
    ++batches;
  }

  if (!result.vectors.is_null())
    canonicalize_modes(
        result.eigenvalues, *result.vectors, *K, *M, *elasticity_traits(dofs).near_null_space,
        shift_eigenvalue(p.get<double>("Rigid-body limit")), p.get<double>("Doublet tolerance"));
  std::vector<ModeRecord> records;
  const auto checks = check_modes(
      *K, *M, result.eigenvalues,
      result.vectors.is_null() ? TpetraMultiVector(K->getDomainMap(), 1) : *result.vectors,
      rigid_translations(dofs), p.get<double>("Doublet tolerance"));
  std::vector<int> kept;
  for (std::size_t i = 0; i < result.eigenvalues.size(); ++i) {
    const double f = frequency_of(result.eigenvalues[i]);
    const bool rigid = std::abs(f) < p.get<double>("Rigid-body limit");
    const double f_band = rigid ? 0.0 : f;
    if (!band.empty() && (f_band < band[0] || f_band > band[1]))
      continue;
    ModeRecord record;
    record.rigid = rigid;
    record.eigenvalue = result.eigenvalues[i];
    // A rigid-body mode's computed frequency is round-off (its sign included); 0 is the answer.
    record.frequency = rigid ? 0.0 : f;
    record.check = checks[i];
    records.push_back(record);
    kept.push_back(static_cast<int>(i));
  }
  // Partners are indices into the returned set; renumber them into the kept set.
  for (auto& record : records) {
    const int partner = record.check.partner;
    const auto it = std::find(kept.begin(), kept.end(), partner);
    record.check.partner = it == kept.end() ? -1 : static_cast<int>(it - kept.begin());
  }
  Teuchos::RCP<TpetraMultiVector> modes;
  if (!records.empty()) {
    const std::vector<std::size_t> columns(kept.begin(), kept.end());
    modes = result.vectors->subCopy(
        Teuchos::ArrayView<const std::size_t>(columns.data(), columns.size()));
  }
  // The slaves of ties and rigid links follow their masters in the modes written out.
  for (std::size_t j = 0;
       !modes.is_null() && constraints.n_multipoint() > 0 && j < modes->getNumVectors(); ++j)
    constraints.recover(*modes->getVectorNonConst(j));
  if (classify_ && !modes.is_null())
    classify(dofs, *modes, records);
  for (auto& record : records) {
    if (record.rigid) {
      record.shape = ModeClass();
      record.shape.family = "rigid-body";
    }
  }
  int n_failed = judge_modes(p, result, records);
  if (p.get<bool>("Sturm check") && !records.empty())
    n_failed += sturm_check(*K, *M, result.eigenvalues, records.back().eigenvalue,
                            shift_eigenvalue(p.get<double>("Rigid-body limit")), section, summary);
  if (!result.converged) {
    summary.add(section, "warning",
                "Anasazi converged " + std::to_string(result.eigenvalues.size()) + " of " +
                    std::to_string(result.n_requested) + " modes");
  }

  if (!band.empty() && records.empty()) {
    // Not an error (a band may be empty by design), but an empty CSV must not pass unnoticed.
    const std::string warning =
        "no modes in [" + CsvWriter::format(band[0]) + ", " + CsvWriter::format(band[1]) +
        "] Hz (" + std::to_string(result.eigenvalues.size()) +
        " computed, all outside the band); " + context.step_name + "_modes.csv is empty";
    summary.add(section, "warning", warning);
    if (comm.is_root())
      std::fprintf(stderr, "railfe: warning: step '%s': %s\n", context.step_name.c_str(),
                   warning.c_str());
  }
  if (!block_names_.empty()) {
    std::string blocks;
    for (const std::string& name : block_names_)
      blocks += (blocks.empty() ? "" : ", ") + name;
    summary.add(section, "blocks", blocks);
  }
  summary.add(section, "degrees of freedom", static_cast<double>(dofs.n_global_dofs()));
  summary.add(section, "fixed DOFs", static_cast<double>(constraints.n_prescribed()));
  summary.add(section, "free DOFs", static_cast<double>(free_dofs));
  summary.add(section, "mass", p.get<std::string>("Mass"));
  summary.add(section, "eigensolver",
              result.complete ? result.inner_method : "Anasazi block Krylov-Schur, shift-invert");
  summary.add(section, "inner solver", p.get<std::string>("Inner solver"));
  summary.add(section, "shift", p.get<double>("Shift"), "Hz");
  summary.add(section, "modes requested", result.n_requested);
  summary.add(section, "modes converged", static_cast<double>(result.eigenvalues.size()));
  summary.add(section, "modes reported", static_cast<double>(records.size()));
  summary.add(section, "eigensolver batches", batches);
  summary.add(section, "block size", block_sizes);
  summary.add(section, "Krylov space", krylov_spaces);
  summary.add(section, "iterations", result.restarts);
  summary.add(section, "operator applications", static_cast<double>(result.operator_applies));
  summary.add(section, "modes failing checks", n_failed);
  double worst_residual = 0, worst_orthogonality = 0;
  for (const auto& record : records) {
    worst_residual = std::max(worst_residual, record.check.backward_error);
    worst_orthogonality = std::max(worst_orthogonality, record.check.orthogonality);
  }
  summary.add(section, "largest backward error", worst_residual);
  summary.add(section, "largest M-orthogonality defect", worst_orthogonality);
  summary.add(section, "time: assembly of K and M", assembly_seconds, "s");
  summary.add(section, "time: factorization", result.factor_seconds, "s");
  summary.add(section, "time: eigensolver iterations", result.iteration_seconds, "s");

  clock.restart();
  write_results(context, dofs, records, modes.get());
  if (!references_.empty())
    write_validation(context, records);
  if (p.get<bool>("Export matrices"))
    export_matrices(context, *K, *M);
  summary.add(section, "time: output", clock.seconds(), "s");

  if (n_failed > 0 && p.get<std::string>("On failed check") == "error") {
    // Name the parameter most likely at fault: unconverged modes want a longer or larger search,
    // failed checks of converged modes a tighter tolerance or a shift nearer to them.
    // A missing doublet partner is no numerical failure: the model is not a body of revolution
    // (a support off the axis, an uneven mesh), and tighter tolerances would not help.
    const auto partner_failures = std::count_if(records.begin(), records.end(), [](const auto& r) {
      return r.status == "failed: doublet partner missing";
    });
    const bool only_partners = partner_failures == n_failed;  // not a Sturm count or a missing mode
    const std::string advice =
        !result.converged
            ? "the eigensolver stopped after Maximum restarts = " +
                  std::to_string(settings.maximum_restarts) +
                  ": raise Maximum restarts or Krylov blocks (0 = automatic), or move the Shift "
                  "nearer the wanted modes"
        : only_partners
            ? "each lacks a doublet partner within the Doublet tolerance: the model is not a "
              "body of revolution (supports or mesh break the symmetry); raise the Doublet "
              "tolerance if it should be one"
            : "lower Tolerance, or move the Shift nearer the failing modes";
    throw RunError(std::to_string(n_failed) + " of " + std::to_string(records.size()) +
                   " modes failed their checks (see the status column of " + context.step_name +
                   "_modes.csv.part, kept as written); " + advice +
                   ", or set On failed check = warn to keep the results");
  }
}

}  // namespace railfe
