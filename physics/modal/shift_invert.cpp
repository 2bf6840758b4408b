#include "physics/modal/shift_invert.hpp"

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/solvers/gathered_matrix.hpp"
#include "physics/modal/krylov_plan.hpp"

namespace railfe {

namespace {

using Eigenproblem = Anasazi::BasicEigenproblem<double, TpetraMultiVector, TpetraOperator>;

// A failed inner solve, carried through Anasazi unchanged so that the message can name the
// modal parameters that cause it rather than the linear solver's own advice.
class InnerSolveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The linear solver's account of its failure without its advice, which names statics
// parameters (Preconditioner, Method) that a modal step does not have.
std::string without_advice(const std::string& message) {
  std::size_t end = message.size();
  for (const char* advice : {". The matrix or the preconditioner", ". Raise 'Maximum iterations'"})
    end = std::min(end, message.find(advice));
  return message.substr(0, end);
}

// Y = (K − σM)⁻¹ M X, through the inner solver's factorization.
class ShiftInvertOperator : public TpetraOperator {
 public:
  ShiftInvertOperator(Teuchos::RCP<const TpetraMatrix> M, LinearSolver& inner, Progress* progress,
                      long long expected_applies)
      : M_(std::move(M)), inner_(inner), progress_(progress), expected_(expected_applies) {}

  Teuchos::RCP<const TpetraMap> getDomainMap() const override { return M_->getDomainMap(); }
  Teuchos::RCP<const TpetraMap> getRangeMap() const override { return M_->getRangeMap(); }

  void apply(const TpetraMultiVector& X, TpetraMultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    (void)mode;  // the operator is M-self-adjoint; Anasazi never asks for the transpose
    TpetraMultiVector mass_times_x(M_->getRangeMap(), X.getNumVectors());
    M_->apply(X, mass_times_x);
    TpetraMultiVector solution(M_->getDomainMap(), X.getNumVectors());
    try {
      inner_.solve_block(mass_times_x, solution);
    } catch (const RunError& error) {
      throw InnerSolveError(error.what());
    }
    Y.update(alpha, solution, beta);
    applies_ += static_cast<long long>(X.getNumVectors());
    // Krylov-Schur typically needs about one Krylov space of applications; the share of it is
    // the progress (its phase has a total of 1), held below 100 % until the solve ends.
    if (progress_ != nullptr)
      progress_->update(std::min(0.99, static_cast<double>(applies_) / expected_));
  }

  long long applies() const { return applies_; }

 private:
  Teuchos::RCP<const TpetraMatrix> M_;
  LinearSolver& inner_;
  Progress* progress_;
  long long expected_;
  mutable long long applies_ = 0;
};

// A random block that does not depend on the number of ranks: each entry is a hash of its global
// index and column, so runs on 1 and 2 ranks start from the same vectors.
void fill_reproducible_random(TpetraMultiVector& block, unsigned seed) {
  const auto& map = *block.getMap();
  for (std::size_t j = 0; j < block.getNumVectors(); ++j) {
    auto column = block.getDataNonConst(j);
    for (decltype(column.size()) i = 0; i < column.size(); ++i) {
      unsigned long long h =
          static_cast<unsigned long long>(map.getGlobalElement(i)) * 0x9E3779B97F4A7C15ull;
      h ^= (j + 1) * 0xBF58476D1CE4E5B9ull + seed;
      h ^= h >> 31;
      h *= 0x94D049BB133111EBull;
      h ^= h >> 29;
      column[i] = static_cast<double>(h >> 11) / 9007199254740992.0 - 0.5;
    }
  }
}

RunError inner_solve_failure(const InnerSolveError& error) {
  return RunError(
      "the inner solve of (K - sigma M) x = M v failed: " + without_advice(error.what()) +
      ". K - sigma M is indefinite when the Shift lies above the lowest natural "
      "frequency, and nearly singular when it lies close to one: choose a Shift "
      "below the lowest mode (negative for a free body, e.g. -1 Hz), or Inner solver "
      "= cholmod");
}

}  // namespace

ShiftInvertEigensolver::ShiftInvertEigensolver(Teuchos::RCP<const TpetraMatrix> K,
                                               Teuchos::RCP<const TpetraMatrix> M,
                                               LinearSolver& inner, const ProblemTraits& traits,
                                               double shift)
    : K_(std::move(K)), M_(std::move(M)), inner_(inner), shift_(shift) {
  Stopwatch clock;
  shifted_ = Tpetra::MatrixMatrix::add(1.0, false, *K_, -shift_, false, *M_);
  inner_.setup(shifted_, traits);
  factor_seconds_ = clock.seconds();
}

ShiftInvertResult ShiftInvertEigensolver::solve(const ShiftInvertSettings& settings,
                                                Progress* progress,
                                                Teuchos::RCP<const TpetraMultiVector> found) const {
  const auto& K = K_;
  const auto& M = M_;
  ShiftInvertResult result;
  result.n_requested = settings.n_modes;
  result.factor_seconds = factor_seconds_;
  const auto n_global = static_cast<long long>(K->getGlobalNumRows());
  if (settings.n_modes < 1)
    throw RunError("the eigensolver was asked for " + std::to_string(settings.n_modes) + " modes");
  Stopwatch clock;

  const long long free_dofs = settings.free_dofs > 0 ? settings.free_dofs : n_global;
  const long long deflated = found.is_null() ? 0 : static_cast<long long>(found->getNumVectors());
  const KrylovPlan plan =
      plan_krylov_space(settings.n_modes, settings.block_size, settings.krylov_blocks, free_dofs,
                        deflated, settings.minimum_space, settings.allow_dense);
  if (!plan.problem.empty())
    throw RunError(plan.parameter + ": " + plan.problem + " (allowed: " + plan.allowed + ")");
  if (plan.dense)
    return solve_dense(settings);
  const int block_size = plan.block_size;
  const int blocks = plan.blocks;
  result.krylov_dimension = plan.dimension();
  result.block_size = block_size;

  auto op = Teuchos::rcp(new ShiftInvertOperator(M, inner_, progress,
                                                 static_cast<long long>(result.krylov_dimension)));
  // Start from (K − σM)⁻¹ M R: smooth, and zero wherever M has no mass (prescribed DOFs).
  TpetraMultiVector random(K->getDomainMap(), block_size);
  fill_reproducible_random(random, settings.seed);
  auto start = Teuchos::rcp(new TpetraMultiVector(K->getDomainMap(), block_size));
  try {
    op->apply(random, *start, Teuchos::NO_TRANS, 1.0, 0.0);
  } catch (const InnerSolveError& error) {
    throw inner_solve_failure(error);
  }

  auto problem = Teuchos::rcp(new Eigenproblem(op, M, start));
  problem->setHermitian(true);
  problem->setNEV(settings.n_modes);
  if (!found.is_null())
    problem->setAuxVecs(found);
  if (!problem->setProblem())
    throw RunError("Anasazi rejected the eigenproblem set-up");

  Teuchos::ParameterList anasazi;
  anasazi.set("Which", std::string("LM"));
  anasazi.set("Block Size", block_size);
  anasazi.set("Num Blocks", blocks);
  anasazi.set("Maximum Restarts", settings.maximum_restarts);
  anasazi.set("Convergence Tolerance", settings.tolerance);
  anasazi.set("Relative Convergence Tolerance", true);
  anasazi.set("Verbosity", static_cast<int>(Anasazi::Errors));
  Anasazi::BlockKrylovSchurSolMgr<double, TpetraMultiVector, TpetraOperator> manager(problem,
                                                                                     anasazi);
  clock.restart();
  Anasazi::ReturnType status = Anasazi::Unconverged;
  try {
    status = manager.solve();
  } catch (const InnerSolveError& error) {
    throw inner_solve_failure(error);
  } catch (const std::exception& error) {
    throw RunError("the Krylov-Schur eigensolver failed: " + essential_line(error.what()));
  }
  result.iteration_seconds = clock.seconds();
  result.converged = status == Anasazi::Converged;
  result.restarts = manager.getNumIters();
  result.operator_applies = op->applies();

  const auto& solution = problem->getSolution();
  const int n_found = solution.numVecs;
  // θ = 1/(λ − σ) for the inverted operator; sort the λ ascending.
  std::vector<double> lambdas(n_found);
  for (int i = 0; i < n_found; ++i)
    lambdas[i] = shift_ + 1.0 / solution.Evals[i].realpart;
  std::vector<int> order(n_found);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambdas[a] < lambdas[b]; });
  result.vectors = Teuchos::rcp(new TpetraMultiVector(K->getDomainMap(), std::max(n_found, 1)));
  TpetraVector mass_times_phi(M->getRangeMap());
  for (int k = 0; k < n_found; ++k) {
    result.eigenvalues.push_back(lambdas[order[k]]);
    auto column = result.vectors->getVectorNonConst(k);
    column->update(1.0, *solution.Evecs->getVector(order[k]), 0.0);
    M->apply(*column, mass_times_phi);
    const double modal_mass = column->dot(mass_times_phi);
    if (modal_mass > 0)
      column->scale(1.0 / std::sqrt(modal_mass));
  }
  if (n_found == 0)
    result.vectors = Teuchos::null;
  return result;
}

ShiftInvertResult ShiftInvertEigensolver::solve_dense(const ShiftInvertSettings& settings) const {
  ShiftInvertResult result;
  result.n_requested = settings.n_modes;
  result.factor_seconds = factor_seconds_;
  result.inner_method = "dense generalized eigensolver (Eigen, rank 0)";
  Stopwatch clock;
  const GatheredMatrix shifted(*shifted_), mass(*M_);
  std::vector<double> lambdas, root_vectors;
  std::string problem;
  if (shifted.on_root()) {
    const long n = shifted.n_rows();
    auto dense = [n](const GatheredMatrix& gathered) {
      Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
      for (long i = 0; i < n; ++i)
        for (long k = gathered.row_offsets()[i]; k < gathered.row_offsets()[i + 1]; ++k)
          out(i, gathered.columns()[k]) += gathered.values()[k];
      return out;
    };
    bool same_order = mass.n_rows() == n;
    for (long i = 0; same_order && i < n; ++i)
      same_order = mass.global_index(i) == shifted.global_index(i);
    if (!same_order)
      throw std::logic_error("ShiftInvertEigensolver: K and M gathered in different orders");
    // M φ = μ (K − σM) φ with K − σM positive definite (σ below the spectrum): μ = 1/(λ − σ),
    // and DOFs without mass (supports, massless nodes) give μ = 0, no mode.
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense(mass), dense(shifted));
    if (solver.info() != Eigen::Success) {
      problem =
          "the dense eigensolver failed (K - sigma M not positive definite: the shift must "
          "lie below the lowest natural frequency)";
    } else {
      const Eigen::VectorXd& mu = solver.eigenvalues();  // ascending: largest μ, lowest λ last
      const double largest = mu.cwiseAbs().maxCoeff();
      for (long k = n - 1; k >= 0; --k) {
        if (!(mu(k) > 1e-12 * largest))
          break;
        lambdas.push_back(shift_ + 1.0 / mu(k));
        // φᵀ(K − σM)φ = 1 from the solver; φᵀMφ = μ, so φ / √μ is mass-normalized.
        const Eigen::VectorXd phi = solver.eigenvectors().col(k) / std::sqrt(mu(k));
        root_vectors.insert(root_vectors.end(), phi.data(), phi.data() + n);
      }
    }
  }
  share_root_verdict(*shifted_, problem);
  long n_found = static_cast<long>(lambdas.size());
  shifted_->getComm()->broadcast(0, sizeof(long), reinterpret_cast<char*>(&n_found));
  lambdas.resize(n_found);
  if (n_found > 0)
    shifted_->getComm()->broadcast(0, static_cast<int>(n_found * sizeof(double)),
                                   reinterpret_cast<char*>(lambdas.data()));
  result.eigenvalues = lambdas;
  result.vectors = Teuchos::rcp(new TpetraMultiVector(K_->getDomainMap(), std::max(n_found, 1L)));
  if (n_found > 0)
    shifted.scatter(root_vectors, *result.vectors);
  else
    result.vectors = Teuchos::null;
  result.converged = n_found >= settings.n_modes;
  result.complete = true;
  result.iteration_seconds = clock.seconds();
  return result;
}

}  // namespace railfe
