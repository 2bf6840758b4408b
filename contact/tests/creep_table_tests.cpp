// The creep-force table: at its nodes it is the exact solver (also at another size and load,
// which checks the similarity it rests on), between them it stays close, and it is odd in the
// creepages.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "contact/laws/creep_table.hpp"
#include "contact/laws/hertz.hpp"
#include "contact/laws/normal_problem.hpp"
#include "contact/laws/tangential_problem.hpp"

namespace railfe {
namespace {

constexpr double kE = 210e9, kNu = 0.3, kG = kE / (2 * (1 + kNu));

// The exact solver on the table's grid for semi-axes a x b, load N and friction mu.
CreepForces exact(double a, double b, double load, double mu, const Creepages& creep) {
  const int m = CreepTable::shipped().axes().grid;
  const double modulus = contact_modulus({kE, kNu}, {kE, kNu});
  const HertzContact h = hertz_from_semi_axes(a, b, modulus, load);
  const HertzPatch patch = solve_hertz_patch(h, kG, kNu, m);
  FrictionLaw friction;
  friction.static_coefficient = friction.dynamic_coefficient = mu;
  TangentialSettings settings;
  settings.leading_edge = patch.leading_edge;
  return solve_tangential(*patch.kernels, patch.normal.pressure, creep, friction, settings).forces;
}

// Creepages at normalized values s (s = t / (1 - |t|) at a node).
Creepages at(double a, double b, double load, double mu, double sx, double sy, double sphi) {
  const double p0 = 3 * load / (2 * M_PI * a * b), unit = mu * p0 / kG;
  return {sx * unit, sy * unit, sphi * unit / a};
}

TEST(CreepTable, NodesAreTheExactSolverAtAnySizeAndLoad) {
  // The table was made at a = 5 mm, 100 kN, mu 0.3; here a = 8 mm, 60 kN, mu 0.2.
  const double a = 8e-3, b = 4e-3, load = 6e4, mu = 0.2;  // a/b = 2, a node
  for (const auto& node : {std::array<double, 3>{0.25, 0, 0}, std::array<double, 3>{0, 0.25, 0},
                           std::array<double, 3>{0.25, -2.0 / 3, 0.25}}) {
    const Creepages creep = at(a, b, load, mu, node[0], node[1], node[2]);
    const CreepForces table = CreepTable::shipped().forces(a, b, kG, kNu, load, mu, creep);
    const CreepForces solver = exact(a, b, load, mu, creep);
    EXPECT_NEAR(table.Fx, solver.Fx, 1e-6 * mu * load);
    EXPECT_NEAR(table.Fy, solver.Fy, 1e-6 * mu * load);
    EXPECT_NEAR(table.Mz, solver.Mz, 1e-6 * mu * load * a);
  }
}

TEST(CreepTable, BetweenNodesItStaysCloseToTheExactSolver) {
  const double a = 6e-3, b = 5e-3, load = 1e5, mu = 0.3;  // a/b = 1.2, between nodes
  double worst = 0;
  for (const auto& s : {std::array<double, 3>{0.13, 0, 0}, std::array<double, 3>{0, 0.37, 0},
                        std::array<double, 3>{0.5, 0.2, 0.1}, std::array<double, 3>{2.3, 0, 0.6},
                        std::array<double, 3>{-0.8, 1.1, -0.3}}) {
    const Creepages creep = at(a, b, load, mu, s[0], s[1], s[2]);
    const CreepForces table = CreepTable::shipped().forces(a, b, kG, kNu, load, mu, creep);
    const CreepForces solver = exact(a, b, load, mu, creep);
    worst = std::max(worst, std::hypot(table.Fx - solver.Fx, table.Fy - solver.Fy) / (mu * load));
  }
  // Linear in ln(a/b) and cubic in the creepages on nine nodes: about 2.5 % of μN at worst,
  // the exact 30 x 30 solver's own error against a fine grid being 1.7 %.
  EXPECT_LT(worst, 0.03);
}

TEST(CreepTable, IsOddInTheCreepagesAndRefusesWhatItDoesNotCover) {
  const CreepTable& table = CreepTable::shipped();
  const Creepages creep{1.3e-3, -0.7e-3, 0.4};
  const CreepForces f = table.forces(7e-3, 5e-3, kG, kNu, 1e5, 0.3, creep);
  const CreepForces g = table.forces(7e-3, 5e-3, kG, kNu, 1e5, 0.3, {-1.3e-3, 0.7e-3, -0.4});
  EXPECT_NEAR(f.Fx, -g.Fx, 1e-9 * std::abs(f.Fx));
  EXPECT_NEAR(f.Fy, -g.Fy, 1e-9 * std::abs(f.Fy));
  EXPECT_THROW(table.forces(7e-3, 0.5e-3, kG, kNu, 1e5, 0.3, creep), std::invalid_argument);
  EXPECT_THROW(table.forces(7e-3, 5e-3, kG, 0.25, 1e5, 0.3, creep), std::invalid_argument);
}

}  // namespace
}  // namespace railfe
