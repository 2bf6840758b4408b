#pragma once
/// \file
/// What the direct solvers share: the matrix gathered on rank 0, rank 0's verdict shared with
/// every rank, the solution scattered back and checked with the distributed matrix.

#include <optional>
#include <string>
#include <vector>

#include "framework/solvers/gathered_matrix.hpp"
#include "framework/solvers/linear_solver.hpp"

namespace railfe {

/// A LinearSolver that factorizes and solves on rank 0 only. Subclasses supply the two steps.
class RootDirectSolver : public LinearSolver {
 public:
  /// \p method names the solver in reports and messages; \p backward_error_limit bounds the
  /// accepted backward error of every solve.
  RootDirectSolver(std::string method, double backward_error_limit);

  void setup(const Teuchos::RCP<const TpetraMatrix>& A, const ProblemTraits& traits) final;
  SolveReport solve(const TpetraVector& b, TpetraVector& x) final;
  SolveReport solve_block(const TpetraMultiVector& B, TpetraMultiVector& X) final;
  Teuchos::RCP<TpetraOperator> factor_operator() final;

 protected:
  /// Factorizes \p matrix (called on rank 0 only). Returns "" or the problem, phrased for users.
  virtual std::string factorize(const GatheredMatrix& matrix, const ProblemTraits& traits) = 0;
  /// Solves with the factorization for the \p n_columns right-hand sides \p rhs (columns one
  /// after another, each in gathered order; rank 0 only); throws std::exception on failure.
  virtual std::vector<double> solve_on_root(const std::vector<double>& rhs, int n_columns) = 0;

 private:
  std::string method_;
  double limit_;
  std::optional<GatheredMatrix> gathered_;
  Teuchos::RCP<const TpetraMatrix> matrix_;
  double setup_seconds_ = 0;
};

}  // namespace railfe
