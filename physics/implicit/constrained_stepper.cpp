#include "physics/implicit/constrained_stepper.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cstdio>
#include <deque>
#include <memory>
#include <unordered_map>

#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/solvers/gathered_matrix.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"
#include "framework/time/coupled_system.hpp"
#include "framework/time/dense_system.hpp"
#include "framework/time/sparse_system.hpp"
#include "physics/implicit/beam_paths.hpp"
#include "physics/implicit/moving_contact.hpp"

namespace railfe {

struct ConstrainedStepper::Root {
  std::unique_ptr<GatheredMatrix> layout;  // gathered K: row order and the scatter plan
  std::vector<long> unknown_of_row;        // rank 0: structure 0..ns-1, vehicle ns.., −1 fixed
  std::unordered_map<GlobalIndex, long> row_of_global;
  std::size_t ns = 0, nv = 0;
  std::unique_ptr<Expression> scale;
  std::vector<double> load;  // F at scale 1 over the unknowns
  std::unique_ptr<MovingLoads> moving_loads;
  std::unique_ptr<SparseLinearSystem> structure;
  std::unique_ptr<LinearDenseSystem> vehicle;
  std::unique_ptr<CoupledSystem> coupled;
  std::unique_ptr<MovingContacts> contacts;
  std::unique_ptr<SaddlePointSolver> saddle;
  std::unique_ptr<HhtIntegrator> integrator;
  std::vector<double> u, v, a;
  std::vector<std::string> names;
};

namespace {

// Nodes joined to \p seeds by elements of any kind (the vehicles), as flags per mesh node.
std::vector<char> joined_nodes(const Mesh& mesh, const std::vector<GlobalIndex>& seeds) {
  std::vector<std::vector<GlobalIndex>> neighbours(mesh.n_nodes());
  for (const ElementBlock& block : mesh.blocks)
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      const int count = block.n_element_nodes(e);
      for (int i = 1; i < count; ++i) {
        neighbours[nodes[0]].push_back(nodes[i]);
        neighbours[nodes[i]].push_back(nodes[0]);
      }
    }
  std::vector<char> joined(mesh.n_nodes(), 0);
  std::deque<GlobalIndex> queue(seeds.begin(), seeds.end());
  for (GlobalIndex seed : seeds)
    joined[seed] = 1;
  while (!queue.empty()) {
    const GlobalIndex node = queue.front();
    queue.pop_front();
    for (GlobalIndex next : neighbours[node])
      if (!joined[next]) {
        joined[next] = 1;
        queue.push_back(next);
      }
  }
  return joined;
}

Eigen::SparseMatrix<double> empty_sparse(std::size_t n) {
  return Eigen::SparseMatrix<double>(static_cast<long>(n), static_cast<long>(n));
}

Irregularity irregularity_of(const MovingContactSpec& spec, const std::string& deck,
                             const std::string& where) {
  if (!spec.irregularity_file.empty())
    return Irregularity::from_csv(spec.irregularity_file);
  return Irregularity(function_of_x(spec.vertical_irregularity, deck, where),
                      function_of_x(spec.lateral_irregularity, deck, where));
}

}  // namespace

ConstrainedStepper::ConstrainedStepper(const ConstrainedSetup& setup)
    : setup_(setup), root_(std::make_unique<Root>()) {
  const DofMap& dofs = *setup.dofs;
  const MeshPartition& partition = dofs.partition();
  const Mesh& mesh = partition.mesh();
  const int per_node = dofs.dofs_per_node();
  Root& root = *root_;

  // The vehicles: every node joined by elements to a contact node (every rank: mesh is whole).
  std::vector<GlobalIndex> seeds;
  for (const MovingContactSpec& contact : *setup.contacts)
    seeds.push_back(mesh.node_set(contact.node_set, "", "").nodes.front());
  const std::vector<char> in_vehicle = joined_nodes(mesh, seeds);
  for (const MovingContactSpec& contact : *setup.contacts)
    for (const PathLink& link : chain_of_blocks(mesh, contact.blocks, setup.deck, ""))
      if (in_vehicle[link.a] || in_vehicle[link.b])
        throw_input_error(setup.deck, setup.path + "/Moving contacts/" + contact.name + "/Path",
                          "is joined by elements to the vehicle of the contact node (node " +
                              std::to_string((in_vehicle[link.a] ? link.a : link.b) + 1) + ")",
                          "a vehicle that touches its path only through Moving contacts");

  // Gather K, M, C, the load and the fixed DOFs on rank 0.
  const LinearModelMatrices& matrices = *setup.matrices;
  root.layout = std::make_unique<GatheredMatrix>(*matrices.stiffness);
  GatheredMatrix mass(*matrices.mass);
  std::unique_ptr<GatheredMatrix> damping;
  if (!matrices.damping.is_null())
    damping = std::make_unique<GatheredMatrix>(*matrices.damping);
  TpetraMultiVector marker(dofs.owned_map(), 1);
  for (LocalIndex dof : *setup.fixed)
    marker.replaceLocalValue(dof, 0, 1.0);
  const std::vector<double> fixed_rows = root.layout->gather(marker);
  const std::vector<double> load_rows = root.layout->gather(*matrices.load);
  if (!root.layout->on_root())
    return;

  const long n_rows = root.layout->n_rows();
  for (long r = 0; r < n_rows; ++r)
    root.row_of_global[root.layout->global_index(r)] = r;
  auto row_of = [&](GlobalIndex node, int component) {
    return root.row_of_global.at(static_cast<GlobalIndex>(per_node) * node + component);
  };
  root.unknown_of_row.assign(n_rows, -1);
  std::vector<char> vehicle_row(n_rows, 0);
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node)
    if (in_vehicle[node] && partition.node_ranks()[node] >= 0)
      for (int c = 0; c < per_node; ++c)
        vehicle_row[row_of(node, c)] = 1;
  for (long r = 0; r < n_rows; ++r)
    if (fixed_rows[r] == 0 && !vehicle_row[r])
      root.unknown_of_row[r] = static_cast<long>(root.ns++);
  for (long r = 0; r < n_rows; ++r)
    if (fixed_rows[r] == 0 && vehicle_row[r])
      root.unknown_of_row[r] = static_cast<long>(root.ns + root.nv++);
  const std::size_t ns = root.ns, nv = root.nv;

  // Split each matrix into the sparse structure block and the dense vehicle block.
  auto split = [&](const GatheredMatrix& matrix, Eigen::SparseMatrix<double>& structure,
                   Eigen::MatrixXd& vehicle) {
    std::vector<Eigen::Triplet<double>> entries;
    vehicle = Eigen::MatrixXd::Zero(static_cast<long>(nv), static_cast<long>(nv));
    for (long r = 0; r < matrix.n_rows(); ++r) {
      const long i = root.unknown_of_row[root.row_of_global.at(matrix.global_index(r))];
      if (i < 0)
        continue;
      for (long k = matrix.row_offsets()[r]; k < matrix.row_offsets()[r + 1]; ++k) {
        const long j =
            root.unknown_of_row[root.row_of_global.at(matrix.global_index(matrix.columns()[k]))];
        if (j < 0 || matrix.values()[k] == 0.0)
          continue;
        const bool row_vehicle = i >= static_cast<long>(ns),
                   column_vehicle = j >= static_cast<long>(ns);
        if (row_vehicle != column_vehicle)
          throw RunError(setup.path +
                         ": a matrix couples the vehicle and the structure (internal)");
        if (row_vehicle)
          vehicle(i - ns, j - ns) += matrix.values()[k];
        else
          entries.emplace_back(i, j, matrix.values()[k]);
      }
    }
    structure = empty_sparse(ns);
    structure.setFromTriplets(entries.begin(), entries.end());
  };
  Eigen::SparseMatrix<double> k_s, m_s, c_s = empty_sparse(ns);
  Eigen::MatrixXd k_v, m_v, c_v = Eigen::MatrixXd::Zero(nv, nv);
  split(*root.layout, k_s, k_v);
  split(mass, m_s, m_v);
  if (damping)
    split(*damping, c_s, c_v);

  root.load.assign(ns + nv, 0.0);
  for (long r = 0; r < n_rows; ++r)
    if (root.unknown_of_row[r] >= 0)
      root.load[root.unknown_of_row[r]] = load_rows[r];
  root.scale =
      std::make_unique<Expression>(setup.load_function, setup.deck, setup.path + "/Load function");
  auto structure_unknown = [&](GlobalIndex node, int component) -> long {
    const long unknown = root.unknown_of_row[row_of(node, component)];
    return unknown < static_cast<long>(ns) ? unknown : -1;
  };
  if (!setup.moving_loads->empty())
    root.moving_loads = std::make_unique<MovingLoads>(*setup.moving_loads, mesh, *setup.sections,
                                                      structure_unknown, setup.deck, setup.path);
  Root* state = &root;
  root.structure =
      std::make_unique<SparseLinearSystem>(m_s, c_s, k_s, [state](double t, double* f) {
        const double scale = (*state->scale)(0, 0, 0, t);
        for (std::size_t i = 0; i < state->ns; ++i)
          f[i] = scale * state->load[i];
        if (state->moving_loads)
          state->moving_loads->add(t, f);
      });
  root.vehicle = std::make_unique<LinearDenseSystem>(m_v, c_v, k_v, [state](double t, double* f) {
    const double scale = (*state->scale)(0, 0, 0, t);
    for (std::size_t i = 0; i < state->nv; ++i)
      f[i] = scale * state->load[state->ns + i];
  });
  root.coupled = std::make_unique<CoupledSystem>(*root.structure, *root.vehicle);

  std::vector<MovingContactPoint> points;
  std::unique_ptr<BeamPath> path;
  for (const MovingContactSpec& contact : *setup.contacts) {
    const std::string where = setup.path + "/Moving contacts/" + contact.name;
    const GlobalIndex node = mesh.node_set(contact.node_set, "", "").nodes.front();
    auto vehicle_unknown = [&](int component, const char* axis) {
      const long unknown = root.unknown_of_row[row_of(node, component)];
      if (unknown < static_cast<long>(ns))
        throw_input_error(setup.deck, where + "/Node set",
                          std::string("holds its node's ") + axis +
                              " displacement fixed, so the contact has nothing to tie",
                          "leave the contact node free along the tied directions");
      return unknown;
    };
    MovingContactPoint point;
    point.name = contact.name;
    point.vertical_unknown = vehicle_unknown(2, "z");
    point.lateral_unknown = contact.lateral ? vehicle_unknown(1, "y") : -1;
    point.start = contact.start;
    point.speed = contact.speed;
    point.irregularity = irregularity_of(contact, setup.deck, where);
    point.may_separate = contact.separation;
    points.push_back(std::move(point));
    root.names.push_back(contact.name);
    auto chain = chain_of_blocks(mesh, contact.blocks, setup.deck, where + "/Path");
    BeamPath this_path = make_beam_path(mesh, *setup.sections, chain, structure_unknown);
    if (!path)
      path = std::make_unique<BeamPath>(std::move(this_path));
    else if (this_path.size() != path->size() || this_path.length() != path->length())
      throw_input_error(setup.deck, where + "/Path",
                        "differs from the first contact's path: every contact of a step runs on "
                        "one path",
                        "the same Path for every contact");
  }
  root.contacts = std::make_unique<MovingContacts>(std::move(*path), std::move(points));
  if (setup.solver == "monolithic") {
    root.saddle = std::make_unique<MonolithicSaddlePointSolver>(*root.coupled);
  } else {
    root.saddle = std::make_unique<BlockSaddlePointSolver>(*root.coupled);
    root.structure->check_solutions(false);  // the block solver checks the coupled solution
  }
  const ImplicitSettings& settings = *setup.settings;
  root.integrator = std::make_unique<HhtIntegrator>(settings.scheme, *root.coupled, settings.newton,
                                                    settings.rayleigh, settings.cut_back);
  root.integrator->constrain(*root.contacts, *root.saddle);
  const std::string step = setup.path;
  root.integrator->on_cut_back([step](const CutBack& cut) {
    std::fprintf(stderr,
                 "railfe: warning: %s: the step from t = %.9g s with dt = %.6g s did not "
                 "converge (%s); retrying with dt = %.6g s\n",
                 step.c_str(), cut.time, cut.failed_step, cut.reason.c_str(), cut.next_step);
  });
  root.u.assign(ns + nv, 0.0);
  root.v.assign(ns + nv, 0.0);
  root.a.assign(ns + nv, 0.0);
}

ConstrainedStepper::~ConstrainedStepper() = default;

void ConstrainedStepper::gather(const double* u, const double* v, const double* a) {
  const DofMap& dofs = *setup_.dofs;
  const std::size_t n = static_cast<std::size_t>(dofs.n_owned_dofs());
  Root& root = *root_;
  std::vector<double>* targets[3] = {&root.u, &root.v, &root.a};
  const double* sources[3] = {u, v, a};
  for (int f = 0; f < 3; ++f) {
    TpetraMultiVector x(dofs.owned_map(), 1);
    {
      auto data = x.getDataNonConst(0);
      std::copy_n(sources[f], n, data.getRawPtr());
    }
    const std::vector<double> rows = root.layout->gather(x);
    if (root.layout->on_root())
      for (std::size_t r = 0; r < rows.size(); ++r)
        if (root.unknown_of_row[r] >= 0)
          (*targets[f])[root.unknown_of_row[r]] = rows[r];
  }
}

void ConstrainedStepper::scatter(double* u, double* v, double* a) {
  const DofMap& dofs = *setup_.dofs;
  const std::size_t n = static_cast<std::size_t>(dofs.n_owned_dofs());
  Root& root = *root_;
  const std::vector<double>* sources[3] = {&root.u, &root.v, &root.a};
  double* targets[3] = {u, v, a};
  for (int f = 0; f < 3; ++f) {
    std::vector<double> rows;
    if (root.layout->on_root()) {
      rows.assign(root.unknown_of_row.size(), 0.0);
      for (std::size_t r = 0; r < rows.size(); ++r)
        if (root.unknown_of_row[r] >= 0)
          rows[r] = (*sources[f])[root.unknown_of_row[r]];
    }
    TpetraMultiVector x(dofs.owned_map(), 1);
    root.layout->scatter(rows, x);
    const auto data = x.getData(0);
    std::copy_n(data.getRawPtr(), n, targets[f]);
  }
}

void ConstrainedStepper::share(const std::string& problem, bool not_converged) const {
  const Communicator& comm = setup_.dofs->partition().comm();
  std::string message = problem;
  comm.broadcast(message);
  std::vector<double> flag{not_converged ? 1.0 : 0.0};
  comm.broadcast(flag);
  if (message.empty())
    return;
  if (flag[0] != 0)
    throw StepNotConverged(message, 0, 0, {});
  throw RunError(message);
}

void ConstrainedStepper::initialize(double time, double* u, double* v, double* a) {
  gather(u, v, a);
  std::string problem;
  if (root_->layout->on_root()) {
    try {
      root_->integrator->initialize(time, root_->u.data(), root_->v.data(), root_->a.data());
    } catch (const RunError& error) {
      problem = error.what();
    }
  }
  share(problem, false);
  scatter(u, v, a);
}

int ConstrainedStepper::advance(double time, double dt, double* u, double* v, double* a) {
  std::string problem;
  bool not_converged = false;
  std::vector<double> substeps{0};
  if (root_->layout->on_root()) {
    try {
      substeps[0] =
          root_->integrator->advance(time, dt, root_->u.data(), root_->v.data(), root_->a.data());
    } catch (const StepNotConverged& error) {
      problem = error.what();
      not_converged = true;
    } catch (const RunError& error) {
      problem = error.what();
    }
  }
  share(problem, not_converged);
  setup_.dofs->partition().comm().broadcast(substeps);
  scatter(u, v, a);
  return static_cast<int>(substeps[0]);
}

NewtonStatistics ConstrainedStepper::statistics() const {
  NewtonStatistics statistics;
  std::vector<double> values(6, 0.0);
  if (root_->layout->on_root()) {
    const NewtonStatistics& s = root_->integrator->newton_statistics();
    values = {static_cast<double>(s.steps),           static_cast<double>(s.iterations),
              static_cast<double>(s.factorizations),  static_cast<double>(s.force_evaluations),
              static_cast<double>(s.last_iterations), static_cast<double>(s.most_iterations)};
    values.insert(values.end(), s.last_residuals.begin(), s.last_residuals.end());
  }
  setup_.dofs->partition().comm().broadcast(values);
  statistics.steps = static_cast<std::size_t>(values[0]);
  statistics.iterations = static_cast<std::size_t>(values[1]);
  statistics.factorizations = static_cast<std::size_t>(values[2]);
  statistics.force_evaluations = static_cast<std::size_t>(values[3]);
  statistics.last_iterations = static_cast<int>(values[4]);
  statistics.most_iterations = static_cast<int>(values[5]);
  statistics.last_residuals.assign(values.begin() + 6, values.end());
  return statistics;
}

std::size_t ConstrainedStepper::n_cut_backs() const {
  std::vector<double> count{0};
  if (root_->layout->on_root())
    count[0] = static_cast<double>(root_->integrator->n_cut_backs());
  setup_.dofs->partition().comm().broadcast(count);
  return static_cast<std::size_t>(count[0]);
}

void ConstrainedStepper::open_contact_file(const std::string& path) {
  std::vector<std::string> columns{"time_s"};
  for (const MovingContactSpec& contact : *setup_.contacts) {
    columns.push_back(contact.name + "_position_m");
    columns.push_back(contact.name + "_force_N");
  }
  contact_file_ = std::make_unique<CsvWriter>(path, columns, root_->layout->on_root());
}

void ConstrainedStepper::write_contacts(double time) {
  if (!root_->layout->on_root() || !contact_file_)
    return;
  const auto forces = root_->contacts->contact_forces(root_->integrator->multipliers().data());
  std::vector<double> row{time};
  for (std::size_t c = 0; c < forces.size(); ++c) {
    row.push_back(root_->contacts->position(c, time));
    row.push_back(forces[c]);
  }
  contact_file_->write_row(row);
}

double ConstrainedStepper::write_events(const std::string& path) {
  const bool root = root_->layout->on_root();
  CsvWriter file(path, {"contact", "event", "time_s", "position_m"}, root);
  std::vector<double> count{0};
  if (root) {
    for (const ContactEvent& event : root_->contacts->events()) {
      file.write_row({event.contact, event.separation ? "separation" : "engagement",
                      CsvWriter::format(event.time), CsvWriter::format(event.position)});
      count[0] += event.separation ? 1 : 0;
    }
  }
  contact_file_.reset();
  setup_.dofs->partition().comm().broadcast(count);
  return count[0];
}

std::size_t ConstrainedStepper::n_structure() const {
  return root_->ns;
}

double ConstrainedStepper::structure_factorizations() const {
  std::vector<double> count{0};
  if (root_->layout->on_root())
    count[0] = static_cast<double>(root_->coupled->structure_factorizations());
  setup_.dofs->partition().comm().broadcast(count);
  return count[0];
}

std::size_t ConstrainedStepper::n_vehicle() const {
  return root_->nv;
}

}  // namespace railfe
