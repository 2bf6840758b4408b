#include "physics/statics/contact_newton.hpp"

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/error.hpp"
#include "framework/base/resources.hpp"
#include "framework/mesh/partition.hpp"
#include "framework/output/progress.hpp"
#include "framework/solvers/krylov_solver.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/statics/contact_linearization.hpp"

namespace railfe {

namespace {

// CG on a nearby factorization stops at this true relative residual: far below the contact
// tolerances (1e-6 and up) yet above the round-off of a 10⁶-equation solve.
constexpr double kReuseTolerance = 1e-10;
// Each CG iteration is one pair of triangular solves, about 1 % of a factorization at full scale:
// beyond this many a new factorization is cheaper.
constexpr int kReuseIterations = 40;

// Evaluates the contact at displacement \p u: its forces over the owned DOFs.
TpetraVector contact_forces(ContactPairs& contact, const std::vector<double>& x,
                            const TpetraVector& u) {
  TpetraVector forces(u.getMap());
  const auto u_data = u.getData();
  auto f_data = forces.getDataNonConst();
  contact.add_forces(x.data(), u_data.getRawPtr(), nullptr, 0, f_data.getRawPtr());
  return forces;
}

// K u − f less the reactions at the prescribed DOFs (from the rows the last apply() kept): the
// out-of-balance force without the contact's, affine in u.
// \p reactions_norm, when given, receives the reactions' 2-norm (a scale of the balance).
TpetraVector balance_without_contact(const TpetraMatrix& K, const TpetraVector& f,
                                     const LinearConstraints& constraints, const TpetraVector& u,
                                     double* reactions_norm = nullptr) {
  TpetraVector residual(u.getMap());
  K.apply(u, residual);
  residual.update(-1.0, f, 1.0);
  TpetraVector reactions(u.getMap());
  constraints.reactions(u, reactions);
  residual.update(-1.0, reactions, 1.0);
  if (reactions_norm != nullptr)
    *reactions_norm = reactions.norm2();
  return residual;
}

// The line search stops when the out-of-balance force's component along the step has fallen to
// this share of its value at the start, or after this many contact evaluations.
constexpr double kLineSearchReduction = 0.1;
constexpr int kLineSearchEvaluations = 8;

// Shortens the step d = u − previous to where the out-of-balance force has no component along
// it: the minimum of the penalty problem's energy along d (convex for frozen normals). A full
// step whose far end already pushes back (the force's component along d has changed sign) is
// overshoot: the bodies, held only by the few contacts of the linearisation, sink too deep.
// Each trial costs one contact evaluation (K u and the reactions are affine in u). Leaves u and
// \p f_contact at the step taken, the contact evaluated last there; returns its fraction of d.
double line_search(ContactPairs& contact, const std::vector<double>& x, const TpetraMatrix& K,
                   const TpetraVector& f, const LinearConstraints& constraints,
                   const TpetraVector& previous, const TpetraVector& f_contact_previous,
                   TpetraVector& u, TpetraVector& f_contact) {
  TpetraVector d(u, Teuchos::Copy);
  d.update(-1.0, previous, 1.0);
  const double at_start = d.dot(balance_without_contact(K, f, constraints, previous));
  const double at_end = d.dot(balance_without_contact(K, f, constraints, u));
  const auto slope = [&](double alpha, const TpetraVector& contact_force) {
    return (1 - alpha) * at_start + alpha * at_end - d.dot(contact_force);
  };
  double low = 0, slope_low = slope(0, f_contact_previous);
  double high = 1, slope_high = slope(1, f_contact);
  if (!(slope_low < 0 && slope_high > 0))
    return 1.0;
  const double target = kLineSearchReduction * -slope_low;
  TpetraVector trial(u.getMap());
  TpetraVector trial_force(u.getMap());
  double alpha = 1;
  int kept = 0;  // which end the last two trials kept (Illinois: halve a stale end's slope)
  for (int evaluation = 0; evaluation < kLineSearchEvaluations; ++evaluation) {
    alpha = (low * slope_high - high * slope_low) / (slope_high - slope_low);
    trial.update(1.0, previous, alpha, d, 0.0);
    trial_force = contact_forces(contact, x, trial);
    const double value = slope(alpha, trial_force);
    if (std::abs(value) <= target)
      break;
    if (value > 0) {
      high = alpha;
      slope_high = value;
      if (kept == 1)
        slope_low *= 0.5;
      kept = 1;
    } else {
      low = alpha;
      slope_low = value;
      if (kept == -1)
        slope_high *= 0.5;
      kept = -1;
    }
  }
  u.assign(trial);
  f_contact.assign(trial_force);
  return alpha;
}

}  // namespace

ContactNewtonReport solve_with_contact(const Teuchos::RCP<TpetraMatrix>& K, const TpetraVector& f,
                                       LinearConstraints& constraints, LinearSolver& solver,
                                       const ProblemTraits& traits, ContactPairs& contact,
                                       const DofMap& dofs, int max_iterations, double tolerance,
                                       const std::string& path, TpetraVector& u,
                                       Progress& progress) {
  const MeshPartition& partition = dofs.partition();
  std::vector<double> x(3 * static_cast<std::size_t>(partition.n_owned_nodes()));
  for (LocalIndex node = 0; node < partition.n_owned_nodes(); ++node)
    std::copy_n(partition.coordinates(node), 3, &x[3 * node]);

  ContactNewtonReport report;
  std::ostringstream history;
  history.precision(3);
  double setup_seconds = 0, solve_seconds = 0;
  TpetraVector f_contact = contact_forces(contact, x, u);
  const bool start_holds_constraints = constraints.holds_prescribed_values(u);
  TpetraVector previous(u.getMap());
  TpetraVector constrained(u.getMap());
  Teuchos::RCP<TpetraOperator> factor;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    const ContactLinearization linear = linearize_contact(contact, dofs);
    const auto tangent = Tpetra::MatrixMatrix::add(1.0, false, *K, 1.0, false, *linear.stiffness);
    TpetraVector rhs(f, Teuchos::Copy);
    rhs.update(1.0, *linear.force, 1.0);
    const auto system = constraints.apply(tangent, rhs);
    previous.assign(u);
    // The tangent differs from the last factorized one only where contacts came, went or moved:
    // CG preconditioned by that factorization usually converges in a few solves with it, a
    // fraction of a new factorization; when it does not, factorize.
    std::optional<SolveReport> reused;
    if (report.factorizations > 0 && !factor.is_null()) {
      const Stopwatch clock;
      u.assign(constrained);
      reused = try_preconditioned_cg(system, factor, rhs, u, kReuseTolerance, kReuseIterations);
      if (!reused)
        solve_seconds += clock.seconds();  // spent in vain, but spent
    }
    if (reused) {
      report.solve = *reused;
      solve_seconds += reused->solve_seconds;
      ++report.reused_factorizations;
    } else {
      solver.setup(system, traits);
      report.solve = solver.solve(rhs, u);
      setup_seconds += report.solve.setup_seconds;
      solve_seconds += report.solve.solve_seconds;
      factor = solver.factor_operator();
      ++report.factorizations;
    }
    constrained.assign(u);
    constraints.recover(u);
    report.iterations = iteration;

    // Out of balance at the new state with the exact contact force: K u − f − f_c(u), less the
    // reactions at the prescribed DOFs.
    const TpetraVector f_contact_previous(f_contact, Teuchos::Copy);
    f_contact = contact_forces(contact, x, u);
    // The first step may also move prescribed DOFs to their values: then only its end keeps them.
    if ((iteration > 1 || start_holds_constraints) &&
        line_search(contact, x, *K, f, constraints, previous, f_contact_previous, u, f_contact) <
            1.0)
      ++report.line_searches;
    // A step that lifts every contact off (many overlapping penalty springs pushing at once on
    // a fine mesh) leaves the next linearisation nothing to hold the bodies with, and the
    // iterations never come back: shorten it until some contact remains.
    for (int halving = 0; linear.active > 0 && halving < 20 && !(f_contact.norm2() > 0);
         ++halving) {
      u.update(0.5, previous, 0.5);
      f_contact = contact_forces(contact, x, u);
      ++report.shortened_steps;
    }
    double reactions_norm = 0;
    TpetraVector residual = balance_without_contact(*K, f, constraints, u, &reactions_norm);
    residual.update(-1.0, f_contact, 1.0);
    const double scale = std::max({f.norm2(), reactions_norm, f_contact.norm2(), 1e-300});
    report.residual = residual.norm2() / scale;
    report.active = linear.active;
    report.contact_force = f_contact.norm2();
    history << (iteration > 1 ? ", " : "") << report.residual << " (" << linear.active
            << " active)";
    progress.update(iteration);
    if (!std::isfinite(report.residual))
      break;
    if (report.residual <= tolerance) {
      report.solve.setup_seconds = setup_seconds;
      report.solve.solve_seconds = solve_seconds;
      return report;
    }
  }
  std::ostringstream limit;
  limit << tolerance;
  throw RunError(path + ": the contact iterations did not converge in " +
                 std::to_string(report.iterations) + " (Contact iterations) to Contact tolerance " +
                 limit.str() + "; relative out-of-balance force per iteration: " + history.str() +
                 ". An active set that keeps changing points to bodies that are not held against "
                 "rigid motion along the contact surface, or to a Penalty factor far above 1. A "
                 "force that stalls while the active set stays the same is the linearisation's "
                 "limit on curved, deforming surfaces (about 1e-5 to 1e-4 of the force, "
                 "docs/verification.md#contact-hertz-cylinder): a Contact tolerance above the "
                 "stalled value accepts it");
}

}  // namespace railfe
