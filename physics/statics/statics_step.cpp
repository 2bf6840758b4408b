#include "physics/statics/statics_step.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "framework/assembly/fe_matrix.hpp"
#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/output/exodus_writer.hpp"
#include "framework/output/field_gather.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/common/contact_tables.hpp"
#include "physics/common/node_set_stresses.hpp"
#include "physics/common/solid_assembly.hpp"
#include "physics/common/solid_beam_ties.hpp"
#include "physics/common/structural_assembly.hpp"
#include "physics/statics/contact_newton.hpp"

namespace railfe {

namespace {

// Sums of the x, y and z force components of a vector over the owned nodes of all ranks.
std::array<double, 3> component_sums(const TpetraVector& vector, const DofMap& dofs) {
  std::array<double, 3> sums{0, 0, 0};
  const auto data = vector.getData();
  for (LocalIndex node = 0; node < dofs.partition().n_owned_nodes(); ++node)
    for (int d = 0; d < 3; ++d)
      sums[d] += data[dofs.local_dof(node, d)];
  for (double& sum : sums)
    sum = dofs.partition().comm().sum(sum);
  return sums;
}

}  // namespace

StaticsStep::StaticsStep(const Teuchos::ParameterList& parameters) : parameters_(&parameters) {}

void StaticsStep::check(const CheckContext& context) {
  const Mesh& mesh = context.model.mesh();
  const std::string& deck = context.source();
  conditions_ = read_solid_conditions(*parameters_, deck, context.path);
  check_solid_conditions(conditions_, mesh, deck, context.path);
  const std::string step = "the statics step '" + context.step_name + "'";
  materials_ = solid_materials(context.model, step, EnhancedStrainSupport::supported);
  sections_.reset();
  dofs_per_node_ = 3;
  mixed_ = has_solid_blocks(mesh) && has_structural_blocks(mesh);
  if (has_structural_blocks(mesh)) {
    sections_ = structural_sections(context.model, step);
    if (mixed_)
      check_mixed_model(conditions_, mesh, deck, context.path);
    else
      check_structural_conditions(conditions_, deck, context.path);
    dofs_per_node_ = mixed_ ? 0 : 6;
  } else {
    refuse_rotations(conditions_, deck, context.path, "a model of solids");
    if (context.model.has_section("Sections"))  // checked, though nothing uses it
      structural_sections(context.model, step);
  }
  // Refused here, before any output.
  std::tie(links_, links_path_) =
      step_rigid_links(*parameters_, mesh, sections_.has_value(), deck, context.path);
  for (const auto& force : conditions_.nodal_forces) {
    bool attached = false;
    for (GlobalIndex node : mesh.node_set(force.node_set, deck, "").nodes) {
      attached = attached || context.model.partition().node_ranks()[node] >= 0;
    }
    if (!attached) {
      throw_input_error(deck, context.path + "/Nodal forces/" + force.name,
                        "node set '" + force.node_set + "' has no node attached to an element",
                        "nodes of the solid mesh");
    }
  }
  const auto& solid = parameters_->sublist("Solid");
  one_point_kappa_ = solid.get<std::string>("Integration") == "one point"
                         ? solid.get<double>("Hourglass coefficient")
                         : -1.0;
  if (one_point_kappa_ >= 0)
    for (int block = 0; block < static_cast<int>(mesh.blocks.size()); ++block)
      if (mesh.blocks[block].type == ElementType::hex8 &&
          materials_->of_block(block).element == SolidElement::enhanced_strain)
        throw_input_error(deck, context.path + "/Solid/Integration",
                          "is 'one point', but block '" + mesh.blocks[block].name +
                              "' has the enhanced-strain element (material '" +
                              materials_->of_block(block).name + "')",
                          "'full' with enhanced-strain materials, or Element 'full integration'");
  springs_ = read_node_set_springs(*parameters_, context.model.partition(), deck, context.path);
  contact_pairs_ = read_contact_pairs(*parameters_, deck, context.path, ContactUse::statics);
  if (sections_ && !mixed_ && !springs_.empty())
    throw_input_error(deck, context.path + "/Springs/" + springs_.front().name,
                      "acts on solid nodes, and the model has beams, springs and point masses",
                      "a spring-damper section on a one-node block (Sections) for springs to "
                      "the ground");
  if (sections_ && !contact_pairs_.empty())
    throw_input_error(deck, context.path + "/Contact pairs",
                      mixed_ ? "are not available yet on a model of solids with beams, springs "
                               "or point masses (mixed DOFs per node)"
                             : "needs solid (hex8) surfaces, and the model has none",
                      "no contact pairs on a model with beams, springs and point masses");
  check_contact_pairs(contact_pairs_, mesh, deck, context.path);
  if (contact_pairs_.empty()) {
    for (const char* name : {"Contact iterations", "Contact tolerance"})
      if (!parameters_->getEntry(name).isDefault())
        throw_input_error(deck, context.path + "/" + name,
                          "is used only with Contact pairs, and the step has none",
                          "remove it, or add a contact pair");
  }
  tie_pairs_.clear();
  for (const auto& tie : conditions_.ties) {
    tie_pairs_.push_back(pair_tied_nodes(tie, mesh, deck, context.path + "/Ties/" + tie.name));
  }
}

void StaticsStep::run(StepContext& context) {
  Model& model = context.model;
  const DofMap& dofs = mixed_ ? model.mesh_dofs() : model.dofs(dofs_per_node_);
  const Communicator& comm = model.comm();
  const std::string section = "Step " + context.step_name + " (statics)";
  RunSummary& summary = context.summary;

  // Each phase starts together on every rank, so its time is its own work, not waiting for a
  // slower rank to finish the previous one.
  Stopwatch clock;
  auto start_phase = [&] {
    comm.barrier();
    clock.restart();
  };
  start_phase();
  FeMatrix stiffness(dofs);
  const double graph_seconds = clock.seconds();
  start_phase();
  Progress assembly_progress =
      context.progress("stiffness assembly", dofs.partition().n_local_elements());
  if (mixed_) {  // solids and structural elements in one matrix
    stiffness.begin_assembly();
    add_elastic_stiffness(stiffness, *materials_, &assembly_progress, one_point_kappa_);
    add_structural_stiffness(stiffness, *sections_);
    stiffness.end_assembly();
  } else if (sections_) {
    assemble_structural_stiffness(stiffness, *sections_);
  } else {
    assemble_elastic_stiffness(stiffness, *materials_, &assembly_progress, one_point_kappa_);
  }
  Teuchos::RCP<TpetraMatrix> K = stiffness_with_springs(stiffness, springs_, dofs);
  assembly_progress.finish();
  const double assembly_seconds = clock.seconds();

  start_phase();
  auto forces = Teuchos::rcp(new TpetraVector(dofs.owned_map()));
  if (mixed_) {
    // The solids' loads, then the structural weight and every nodal force (with its moment).
    SolidConditions solid_loads = conditions_;
    solid_loads.nodal_forces.clear();
    assemble_solid_loads(solid_loads, *materials_, dofs, *forces);
    TpetraVector structural(dofs.owned_map());
    assemble_structural_loads(conditions_, *sections_, dofs, structural);
    forces->update(1.0, structural, 1.0);
  } else if (sections_) {
    assemble_structural_loads(conditions_, *sections_, dofs, *forces);
  } else {
    assemble_solid_loads(conditions_, *materials_, dofs, *forces);
  }
  const auto applied = component_sums(*forces, dofs);
  // An overflowing load (an extreme Density times Gravity, or a huge Total force) would end in a
  // solver message about restraints; say what it is instead.
  if (!std::isfinite(forces->norm1()))
    throw RunError(context.path +
                   ": the assembled load is not finite (NaN or inf): check "
                   "Gravity with the materials' Density, and every Total force, "
                   "Traction and Pressure for extreme values");
  TpetraVector original_forces(*forces, Teuchos::Copy);
  LinearConstraints constraints(dofs, context.source());
  add_rigid_links(links_, dofs, constraints, context.source(), links_path_);
  if (sections_ && !mixed_)
    add_structural_constraints(conditions_, dofs, constraints);
  else
    add_solid_constraints(conditions_, tie_pairs_, dofs, constraints);
  const double load_seconds = clock.seconds();

  const auto solver = create_linear_solver(parameters_->sublist("Linear solver"));
  auto u = Teuchos::rcp(new TpetraVector(dofs.owned_map()));
  comm.barrier();
  SolveReport report;
  std::unique_ptr<ContactPairs> contact;
  ContactNewtonReport newton;
  if (contact_pairs_.empty()) {
    const auto system = constraints.apply(K, *forces);
    Progress setup_progress = context.progress("solver set-up", 1);
    solver->setup(system, elasticity_traits(dofs));
    setup_progress.finish();
    Progress solve_progress = context.progress("linear solve", 1);
    solver->report_progress_to(&solve_progress);
    report = solver->solve(*forces, *u);
    solve_progress.finish();
    constraints.recover(*u);
  } else {
    contact = std::make_unique<ContactPairs>(contact_pairs_, dofs.partition(), *materials_,
                                             context.source(), context.path);
    // Masses only set the (unused) critical step; the penalty is the bulk-modulus form.
    const std::vector<double> unit_mass(dofs.partition().n_owned_nodes(), 1.0);
    std::vector<double> x(3 * static_cast<std::size_t>(dofs.partition().n_owned_nodes()));
    for (LocalIndex node = 0; node < dofs.partition().n_owned_nodes(); ++node)
      std::copy_n(dofs.partition().coordinates(node), 3, &x[3 * node]);
    const std::vector<double> zero(x.size(), 0.0);
    contact->initialise(unit_mass, 0, x.data(), zero.data());
    const int max_iterations = parameters_->get<int>("Contact iterations");
    Progress progress = context.iteration_progress("contact iterations", max_iterations);
    newton = solve_with_contact(
        K, original_forces, constraints, *solver, elasticity_traits(dofs), *contact, dofs,
        max_iterations, parameters_->get<double>("Contact tolerance"), context.path, *u, progress);
    progress.finish();
    report = newton.solve;
  }
  TpetraVector reactions(dofs.owned_map());
  constraints.reactions(*u, reactions);

  // Equilibrium: applied loads, reactions and spring forces must cancel; the work of loads and
  // reactions gives the strain energy (the springs' included).
  auto reaction_sum = component_sums(reactions, dofs);
  const auto spring_forces = node_set_spring_forces(springs_, dofs, *u);
  for (std::size_t s = 0; s < springs_.size(); ++s)
    for (int d = 0; d < 3; ++d)
      if (springs_[s].to_node_set.empty())  // the others are internal
        reaction_sum[d] += spring_forces[s][d];
  double imbalance = 0, scale = 0;
  for (int d = 0; d < 3; ++d) {
    imbalance += std::pow(applied[d] + reaction_sum[d], 2);
    scale = std::max({scale, std::abs(applied[d]), std::abs(reaction_sum[d])});
  }
  // Contact forces are internal: with them the reactions may cancel alone (a body pressed on
  // another between two held faces), and the error is measured against the contact force.
  if (contact)
    for (const PenaltyContactPair& pair : contact->pairs())
      scale = std::max(scale, std::abs(pair.totals().normal_force));
  // Without contact the work of loads and reactions; with it (K kept unmodified) ½ uᵀ K u.
  double strain_energy = 0.5 * (original_forces.dot(*u) + reactions.dot(*u));
  if (contact) {
    TpetraVector ku(dofs.owned_map());
    K->apply(*u, ku);
    strain_energy = 0.5 * ku.dot(*u);
  }

  const GlobalIndex n_elements = model.mesh().n_elements();
  summary.add(section, "degrees of freedom", static_cast<double>(dofs.n_global_dofs()));
  summary.add(section, "matrix entries", static_cast<double>(stiffness.n_global_entries()));
  summary.add(section, "prescribed DOFs", static_cast<double>(constraints.n_prescribed()));
  summary.add(section, "multi-point constraints", static_cast<double>(constraints.n_multipoint()));
  summary.add(section, "solver", report.method);
  summary.add(section, "iterations", report.iterations);
  summary.add(section, "relative residual", report.relative_residual);
  summary.add(section, "backward error", report.backward_error);
  summary.add(section, "strain energy", strain_energy, "J");
  if (contact) {
    summary.add(section, "contact pairs", static_cast<double>(contact_pairs_.size()));
    summary.add(section, "contact iterations", newton.iterations);
    if (newton.reused_factorizations > 0) {
      summary.add(section, "contact iterations with a new factorization", newton.factorizations);
      summary.add(section, "contact iterations by CG on an earlier factorization",
                  newton.reused_factorizations);
    }
    summary.add(section, "contact out-of-balance force (relative)", newton.residual);
    summary.add(section, "active slave nodes", static_cast<double>(newton.active));
    if (newton.line_searches > 0)
      summary.add(section, "contact steps shortened by the line search", newton.line_searches);
    if (newton.shortened_steps > 0)
      summary.add(section, "contact steps halved (they lifted every contact off)",
                  newton.shortened_steps);
  }
  summary.add(section, "equilibrium error |applied + reactions| / max",
              scale > 0 ? std::sqrt(imbalance) / scale : 0.0);
  summary.add(section, "time: sparsity graph", graph_seconds, "s");
  summary.add(section, "time: stiffness assembly", assembly_seconds, "s");
  summary.add(section, "assembly rate per rank",
              n_elements / comm.n_ranks() / std::max(assembly_seconds, 1e-9), "elements/s");
  summary.add(section, "time: loads and constraints", load_seconds, "s");
  summary.add(section, "time: solver setup", report.setup_seconds, "s");
  summary.add(section, "time: solve", report.solve_seconds, "s");

  start_phase();
  write_results(context, dofs, *u, reactions, contact.get());
  write_springs(context, spring_forces);
  if (contact)
    write_contact(context, *contact);
  summary.add(section, "time: output", clock.seconds(), "s");
  model.set_field("displacement", u);
  model.set_field(context.step_name + "/displacement", u);
}

namespace {

// Sum over the owned nodes of \p nodes of components 0..n-1 of \p data (those a node carries),
// over all ranks; with \p count, component n of the result counts the nodes with n components.
std::vector<double> node_set_sum(const DofMap& dofs, const std::vector<GlobalIndex>& nodes,
                                 const Teuchos::ArrayRCP<const double>& data, int n,
                                 bool count = false) {
  const MeshPartition& partition = dofs.partition();
  std::vector<double> sum(n + (count ? 1 : 0), 0.0);
  for (GlobalIndex node : nodes) {
    const LocalIndex local = partition.local_node(node);
    if (local < 0 || local >= partition.n_owned_nodes())
      continue;
    const int carried = std::min(n, dofs.dofs_of_node(local));
    for (int d = 0; d < carried; ++d)
      sum[d] += data[dofs.local_dof(local, d)];
    if (count && carried == n)
      sum[n] += 1;
  }
  for (double& value : sum)
    value = partition.comm().sum(value);
  return sum;
}

// The translations (3 per local node) of overlapping vector \p u_overlap over \p dofs: what the
// solid stress recovery reads, whatever the layout.
std::vector<double> node_translations(const DofMap& dofs, const double* u_overlap) {
  const LocalIndex n = dofs.partition().n_local_nodes();
  std::vector<double> translations(3 * static_cast<std::size_t>(n));
  for (LocalIndex node = 0; node < n; ++node)
    for (int d = 0; d < 3; ++d)
      translations[3 * node + d] = u_overlap[dofs.local_dof(node, d)];
  return translations;
}

}  // namespace

void StaticsStep::write_probes(StepContext& context, const DofMap& dofs, const TpetraVector& u,
                               const double* u_overlap) const {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  const Communicator& comm = partition.comm();
  std::vector<std::vector<GlobalIndex>> probe_sets;
  for (const auto& probe : conditions_.probes)
    probe_sets.push_back(mesh.node_set(probe.node_set, "", "").nodes);
  // Beams report their rotations (the mean over the set's nodes that carry them); solids the
  // stresses extrapolated to the nodes; a mixed model both.
  std::vector<double> probe_stresses;
  std::vector<std::string> columns{"probe", "nodes", "ux_m", "uy_m", "uz_m"};
  if (sections_)
    columns.insert(columns.end(), {"rx_rad", "ry_rad", "rz_rad"});
  if (!sections_ || mixed_) {
    probe_stresses =
        node_set_stresses(partition, *materials_, u_overlap, probe_sets, one_point_kappa_ >= 0);
    columns.insert(columns.end(), {"sxx_Pa", "syy_Pa", "szz_Pa", "sxy_Pa", "syz_Pa", "szx_Pa"});
  }
  CsvWriter probes(context.output.staging_path(context.step_name + "_probes.csv"), columns,
                   comm.is_root());
  for (std::size_t p = 0; p < conditions_.probes.size(); ++p) {
    long long count = 0;
    for (GlobalIndex node : probe_sets[p]) {
      const LocalIndex local = partition.local_node(node);
      count += local >= 0 && local < partition.n_owned_nodes();
    }
    const double total = static_cast<double>(comm.sum(count));
    const int n = sections_ ? 6 : 3;
    const auto sum = node_set_sum(dofs, probe_sets[p], u.getData(), n, true);
    std::vector<std::string> row{conditions_.probes[p].name,
                                 std::to_string(static_cast<long long>(total))};
    for (int c = 0; c < n; ++c) {
      const double nodes = c < 3 ? total : sum[n];  // rotations: the nodes that carry them
      row.push_back(CsvWriter::format(nodes > 0 ? sum[c] / nodes : 0.0));
    }
    for (std::size_t c = 0; !probe_stresses.empty() && c < 6; ++c)
      row.push_back(CsvWriter::format(probe_stresses[6 * p + c]));
    probes.write_row(row);
  }
}

void StaticsStep::write_results(StepContext& context, const DofMap& dofs, const TpetraVector& u,
                                const TpetraVector& reactions, const ContactPairs* contact) const {
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  const Communicator& comm = partition.comm();
  const bool root = comm.is_root();
  const std::string& name = context.step_name;

  const auto u_data = u.getData();
  const auto r_data = reactions.getData();
  const LocalIndex n_owned = partition.n_owned_nodes();

  TpetraVector u_overlap(dofs.overlap_map());
  dofs.owned_to_overlap(u, u_overlap);
  const double* u_local = u_overlap.getData().getRawPtr();
  std::vector<double> translations;  // 3 per node, for the solids' stresses on a mixed map
  if (mixed_) {
    translations = node_translations(dofs, u_local);
    u_local = translations.data();
  }
  write_probes(context, dofs, u, u_local);

  std::vector<std::string> reaction_columns{"condition", "node_set", "Fx_N", "Fy_N", "Fz_N"};
  if (sections_)
    reaction_columns.insert(reaction_columns.end(), {"Mx_Nm", "My_Nm", "Mz_Nm"});
  CsvWriter reaction_file(context.output.staging_path(name + "_reactions.csv"), reaction_columns,
                          root);
  for (const auto& condition : conditions_.displacements) {
    const auto sum = node_set_sum(dofs, mesh.node_set(condition.node_set, "", "").nodes, r_data,
                                  sections_ ? 6 : 3);
    std::vector<std::string> row{condition.name, condition.node_set};
    for (double value : sum)
      row.push_back(CsvWriter::format(value));
    reaction_file.write_row(row);
  }

  if (!context.model.deck().parameters->sublist("Output").get<bool>("Exodus"))
    return;
  const auto stresses = element_stresses(partition, *materials_, u_local);
  std::vector<double> element_values;
  element_values.reserve(7 * stresses.size() / 6);
  for (std::size_t e = 0; e < stresses.size() / 6; ++e) {
    const double* s = &stresses[6 * e];
    element_values.insert(element_values.end(), s, s + 6);
    const double von_mises = std::sqrt(
        0.5 * (std::pow(s[0] - s[1], 2) + std::pow(s[1] - s[2], 2) + std::pow(s[2] - s[0], 2)) +
        3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
    element_values.push_back(von_mises);
  }
  std::vector<std::string> nodal_names{"displacement_x", "displacement_y", "displacement_z",
                                       "reaction_x",     "reaction_y",     "reaction_z"};
  if (sections_)
    nodal_names.insert(nodal_names.end(), {"rotation_x", "rotation_y", "rotation_z", "moment_x",
                                           "moment_y", "moment_z"});
  const int base = static_cast<int>(nodal_names.size());
  const int contact_width = contact ? static_cast<int>(contact_nodal_field_names().size()) : 0;
  const int width = base + contact_width;
  std::vector<double> owned(static_cast<std::size_t>(width) * n_owned, 0.0);
  for (LocalIndex node = 0; node < n_owned; ++node)
    for (int d = 0; d < 3; ++d) {
      owned[width * node + d] = u_data[dofs.local_dof(node, d)];
      owned[width * node + 3 + d] = r_data[dofs.local_dof(node, d)];
      if (sections_ && dofs.dofs_of_node(node) == 6) {  // rotations where they exist
        owned[width * node + 6 + d] = u_data[dofs.local_dof(node, 3 + d)];
        owned[width * node + 9 + d] = r_data[dofs.local_dof(node, 3 + d)];
      }
    }
  if (contact) {
    add_contact_nodal_fields(*contact, owned, width, base);
    nodal_names.insert(nodal_names.end(), contact_nodal_field_names().begin(),
                       contact_nodal_field_names().end());
  }
  const auto nodal = gather_node_field(partition, owned, width);
  const auto element = gather_element_field(partition, element_values, 7);

  ExodusWriter writer(
      context.output.staging_path(name + ".exo"), mesh,
      context.model.deck().parameters->get<std::string>("Title"), nodal_names,
      {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx", "von_mises"},
      root);
  writer.write_step(1.0, nodal, element);
  writer.close();
}

void StaticsStep::write_springs(StepContext& context,
                                const std::vector<std::array<double, 3>>& forces) const {
  if (springs_.empty())
    return;
  CsvWriter file(context.output.staging_path(context.step_name + "_springs.csv"),
                 {"spring", "Fx_N", "Fy_N", "Fz_N"}, context.model.comm().is_root());
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    file.write_row({springs_[s].name, CsvWriter::format(forces[s][0]),
                    CsvWriter::format(forces[s][1]), CsvWriter::format(forces[s][2])});
  }
}

void StaticsStep::write_contact(StepContext& context, const ContactPairs& contact) const {
  const bool root = context.model.comm().is_root();
  for (const PenaltyContactPair& pair : contact.pairs()) {
    const std::string stem = context.step_name + "_contact_" + pair.settings().name;
    CsvWriter totals(context.output.staging_path(stem + ".csv"), contact_history_columns(), root);
    totals.write_row(contact_history_row(0, pair));
    CsvWriter patch(context.output.staging_path(stem + "_patch.csv"), contact_patch_columns(),
                    root);
    for (const auto& row : contact_patch_rows(0, pair, contact))
      patch.write_row(row);
  }
}

}  // namespace railfe
