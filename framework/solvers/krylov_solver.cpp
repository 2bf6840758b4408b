#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/krylov_solver.hpp"
#include "framework/solvers/preconditioners.hpp"
#include "framework/solvers/solution_check.hpp"

namespace railfe {

namespace {

// A backward error this small means x solves a matrix and right-hand side within a few hundred
// units of round-off of the given ones.
constexpr double kRoundOffBackwardError = 1e-14;

// Sits in front of CG's preconditioner, whose input each iteration is the current residual, and
// reports progress as the share of orders of magnitude the residual has dropped on the way to
// the target. The norm is a collective, so every rank takes it at the same iterations: the first
// and every tenth (one dot product per ten iterations); rank 0 prints when a line is due.
class ProgressPreconditioner : public TpetraOperator {
 public:
  ProgressPreconditioner(Teuchos::RCP<TpetraOperator> inner, Teuchos::RCP<const TpetraMap> map,
                         Progress& progress, double target)
      : inner_(std::move(inner)), map_(std::move(map)), progress_(progress), target_(target) {}

  Teuchos::RCP<const TpetraMap> getDomainMap() const override { return map_; }
  Teuchos::RCP<const TpetraMap> getRangeMap() const override { return map_; }

  void apply(const TpetraMultiVector& X, TpetraMultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    if (applications_++ % 10 == 0) {
      const double norm = X.getVector(0)->norm2();
      if (initial_ < 0)
        initial_ = norm;
      if (initial_ > target_ && norm > 0) {
        const double reduced = std::log(initial_ / norm) / std::log(initial_ / target_);
        progress_.update(std::min(1.0, std::max(0.0, reduced)));
      }
    }
    if (inner_.is_null()) {
      Y.update(alpha, X, beta);
    } else {
      inner_->apply(X, Y, mode, alpha, beta);
    }
  }

 private:
  Teuchos::RCP<TpetraOperator> inner_;
  Teuchos::RCP<const TpetraMap> map_;
  Progress& progress_;
  double target_;
  mutable double initial_ = -1;
  mutable long applications_ = 0;
};

// What one Belos solve ended with.
struct BelosRun {
  Belos::ReturnType outcome = Belos::Unconverged;
  int iterations = 0;
};

// Belos throws when CG meets p·Ap <= 0: the matrix or the preconditioner is not positive definite.
struct BelosBreakdown : std::runtime_error {
  BelosBreakdown(const std::string& what, int iterations_done)
      : std::runtime_error(what), iterations(iterations_done) {}
  int iterations;
};

// Runs the Belos solver \p settings names on A x = b from the guess in \p x, with the optional
// left and right preconditioners (collective).
BelosRun run_belos(const KrylovSettings& settings, const Teuchos::RCP<const TpetraMatrix>& A,
                   const Teuchos::RCP<TpetraOperator>& left,
                   const Teuchos::RCP<TpetraOperator>& right, const TpetraVector& b,
                   TpetraVector& x) {
  using MV = TpetraMultiVector;
  using OP = TpetraOperator;
  auto parameters = Teuchos::rcp(new Teuchos::ParameterList);
  parameters->set("Convergence Tolerance", settings.relative_tolerance);
  parameters->set("Maximum Iterations", settings.maximum_iterations);
  if (settings.method == "gmres")
    parameters->set("Num Blocks", settings.restart);
  parameters->set("Verbosity", Belos::Errors + Belos::Warnings);
  Belos::SolverFactory<double, MV, OP> factory;
  auto solver = factory.create(settings.method == "cg" ? "CG" : "GMRES", parameters);
  auto op = Teuchos::rcp_implicit_cast<const OP>(A);
  auto problem = Teuchos::rcp(
      new Belos::LinearProblem<double, MV, OP>(op, Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b)));
  if (!left.is_null())
    problem->setLeftPrec(left);
  if (!right.is_null())
    problem->setRightPrec(right);
  problem->setProblem();
  solver->setProblem(problem);
  BelosRun run;
  try {
    run.outcome = solver->solve();
  } catch (const std::exception& error) {
    throw BelosBreakdown(error.what(), solver->getNumIters());
  }
  run.iterations = solver->getNumIters();
  return run;
}

class KrylovSolver : public LinearSolver {
 public:
  explicit KrylovSolver(const KrylovSettings& settings) : settings_(settings) {}

  void setup(const Teuchos::RCP<const TpetraMatrix>& A, const ProblemTraits& traits) override {
    Stopwatch clock;
    matrix_ = A;
    if (settings_.method == "cg" && !traits.symmetric_positive_definite) {
      throw RunError("CG needs a symmetric positive definite matrix; use 'gmres' for this problem");
    }
    try {
      preconditioner_ = make_preconditioner(settings_.preconditioner, A, traits);
    } catch (const std::exception& error) {
      throw RunError("setting up the " + preconditioner_description(settings_.preconditioner) +
                     " preconditioner failed: " + essential_line(error.what()));
    }
    setup_seconds_ = clock.seconds();
  }

  SolveReport solve(const TpetraVector& b, TpetraVector& x) override {
    Stopwatch clock;
    SolveReport report;
    report.method = std::string(settings_.method == "cg" ? "CG" : "GMRES") + " + " +
                    preconditioner_description(settings_.preconditioner);
    report.setup_seconds = setup_seconds_;
    if (b.norm2() == 0.0) {
      x.putScalar(0.0);
      report.solve_seconds = clock.seconds();
      return report;
    }
    Teuchos::RCP<TpetraOperator> left, right;
    if (settings_.method == "cg") {
      left = preconditioner_;
      if (progress_ != nullptr)
        left = Teuchos::rcp(new ProgressPreconditioner(preconditioner_, b.getMap(), *progress_,
                                                       settings_.relative_tolerance * b.norm2()));
    } else {
      right = preconditioner_;
    }
    BelosRun run;
    try {
      run = run_belos(settings_, matrix_, left, right, b, x);
    } catch (const BelosBreakdown& error) {
      throw RunError(report.method + " broke down after " + std::to_string(error.iterations) +
                     " iterations: " + essential_line(error.what()) +
                     ". The matrix or the preconditioner is not positive definite: check that the "
                     "model is restrained, or try Preconditioner 'muelu-sa' or 'ilu', or a direct "
                     "Method ('cholmod').");
    }
    const Belos::ReturnType outcome = run.outcome;
    report.iterations = run.iterations;
    const ResidualNorms norms = residual_norms(*matrix_, x, b);
    report.relative_residual = norms.relative_residual;
    report.backward_error = norms.backward_error;
    report.solve_seconds = clock.seconds();
    // Belos stops on its recursively updated residual; the true one may drift a little above it,
    // and no method gets below the round-off floor (backward error ~1e-16): a solution whose
    // backward error is at that floor is as accurate as double precision allows.
    if (!std::isfinite(norms.backward_error))
      require_backward_error(norms, 0.0, report.method);  // names the non-finite solution
    const bool accurate = norms.relative_residual <= 10 * settings_.relative_tolerance ||
                          norms.backward_error <= kRoundOffBackwardError;
    if (outcome != Belos::Converged || !accurate) {
      std::ostringstream message;
      message << report.method << " did not converge: after " << report.iterations
              << " iterations the relative residual is " << norms.relative_residual << " (target "
              << settings_.relative_tolerance << ", at most " << settings_.maximum_iterations
              << " iterations). Raise 'Maximum iterations', choose another preconditioner, or "
                 "use a direct solver; also check that the model is restrained.";
      throw RunError(message.str());
    }
    return report;
  }

 private:
  KrylovSettings settings_;
  Teuchos::RCP<const TpetraMatrix> matrix_;
  Teuchos::RCP<TpetraOperator> preconditioner_;
  double setup_seconds_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_krylov_solver(const KrylovSettings& settings) {
  return std::make_unique<KrylovSolver>(settings);
}

std::optional<SolveReport> try_preconditioned_cg(const Teuchos::RCP<const TpetraMatrix>& A,
                                                 const Teuchos::RCP<TpetraOperator>& preconditioner,
                                                 const TpetraVector& b, TpetraVector& x,
                                                 double relative_tolerance,
                                                 int maximum_iterations) {
  Stopwatch clock;
  KrylovSettings settings;
  settings.relative_tolerance = relative_tolerance;
  settings.maximum_iterations = maximum_iterations;
  BelosRun run;
  try {
    run = run_belos(settings, A, preconditioner, Teuchos::null, b, x);
  } catch (const BelosBreakdown&) {
    return std::nullopt;
  }
  const ResidualNorms norms = residual_norms(*A, x, b);
  if (run.outcome != Belos::Converged || !(norms.relative_residual <= 10 * relative_tolerance))
    return std::nullopt;
  SolveReport report;
  report.method = "CG preconditioned by an earlier factorization";
  report.iterations = run.iterations;
  report.relative_residual = norms.relative_residual;
  report.backward_error = norms.backward_error;
  report.solve_seconds = clock.seconds();
  return report;
}

}  // namespace railfe
