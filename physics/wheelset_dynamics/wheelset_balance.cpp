#include "physics/wheelset_dynamics/wheelset_balance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/geometry/contact_table.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

// The vertical and roll residuals f_ext − f_int at u (velocities zero).
std::array<double, 2> residual(WheelsetSystem& system, const std::vector<double>& u) {
  std::vector<double> zero(u.size(), 0.0), internal(u.size()), external(u.size());
  system.internal_force(u.data(), zero.data(), internal.data());
  system.external_force(0, external.data());
  return {external[2] - internal[2], external[3] - internal[3]};
}

}  // namespace

WheelsetBalance balance_wheelset(WheelsetSystem& system, const WheelRailGeometry& geometry,
                                 std::vector<double>& u, bool rolling) {
  system.set_rolling(rolling);
  // Rails' offsets are the same for all internal nodes: take the right tread's.
  const double rail_y = u[6 + 1], rail_z = u[6 + 2];
  const double relative = u[1] - rail_y;
  const RigidContact rigid = solve_rigid_contact(geometry, relative, 0.0, nullptr);
  if (!rigid.converged) {
    std::ostringstream message;
    message << "the wheelset cannot be placed on the rails at a lateral shift of " << relative
            << " m: the rigid contact of the profiles was not found (the profiles do not touch "
               "there; see Initial lateral shift and the profiles' Track dimensions)";
    throw RunError(message.str());
  }
  std::vector<double> external(u.size());
  system.external_force(0, external.data());
  WheelsetBalance balance;
  balance.weight = external[2];
  // Start from the Hertz approach of half the load on each wheel, a guess within a factor of
  // a few, so that Newton starts where the force grows with the approach.
  u[2] = rail_z + rigid.vertical + 2e-5;
  u[3] = rigid.roll;
  const double scale = std::max(balance.weight, 1.0);
  for (; balance.iterations < 100; ++balance.iterations) {
    const auto r = residual(system, u);
    balance.residual = std::hypot(r[0], r[1]);
    if (balance.residual <= 1e-10 * scale)
      return balance;
    // Jacobian by forward differences (the search is exact to 1e-12 m).
    double J[2][2];
    for (int j = 0; j < 2; ++j) {
      std::vector<double> moved = u;
      const double h = 1e-9;
      moved[2 + j] += h;
      const auto rj = residual(system, moved);
      for (int i = 0; i < 2; ++i)
        J[i][j] = (rj[i] - r[i]) / h;
    }
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(std::abs(det) > 0) || !std::isfinite(det))
      break;
    double dz = -(J[1][1] * r[0] - J[0][1] * r[1]) / det;
    double droll = -(-J[1][0] * r[0] + J[0][0] * r[1]) / det;
    // A Hertz spring is soft near zero approach: limit each step to 0.1 mm and 1 mrad.
    const double limit = std::max(std::abs(dz) / 1e-4, std::abs(droll) / 1e-3);
    if (limit > 1) {
      dz /= limit;
      droll /= limit;
    }
    u[2] += dz;
    u[3] += droll;
  }
  std::ostringstream message;
  message << "the static balance of the wheelset did not converge (residual " << balance.residual
          << " N after " << balance.iterations << " Newton iterations)";
  throw RunError(message.str());
}

WheelsetBalance balance_on_rail_beams(WheelsetSystem& system, const WheelRailGeometry& geometry,
                                      BeamRails& rails, SparseLinearSystem& structure,
                                      std::vector<double>& u, bool rolling) {
  const std::size_t ns = structure.n_unknowns();
  MatrixCoefficients statics;
  statics.stiffness = 1;
  structure.factor(u.data(), u.data(), statics);
  std::vector<double> uv(u.begin() + static_cast<long>(ns), u.end());
  std::vector<double> zero(uv.size(), 0.0), force(uv.size()), lambda(3 * n_wheelset_contacts);
  std::vector<double> load(u.size()), rails_u(ns);
  ConstraintRows rows;
  WheelsetBalance balance;
  double moved = 0;
  for (int round = 0; round < 30; ++round) {
    // The internal nodes where the rows put them on the rails' present shape.
    const auto displacement = rails.rail_displacements(0, u.data());
    const auto offset = rails.offsets(0);
    moved = 0;
    for (std::size_t r = 0; r < displacement.size(); ++r) {
      const double node = displacement[r] + (r % 3 == 0 ? 0.0 : offset[r % 3 - 1]);
      moved = std::max(moved, std::abs(node - uv[6 + r]));
      uv[6 + r] = node;
    }
    if (round > 0 && moved <= 1e-13)
      break;
    const WheelsetBalance wheelset = balance_wheelset(system, geometry, uv, rolling);
    balance.iterations += wheelset.iterations;
    balance.residual = wheelset.residual;
    balance.weight = wheelset.weight;
    rails.set_levers(system.contact_states(uv.data(), zero.data()));
    rows.clear();
    rails.rows_at(0, rows);
    // The nodes carry no load of their own: f_int + Cᵀλ = 0 on each (its entry is 1).
    system.internal_force(uv.data(), zero.data(), force.data());
    for (std::size_t r = 0; r < lambda.size(); ++r)
      lambda[r] = -force[6 + r];
    std::fill(load.begin(), load.end(), 0.0);
    rows.add_transpose(lambda.data(), -1.0, load.data());
    structure.solve(load.data(), rails_u.data());
    std::copy(rails_u.begin(), rails_u.end(), u.begin());
  }
  if (moved > 1e-13) {
    std::ostringstream message;
    message << "the static balance of the wheelset on its rail beams did not settle (the rails "
               "under the contacts still moved "
            << moved << " m in the last round)";
    throw RunError(message.str());
  }
  std::copy(uv.begin(), uv.end(), u.begin() + static_cast<long>(ns));
  return balance;
}

}  // namespace railfe
