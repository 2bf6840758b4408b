#include "framework/assembly/linear_constraints.hpp"

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <map>
#include <set>

#include "framework/assembly/tpetra_compat.hpp"
#include "framework/base/error.hpp"

namespace railfe {

LinearConstraints::LinearConstraints(const DofMap& dofs, std::string source)
    : dofs_(&dofs), source_(std::move(source)) {}

void LinearConstraints::prescribe(GlobalIndex dof, double value) {
  const LocalIndex local = dofs_->owned_map()->getLocalElement(dof);
  if (local == Teuchos::OrdinalTraits<LocalIndex>::invalid())
    return;
  prescribed_.emplace_back(local, value);
}

void LinearConstraints::add_multipoint(const MultipointConstraint& constraint) {
  if (dofs_->owned_map()->isNodeGlobalElement(constraint.slave))
    multipoint_.push_back(constraint);
}

void LinearConstraints::finalize() {
  const Communicator& comm = dofs_->partition().comm();
  // The last value given for a DOF wins (conditions later in the deck override earlier ones).
  std::map<LocalIndex, double> unique(prescribed_.begin(), prescribed_.end());
  prescribed_.assign(unique.begin(), unique.end());

  std::vector<long long> my_slaves;
  for (const auto& constraint : multipoint_)
    my_slaves.push_back(constraint.slave);
  std::vector<long long> all_slaves = comm.all_gather(my_slaves);
  std::sort(all_slaves.begin(), all_slaves.end());
  std::string problem;
  const auto duplicate = std::adjacent_find(all_slaves.begin(), all_slaves.end());
  if (duplicate != all_slaves.end()) {
    problem = format_input_message(
        source_, "", dofs_->describe(*duplicate) + " is the slave of two multi-point constraints",
        "each DOF constrained once");
  }
  const std::set<long long> slaves(all_slaves.begin(), all_slaves.end());
  for (const auto& constraint : multipoint_) {
    for (const auto& [master, coefficient] : constraint.masters) {
      if (problem.empty() && slaves.count(master)) {
        problem = format_input_message(source_, "",
                                       dofs_->describe(master) +
                                           " is both a master and a slave of "
                                           "multi-point constraints",
                                       "masters that are not themselves constrained");
      }
    }
  }
  const auto& owned = *dofs_->owned_map();
  for (const auto& [local, value] : prescribed_) {
    if (problem.empty() && slaves.count(owned.getGlobalElement(local))) {
      problem =
          format_input_message(source_, "",
                               dofs_->describe(owned.getGlobalElement(local)) +
                                   " is both prescribed and the slave of a multi-point constraint",
                               "prescribe the master instead");
    }
  }
  comm.agree(problem, true);
  n_prescribed_ = comm.sum(static_cast<long long>(prescribed_.size()));
  n_multipoint_ = static_cast<GlobalIndex>(all_slaves.size());
  if (n_multipoint_ > 0)
    build_transformation();
}

Teuchos::RCP<TpetraMatrix> LinearConstraints::apply(const Teuchos::RCP<TpetraMatrix>& K,
                                                    TpetraVector& f) {
  // Keep the original rows of prescribed DOFs and their loads: reactions are K u - f there.
  reaction_columns_ = K->getColMap();
  reaction_row_offsets_.assign(1, 0);
  reaction_row_columns_.clear();
  reaction_row_values_.clear();
  reaction_loads_.clear();
  {
    auto local = K->getLocalMatrixHost();
    const auto f_data = f.getData(0);
    for (const auto& [row, value] : prescribed_) {
      for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k) {
        reaction_row_columns_.push_back(local.graph.entries(k));
        reaction_row_values_.push_back(local.values(k));
      }
      reaction_row_offsets_.push_back(reaction_row_columns_.size());
      reaction_loads_.push_back(f_data[row]);
    }
  }
  Teuchos::RCP<TpetraMatrix> system = K;
  if (n_multipoint_ > 0)
    system = eliminate_multipoint(K, f);
  if (n_prescribed_ > 0)
    eliminate_prescribed(*system, f);
  return system;
}

void LinearConstraints::build_transformation() {
  const auto owned = dofs_->owned_map();
  std::map<GlobalIndex, const MultipointConstraint*> by_slave;
  std::size_t widest_row = 1;  // a rigid link's translation rows have up to three masters
  for (const auto& constraint : multipoint_) {
    by_slave[constraint.slave] = &constraint;
    widest_row = std::max(widest_row, constraint.masters.size());
  }

  transformation_ = Teuchos::rcp(new TpetraMatrix(owned, widest_row));
  shift_ = Teuchos::rcp(new TpetraVector(owned));
  auto identity_on_slaves = Teuchos::rcp(new TpetraMatrix(owned, 1));
  const double one = 1.0;
  for (std::size_t local = 0; local < local_size(*owned); ++local) {
    const GlobalIndex dof = owned->getGlobalElement(static_cast<LocalIndex>(local));
    auto it = by_slave.find(dof);
    if (it == by_slave.end()) {
      transformation_->insertGlobalValues(dof, Teuchos::tuple(dof), Teuchos::tuple(one));
      // An explicit zero, so that every row of K̄ has a diagonal entry: a master DOF no element
      // stiffens (a wheelset's spin, whose axle boxes sit on the axle) may be prescribed next,
      // and eliminate_prescribed() writes 1 there.
      identity_on_slaves->insertGlobalValues(dof, Teuchos::tuple(dof), Teuchos::tuple(0.0));
      continue;
    }
    std::vector<GlobalIndex> columns;
    std::vector<double> coefficients;
    for (const auto& [master, coefficient] : it->second->masters) {
      columns.push_back(master);
      coefficients.push_back(coefficient);
    }
    if (!columns.empty()) {
      transformation_->insertGlobalValues(dof, Teuchos::ArrayView<const GlobalIndex>(columns),
                                          Teuchos::ArrayView<const double>(coefficients));
    }
    shift_->replaceGlobalValue(dof, it->second->offset);
    identity_on_slaves->insertGlobalValues(dof, Teuchos::tuple(dof), Teuchos::tuple(one));
  }
  transformation_->fillComplete(owned, owned);
  identity_on_slaves->fillComplete(owned, owned);
  identity_on_slaves_ = identity_on_slaves;
}

Teuchos::RCP<TpetraMatrix> LinearConstraints::transform(const TpetraMatrix& A) const {
  TpetraMatrix AT(A.getRowMap(), 0);
  Tpetra::MatrixMatrix::Multiply(A, false, *transformation_, false, AT);
  auto TtAT = Teuchos::rcp(new TpetraMatrix(transformation_->getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(*transformation_, true, AT, false, *TtAT);
  return TtAT;
}

Teuchos::RCP<TpetraMatrix> LinearConstraints::eliminate_multipoint(
    const Teuchos::RCP<TpetraMatrix>& K, TpetraVector& f) {
  const auto owned = dofs_->owned_map();
  // f̄ = Tᵀ (f − K g)
  TpetraVector work(owned);
  K->apply(*shift_, work);
  f.update(-1.0, work, 1.0);
  work.putScalar(0.0);
  transformation_->apply(f, work, Teuchos::TRANS);
  f.assign(work);

  // K̄ = Tᵀ K T + (identity on slave rows, which Tᵀ K T leaves empty, and a zero diagonal
  // entry on the others)
  return Tpetra::MatrixMatrix::add(1.0, false, *transform(*K), 1.0, false, *identity_on_slaves_);
}

void LinearConstraints::eliminate_prescribed(TpetraMatrix& K, TpetraVector& f) {
  const auto domain = K.getDomainMap();
  TpetraVector values(domain);
  for (const auto& [row, value] : prescribed_)
    values.replaceLocalValue(row, value);
  // Move the known values to the right-hand side: f ← f − K g.
  TpetraVector work(K.getRangeMap());
  K.apply(values, work);
  f.update(-1.0, work, 1.0);

  // The diagonal keeps its size, so the equation u_i = value is as well scaled as its neighbours.
  const std::vector<double> diagonal = zero_prescribed_couplings(K, true);
  for (const auto& [row, value] : prescribed_) {
    f.replaceLocalValue(row, diagonal[row] * value);
  }
}

void LinearConstraints::remove_prescribed(TpetraMatrix& M) const {
  zero_prescribed_couplings(M, false);
}

Teuchos::RCP<TpetraMatrix> LinearConstraints::constrained_mass(
    const Teuchos::RCP<TpetraMatrix>& M) const {
  Teuchos::RCP<TpetraMatrix> reduced = M;
  if (n_multipoint_ > 0)
    reduced = transform(*M);
  if (n_prescribed_ > 0)
    zero_prescribed_couplings(*reduced, false);
  return reduced;
}

std::vector<double> LinearConstraints::zero_prescribed_couplings(TpetraMatrix& A,
                                                                 bool keep_diagonal) const {
  const auto domain = A.getDomainMap();
  TpetraVector marker(domain);
  for (const auto& entry : prescribed_)
    marker.replaceLocalValue(entry.first, 1.0);
  TpetraVector column_marker(A.getColMap());
  TpetraImport to_columns(domain, A.getColMap());
  column_marker.doImport(marker, to_columns, Tpetra::INSERT);
  const auto is_column_prescribed = column_marker.getData(0);
  std::vector<char> is_row_prescribed(local_rows(A), 0);
  for (const auto& entry : prescribed_)
    is_row_prescribed[entry.first] = 1;

  A.resumeFill();
  auto local = A.getLocalMatrixHost();
  const auto& row_map = *A.getRowMap();
  const auto& column_map = *A.getColMap();
  std::vector<double> diagonal(local_rows(A), 1.0);
  for (std::size_t row = 0; row < local_rows(A); ++row) {
    const auto begin = local.graph.row_map(row), end = local.graph.row_map(row + 1);
    if (is_row_prescribed[row]) {
      const LocalIndex diagonal_column =
          column_map.getLocalElement(row_map.getGlobalElement(static_cast<LocalIndex>(row)));
      for (auto k = begin; k < end; ++k) {
        if (keep_diagonal && local.graph.entries(k) == diagonal_column) {
          // A DOF without stiffness of its own (a rotation a spring leaves free) keeps the
          // equation 1 · u_i = value instead of an empty row.
          if (local.values(k) != 0.0)
            diagonal[row] = local.values(k);
          else
            local.values(k) = 1.0;
        } else {
          local.values(k) = 0.0;
        }
      }
    } else {
      for (auto k = begin; k < end; ++k) {
        if (is_column_prescribed[local.graph.entries(k)] != 0.0)
          local.values(k) = 0.0;
      }
    }
  }
  A.fillComplete(A.getDomainMap(), A.getRangeMap());
  return diagonal;
}

void LinearConstraints::recover(TpetraVector& solution) const {
  if (transformation_.is_null())
    return;
  TpetraVector reduced(solution, Teuchos::Copy);
  transformation_->apply(reduced, solution);
  solution.update(1.0, *shift_, 1.0);
}

bool LinearConstraints::holds_prescribed_values(const TpetraVector& u) const {
  const auto data = u.getData();
  long long broken = n_multipoint_ > 0 ? 1 : 0;
  for (const auto& [dof, value] : prescribed_)
    broken += data[dof] != value ? 1 : 0;
  return dofs_->partition().comm().sum(broken) == 0;
}

void LinearConstraints::reactions(const TpetraVector& u, TpetraVector& r) const {
  r.putScalar(0.0);
  if (reaction_columns_.is_null())
    return;
  TpetraVector u_columns(reaction_columns_);
  TpetraImport to_columns(u.getMap(), reaction_columns_);
  u_columns.doImport(u, to_columns, Tpetra::INSERT);
  const auto u_data = u_columns.getData(0);
  for (std::size_t k = 0; k < prescribed_.size(); ++k) {
    double force = -reaction_loads_[k];
    for (std::size_t j = reaction_row_offsets_[k]; j < reaction_row_offsets_[k + 1]; ++j) {
      force += reaction_row_values_[j] * u_data[reaction_row_columns_[j]];
    }
    r.replaceLocalValue(prescribed_[k].first, force);
  }
}

}  // namespace railfe
