#pragma once
/// \file
/// Linear constraints on K u = f: prescribed values (Dirichlet) and multi-point constraints
/// u_s = Σ c_m u_m + b. Multi-point constraints are eliminated by u = T ū + g (K̄ = Tᵀ K T);
/// prescribed values by symmetric elimination, so a symmetric positive definite K stays so and
/// CG, MueLu and Cholesky remain usable.

#include <string>
#include <utility>
#include <vector>

#include "framework/assembly/dof_map.hpp"

namespace railfe {

/// u[slave] = Σ coefficient · u[master] + offset, over global DOF indices.
struct MultipointConstraint {
  GlobalIndex slave = 0;                                ///< the DOF that is eliminated
  std::vector<std::pair<GlobalIndex, double>> masters;  ///< (master DOF, coefficient)
  double offset = 0;                                    ///< the constant b
};

/// The constraints of one linear solve and how to apply and undo them.
class LinearConstraints {
 public:
  /// Constraints on the DOFs of \p dofs; \p source names the deck in messages.
  LinearConstraints(const DofMap& dofs, std::string source);

  /// Prescribes u[dof] = value. Any rank may call it; only the owner of \p dof keeps it, and a
  /// DOF prescribed twice takes the last value.
  void prescribe(GlobalIndex dof, double value);
  /// Adds a multi-point constraint. Any rank may call it; the owner of the slave keeps it.
  void add_multipoint(const MultipointConstraint& constraint);
  /// Checks consistency (collective): a slave may not be prescribed, be a master, or be the slave
  /// of two constraints. Throws InputError naming node and component. Builds T (collective).
  void finalize();

  /// Number of prescribed DOFs over all ranks (after finalize()).
  GlobalIndex n_prescribed() const { return n_prescribed_; }
  /// Number of multi-point constraints over all ranks (after finalize()).
  GlobalIndex n_multipoint() const { return n_multipoint_; }

  /// Applies the constraints to K u = f (collective) and returns the matrix to solve with; \p f
  /// becomes the right-hand side. Without multi-point constraints the returned matrix is \p K
  /// itself, modified in place; with them it is a new matrix. The rows of prescribed DOFs are
  /// kept for reactions().
  Teuchos::RCP<TpetraMatrix> apply(const Teuchos::RCP<TpetraMatrix>& K, TpetraVector& f);
  /// Zeroes the rows and columns of the prescribed DOFs in \p M, diagonal included (collective).
  /// For the mass matrix of an eigenproblem whose stiffness went through apply() with zero
  /// values: the prescribed DOFs then carry no inertia and give no eigenvalue. Prescribed DOFs
  /// only (no multi-point constraints: use constrained_mass()).
  void remove_prescribed(TpetraMatrix& M) const;
  /// The mass matrix of the constrained eigenproblem that goes with apply()'s stiffness (after
  /// finalize(), collective): M̄ = Tᵀ M T with the rows and columns of prescribed DOFs zeroed. The
  /// rows of slave DOFs are empty (K̄ has 1 there), so slaves and prescribed DOFs carry no inertia
  /// and give no finite eigenvalue; a mass carried by a rigid link lands on its master with the
  /// parallel-axis terms. Without multi-point constraints \p M itself is modified and returned.
  Teuchos::RCP<TpetraMatrix> constrained_mass(const Teuchos::RCP<TpetraMatrix>& M) const;
  /// Turns the solution of the constrained system into u, in place (collective).
  void recover(TpetraVector& solution) const;
  /// Whether \p u has every prescribed value exactly and no multi-point constraint exists
  /// (collective): then u and any solution of apply()'s system are joined by steps that keep the
  /// constraints.
  bool holds_prescribed_values(const TpetraVector& u) const;
  /// Reaction forces r = K u − f at prescribed DOFs (zero elsewhere), from the rows apply() kept.
  void reactions(const TpetraVector& u, TpetraVector& r) const;

 private:
  void build_transformation();
  // Tᵀ A T (a new matrix).
  Teuchos::RCP<TpetraMatrix> transform(const TpetraMatrix& A) const;
  Teuchos::RCP<TpetraMatrix> eliminate_multipoint(const Teuchos::RCP<TpetraMatrix>& K,
                                                  TpetraVector& f);
  void eliminate_prescribed(TpetraMatrix& K, TpetraVector& f);
  // Zeroes prescribed rows and columns of A; returns each row's diagonal (1 where it was zero or
  // not kept).
  std::vector<double> zero_prescribed_couplings(TpetraMatrix& A, bool keep_diagonal) const;

  const DofMap* dofs_;
  std::string source_;
  std::vector<std::pair<LocalIndex, double>> prescribed_;  // (owned local DOF, value)
  std::vector<MultipointConstraint> multipoint_;           // slaves owned here
  GlobalIndex n_prescribed_ = 0;
  GlobalIndex n_multipoint_ = 0;
  Teuchos::RCP<TpetraMatrix> transformation_;  // T, when there are multi-point constraints
  Teuchos::RCP<TpetraVector> shift_;           // g: offsets at slave DOFs
  Teuchos::RCP<TpetraMatrix> identity_on_slaves_;

  // Original rows of prescribed DOFs: u is imported to the column map of the original K.
  Teuchos::RCP<const TpetraMap> reaction_columns_;
  std::vector<std::size_t> reaction_row_offsets_{0};
  std::vector<LocalIndex> reaction_row_columns_;
  std::vector<double> reaction_row_values_;
  std::vector<double> reaction_loads_;
};

}  // namespace railfe
