#include "physics/statics/contact_newton.hpp"

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "framework/assembly/linear_constraints.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/partition.hpp"
#include "framework/output/progress.hpp"
#include "physics/common/contact_pairs.hpp"
#include "physics/statics/contact_linearization.hpp"

namespace railfe {

namespace {

// Evaluates the contact at displacement \p u: its forces over the owned DOFs.
TpetraVector contact_forces(ContactPairs& contact, const std::vector<double>& x,
                            const TpetraVector& u) {
  TpetraVector forces(u.getMap());
  const auto u_data = u.getData();
  auto f_data = forces.getDataNonConst();
  contact.add_forces(x.data(), u_data.getRawPtr(), nullptr, 0, f_data.getRawPtr());
  return forces;
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
  TpetraVector previous(u.getMap());
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    const ContactLinearization linear = linearize_contact(contact, dofs);
    const auto tangent = Tpetra::MatrixMatrix::add(1.0, false, *K, 1.0, false, *linear.stiffness);
    TpetraVector rhs(f, Teuchos::Copy);
    rhs.update(1.0, *linear.force, 1.0);
    const auto system = constraints.apply(tangent, rhs);
    solver.setup(system, traits);
    previous.assign(u);
    report.solve = solver.solve(rhs, u);
    setup_seconds += report.solve.setup_seconds;
    solve_seconds += report.solve.solve_seconds;
    constraints.recover(u);
    report.iterations = iteration;

    // Out of balance at the new state with the exact contact force: K u − f − f_c(u), less the
    // reactions at the prescribed DOFs.
    f_contact = contact_forces(contact, x, u);
    // A step that lifts every contact off (many overlapping penalty springs pushing at once on
    // a fine mesh) leaves the next linearisation nothing to hold the bodies with, and the
    // iterations never come back: shorten it until some contact remains.
    for (int halving = 0; linear.active > 0 && halving < 20 && !(f_contact.norm2() > 0);
         ++halving) {
      u.update(0.5, previous, 0.5);
      f_contact = contact_forces(contact, x, u);
      ++report.shortened_steps;
    }
    TpetraVector residual(u.getMap());
    K->apply(u, residual);
    residual.update(-1.0, f, -1.0, f_contact, 1.0);
    TpetraVector reactions(u.getMap());
    constraints.reactions(u, reactions);
    residual.update(-1.0, reactions, 1.0);
    const double scale = std::max({f.norm2(), reactions.norm2(), f_contact.norm2(), 1e-300});
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
