#include "physics/wheelset_dynamics/vehicle_balance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/geometry/contact_table.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

// The unknowns the balance moves (see the file comment), and which of them are the wheelsets'.
struct BalanceUnknowns {
  std::vector<Eigen::Index> all, bodies;
};

BalanceUnknowns balance_unknowns(VehicleSystem& system) {
  std::vector<char> wheelset(system.n_model_unknowns(), 0);
  for (int w = 0; w < system.n_wheelsets(); ++w)
    wheelset[system.wheelset(w).unknowns().wheelset] = 1;
  BalanceUnknowns unknowns;
  for (Eigen::Index node = 0; node < system.n_model_unknowns(); node += 6) {
    if (wheelset[node]) {
      unknowns.all.insert(unknowns.all.end(), {node + 2, node + 3});
      continue;
    }
    for (Eigen::Index c : {1, 2, 3, 4}) {
      unknowns.all.push_back(node + c);
      unknowns.bodies.push_back(node + c);
    }
  }
  return unknowns;
}

Eigen::VectorXd residual(VehicleSystem& system, const std::vector<double>& u,
                         const std::vector<Eigen::Index>& rows) {
  std::vector<double> zero(u.size(), 0.0), internal(u.size()), external(u.size());
  system.internal_force(u.data(), zero.data(), internal.data());
  system.external_force(0, external.data());
  Eigen::VectorXd r(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    r(static_cast<Eigen::Index>(i)) = external[rows[i]] - internal[rows[i]];
  return r;
}

Eigen::MatrixXd restricted(const Eigen::MatrixXd& matrix, const std::vector<Eigen::Index>& rows) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      out(i, j) = matrix(rows[i], rows[j]);
  return out;
}

}  // namespace

VehicleBalance balance_vehicle(VehicleSystem& system, const WheelRailGeometry& geometry,
                               std::vector<double>& u) {
  for (int w = 0; w < system.n_wheelsets(); ++w)
    system.wheelset(w).set_rolling(false);
  VehicleBalance balance;
  std::vector<double> external(u.size()), zero(u.size(), 0.0);
  system.external_force(0, external.data());
  for (Eigen::Index node = 0; node < system.n_model_unknowns(); node += 6)
    balance.weight += external[node + 2];

  // Each wheelset where its profiles touch the rails, with the Hertz approach of a light load
  // (so Newton starts where the force grows with the approach).
  for (int w = 0; w < system.n_wheelsets(); ++w) {
    const WheelsetUnknowns at = system.wheelset(w).unknowns();
    const double rail_y = u[at.nodes + 1], rail_z = u[at.nodes + 2];
    const double relative = u[at.wheelset + 1] - rail_y;
    const RigidContact rigid = solve_rigid_contact(geometry, relative, 0.0, nullptr);
    if (!rigid.converged) {
      std::ostringstream message;
      message << "wheelset " << w + 1 << " cannot be placed on the rails at a lateral shift of "
              << relative
              << " m: the rigid contact of the profiles was not found (the profiles do not touch "
                 "there; see the profiles' Track dimensions)";
      throw RunError(message.str());
    }
    u[at.wheelset + 2] = rail_z + rigid.vertical + 2e-5;
    u[at.wheelset + 3] = rigid.roll;
  }
  const BalanceUnknowns unknowns = balance_unknowns(system);
  Eigen::MatrixXd stiffness, damping;
  // The bodies on their suspensions over the placed wheelsets: linear, one solve.
  {
    system.tangent(u.data(), zero.data(), stiffness, damping);
    const Eigen::VectorXd r = residual(system, u, unknowns.bodies);
    const Eigen::VectorXd step = restricted(stiffness, unknowns.bodies).lu().solve(r);
    for (std::size_t i = 0; i < unknowns.bodies.size(); ++i)
      u[unknowns.bodies[i]] += step(static_cast<Eigen::Index>(i));
  }
  const double scale = std::max(balance.weight, 1.0);
  for (; balance.iterations < 200; ++balance.iterations) {
    const Eigen::VectorXd r = residual(system, u, unknowns.all);
    balance.residual = r.cwiseAbs().maxCoeff();
    if (balance.residual <= 1e-10 * scale)
      return balance;
    system.tangent(u.data(), zero.data(), stiffness, damping);
    Eigen::VectorXd step = restricted(stiffness, unknowns.all).partialPivLu().solve(r);
    if (!step.allFinite())
      break;
    // A Hertz spring is soft near zero approach: limit each wheelset's step to 0.1 mm and
    // 1 mrad, the whole step scaled alike.
    double limit = 1;
    for (std::size_t i = 0; i < unknowns.all.size(); ++i) {
      const Eigen::Index k = unknowns.all[i];
      const bool body = std::binary_search(unknowns.bodies.begin(), unknowns.bodies.end(), k);
      if (!body)
        limit = std::max(limit,
                         std::abs(step(static_cast<Eigen::Index>(i))) / (k % 6 == 2 ? 1e-4 : 1e-3));
    }
    step /= limit;
    for (std::size_t i = 0; i < unknowns.all.size(); ++i)
      u[unknowns.all[i]] += step(static_cast<Eigen::Index>(i));
  }
  std::ostringstream message;
  message << "the static balance of the vehicle did not converge (largest residual "
          << balance.residual << " N after " << balance.iterations << " Newton iterations)";
  throw RunError(message.str());
}

}  // namespace railfe
