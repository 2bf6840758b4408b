// The exact steady-rolling solver on the half-space grid: the normal problem against Hertz and
// on a two-patch (non-elliptic) contact, the creep curve's initial slope against Kalker's
// linear theory within 2 % on a 40 x 40 grid with grid convergence, spin's coefficients and
// second-order convergence in spin, and full saturation at μN.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/laws/hertz.hpp"
#include "contact/laws/normal_problem.hpp"
#include "contact/laws/tangential_problem.hpp"

namespace railfe {
namespace {

constexpr double kE = 210e9, kNu = 0.3, kG = kE / (2 * (1 + kNu)), kLoad = 1e5;

// The Hertz case on an m x m grid reaching 10 % beyond the ellipse.
struct Patch {
  HertzContact hertz;
  ContactGrid grid;
  HalfSpaceKernels kernels;
  NormalSolution normal;
  TangentialSettings settings;  ///< the ellipse's leading edge
  explicit Patch(int m, double margin = 1.1)
      : hertz(hertz_contact(1 / (2 * 0.46), 1 / (2 * 0.30), contact_modulus({kE, kNu}, {kE, kNu}),
                            kLoad)),
        grid{-margin * hertz.a,
             -margin * hertz.b,
             2 * margin * hertz.a / m,
             2 * margin * hertz.b / m,
             m,
             m},
        kernels(grid, kG, kNu) {
    std::vector<double> separation(grid.size());
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        separation[j * m + i] = hertz.A * grid.x(i) * grid.x(i) + hertz.B * grid.y(j) * grid.y(j);
    normal = solve_normal(kernels, separation, kLoad);
    settings.leading_edge = hertz_leading_edge(hertz, grid);
  }
};

TEST(ExactSolver, NormalProblemReproducesHertz) {
  const Patch patch(40);
  ASSERT_TRUE(patch.normal.converged);
  EXPECT_NEAR(patch.normal.load, kLoad, 1e-9 * kLoad);
  EXPECT_NEAR(patch.normal.max_pressure, patch.hertz.pressure, 0.002 * patch.hertz.pressure);
  EXPECT_NEAR(patch.normal.approach, patch.hertz.approach, 0.0005 * patch.hertz.approach);
  EXPECT_NEAR(patch.normal.area, M_PI * patch.hertz.a * patch.hertz.b,
              0.01 * M_PI * patch.hertz.a * patch.hertz.b);
}

TEST(ExactSolver, FftConvolutionEqualsDirectSummation) {
  const ContactGrid grid{-1e-3, -2e-3, 1e-4, 2e-4, 17, 13};  // odd sizes, unequal sides
  const HalfSpaceKernels kernels(grid, kG, kNu);
  std::vector<double> p(grid.size());
  for (std::size_t e = 0; e < p.size(); ++e)
    p[e] = std::sin(0.7 * e) * 1e8;
  const std::vector<double> fast = kernels.normal(p), direct = kernels.normal_direct(p);
  double scale = 0;
  for (double u : direct)
    scale = std::max(scale, std::abs(u));
  for (std::size_t e = 0; e < p.size(); ++e)
    EXPECT_NEAR(fast[e], direct[e], 1e-12 * scale);
}

TEST(ExactSolver, NormalProblemHandlesTwoSeparatePatches) {
  // Two bumps 8 mm apart along y (the lower envelope of two paraboloids): two patches, no
  // pressure between them, the deformed gap closed where pressed and open elsewhere.
  const int m = 48;
  const ContactGrid grid{-6e-3, -10e-3, 12e-3 / m, 20e-3 / m, m, m};
  const HalfSpaceKernels kernels(grid, kG, kNu);
  std::vector<double> separation(grid.size());
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x = grid.x(i), y = grid.y(j);
      separation[j * m + i] = std::min(1.1 * x * x + 1.7 * (y - 4e-3) * (y - 4e-3) + 2e-6,
                                       1.1 * x * x + 1.7 * (y + 4e-3) * (y + 4e-3));
    }
  const NormalSolution s = solve_normal(kernels, separation, 5e4);
  ASSERT_TRUE(s.converged);
  const std::vector<double> u = kernels.normal(s.pressure);
  double left = 0, right = 0, between = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int e = j * m + i;
      const double gap = separation[e] + u[e] - s.approach;
      if (s.pressure[e] > 0)
        EXPECT_NEAR(gap, 0, 1e-9 * s.approach);
      else
        EXPECT_GT(gap, -1e-9 * s.approach);
      const double y = grid.y(j);
      (std::abs(y) < 1e-3 ? between : (y < 0 ? left : right)) += s.pressure[e];
    }
  EXPECT_EQ(between, 0);
  // The bump 2 um closer carries more: Hertz alone would give (δ / (δ - 2 um))^1.5, about 6 %.
  EXPECT_GT(left, 1.05 * right);
  EXPECT_GT(right, 0);
}

TEST(ExactSolver, InitialSlopeIsKalkersLinearTheoryWithinTwoPercent) {
  const FrictionLaw coulomb;
  double previous = 1;
  for (int m : {20, 40, 60}) {
    const Patch patch(m);
    const KalkerCoefficients c = KalkerTable::shipped().at(patch.hertz.a, patch.hertz.b, kNu);
    const double creep = 1e-6;
    const TangentialSolution sx = solve_tangential(patch.kernels, patch.normal.pressure,
                                                   {creep, 0, 0}, coulomb, patch.settings);
    const TangentialSolution sy = solve_tangential(patch.kernels, patch.normal.pressure,
                                                   {0, creep, 0}, coulomb, patch.settings);
    ASSERT_TRUE(sx.converged && sy.converged);
    const CreepForces lx = kalker_linear(c, kG, patch.hertz.a, patch.hertz.b, {creep, 0, 0});
    const CreepForces ly = kalker_linear(c, kG, patch.hertz.a, patch.hertz.b, {0, creep, 0});
    const double error =
        std::max(std::abs(sx.forces.Fx / lx.Fx - 1), std::abs(sy.forces.Fy / ly.Fy - 1));
    if (m == 40) {
      EXPECT_LT(error, 0.02);
    }
    EXPECT_LT(error, previous);  // converging with the grid
    previous = error;
  }
}

TEST(ExactSolver, SpinCoefficientsMatchKalkerOnCoarseGrids) {
  // The spin moment's initial slope is C33. With the transport term second order it lies within
  // 2 % of Kalker's table on every grid from 32 to 60 elements a side (-0.2 % at 40; first order:
  // +6 to +13 %). C23, the lateral force of spin and (Kalker's symmetry) the moment of η, within
  // 1.5 %. What is left is the contact area's staircase, which moves C11 and C22 as much.
  const FrictionLaw coulomb;
  for (int m = 32; m <= 60; m += 4) {
    const Patch patch(m);
    const KalkerCoefficients c = KalkerTable::shipped().at(patch.hertz.a, patch.hertz.b, kNu);
    const double ab = patch.hertz.a * patch.hertz.b, root = std::sqrt(ab);
    const double creep = 1e-6, spin = creep / root;
    const TangentialSolution ts = solve_tangential(patch.kernels, patch.normal.pressure,
                                                   {0, 0, spin}, coulomb, patch.settings);
    const TangentialSolution ty = solve_tangential(patch.kernels, patch.normal.pressure,
                                                   {0, creep, 0}, coulomb, patch.settings);
    ASSERT_TRUE(ts.converged && ty.converged);
    const double C33 = -ts.forces.Mz / (kG * ab * ab * spin);
    const double C23_spin = -ts.forces.Fy / (kG * ab * root * spin);
    const double C23_lateral = ty.forces.Mz / (kG * ab * root * creep);
    EXPECT_NEAR(C33, c.C33, (m == 40 ? 0.01 : 0.02) * c.C33) << m << " elements";
    EXPECT_NEAR(C23_spin, c.C23, 0.015 * c.C23) << m << " elements";
    EXPECT_NEAR(C23_lateral, c.C23, 0.015 * c.C23) << m << " elements";
  }
}

TEST(ExactSolver, SpinCasesConvergeAndMeetOnePercentAt40) {
  // Small spin 0.5 /m, large spin 2 /m and lateral creepage with spin (η 1e-3, φ 2 /m), μ 0.3:
  // the lateral force on grids of 20, 40 and 80 elements. The 40 x 40 force lies within 1 % of
  // the extrapolated limit F80 + (F80 - F40) / 3 (small spin: -0.26 %; with BDF2 on the leading
  // elements too, -1.4 %, and 1.8 % low against 120 x 120). Halving the element cuts the change
  // more than threefold in pure spin (0.5 /m: 6.0, BDF2 on the leading elements 2.2, first order
  // 2.4 at 2 /m; 2 /m: 3.1). The combined case's ratio is 3.0 (2.98 since the leading elements
  // take the edge's form, 3.06 before), so it is held to the 1 % only.
  FrictionLaw coulomb;
  coulomb.static_coefficient = coulomb.dynamic_coefficient = 0.3;
  for (const Creepages creep :
       {Creepages{0, 0, 0.5}, Creepages{0, 0, 2.0}, Creepages{0, 1e-3, 2.0}}) {
    double force[3];
    for (int k = 0; k < 3; ++k) {
      const Patch patch(20 << k);
      const TangentialSolution t =
          solve_tangential(patch.kernels, patch.normal.pressure, creep, coulomb, patch.settings);
      ASSERT_TRUE(t.converged);
      force[k] = t.forces.Fy;
    }
    const double limit = force[2] + (force[2] - force[1]) / 3;
    if (creep.lateral == 0) {
      EXPECT_GT(std::abs(force[0] - force[1]), 3 * std::abs(force[1] - force[2])) << creep.spin;
    }
    EXPECT_NEAR(force[1], limit, 0.01 * std::abs(limit)) << creep.lateral << ' ' << creep.spin;
  }
}

TEST(ExactSolver, LargeCreepageSaturatesAtMuN) {
  const Patch patch(30);
  FrictionLaw coulomb;
  coulomb.static_coefficient = coulomb.dynamic_coefficient = 0.25;
  const TangentialSolution t = solve_tangential(patch.kernels, patch.normal.pressure,
                                                {0.3, -0.4, 0}, coulomb, patch.settings);
  ASSERT_TRUE(t.converged);
  // Every element slides: |q| = μp everywhere, so |F| = μN; the slip, and the force, point
  // along the rigid slip up to the elastic strain (about 1e-3 against 0.5).
  EXPECT_NEAR(std::hypot(t.forces.Fx, t.forces.Fy), 0.25 * kLoad, 1e-4 * kLoad);
  EXPECT_NEAR(t.forces.Fy / t.forces.Fx, -4.0 / 3, 0.01);
  EXPECT_EQ(t.adhesion_fraction, 0);
}

TEST(ExactSolver, CentralStripOfALongEllipseIsCartersRollingCylinder) {
  // b / a = 10: the strip through the centre rolls as a 2-D cylinder. Carter: adhesion over the
  // leading 2a' of the strip, and F = μP (1 - (a'/a)²) per unit length, for creepage
  // ξ = μ a (1 - a'/a) / R with R from 2-D Hertz (p0 = a E* / 2R).
  const int m = 40;
  const double a = 5e-3, b = 10 * a, mu = 0.3;
  const double modulus = contact_modulus({kE, kNu}, {kE, kNu});
  const HertzContact h = hertz_from_semi_axes(a, b, modulus, kLoad);
  // At 40 elements the patch grid reaches 10 % beyond the ellipse.
  const HertzPatch patch = solve_hertz_patch(h, kG, kNu, m);
  const ContactGrid& grid = patch.kernels->grid();
  const HalfSpaceKernels& kernels = *patch.kernels;
  const NormalSolution& normal = patch.normal;
  const int strip = m / 2;
  const double y = grid.y(strip), half = a * std::sqrt(1 - (y / b) * (y / b));
  const double p0 = h.pressure * std::sqrt(1 - (y / b) * (y / b));
  const double radius = half * modulus / (2 * p0);
  FrictionLaw coulomb;
  coulomb.static_coefficient = coulomb.dynamic_coefficient = mu;
  for (double ratio : {0.25, 0.5, 0.75}) {
    const double creep = mu * half * (1 - ratio) / radius;
    TangentialSettings settings;
    settings.leading_edge = patch.leading_edge;
    const TangentialSolution t =
        solve_tangential(kernels, normal.pressure, {creep, 0, 0}, coulomb, settings);
    ASSERT_TRUE(t.converged);
    double force = 0, load = 0;
    int in_contact = 0, adhering = 0;
    for (int i = 0; i < m; ++i) {
      const int e = strip * m + i;
      force += t.qx[e] * grid.dx;
      load += normal.pressure[e] * grid.dx;
      in_contact += normal.pressure[e] > 0;
      adhering += normal.pressure[e] > 0 && t.adhesion[e];
    }
    EXPECT_NEAR(-force / (mu * load), 1 - ratio * ratio, 0.015 * (1 - ratio * ratio));
    EXPECT_NEAR(adhering, ratio * in_contact, 1.0);
  }
}

TEST(ExactSolver, FallingFrictionThatLeavesTheSteadyStateOpenIsReported) {
  // Coulomb friction: one steady state. Friction falling steeply with slip velocity (μs 0.4,
  // μd 0.1, c 100 s/m at 30 m/s): starting from no traction and from full slip ends in states
  // 8e-3 μN apart, so no force is returned. A mild fall (c 10 s/m) settles to one state from
  // both starts.
  const Patch patch(20);
  FrictionLaw falling;
  falling.static_coefficient = 0.4;
  falling.dynamic_coefficient = 0.1;
  falling.decay = 100;
  double spread = -1;
  const TangentialSolution open = solve_steady_rolling(
      patch.kernels, patch.normal.pressure, {2e-3, 0, 0}, falling, 1e-6, &spread, patch.settings);
  EXPECT_FALSE(open.converged);
  EXPECT_TRUE(std::isnan(open.forces.Fx));
  EXPECT_GT(spread, 1e-3);
  FrictionLaw mild = falling;
  mild.decay = 10;
  const TangentialSolution settled = solve_steady_rolling(
      patch.kernels, patch.normal.pressure, {2e-3, 0, 0}, mild, 1e-6, &spread, patch.settings);
  EXPECT_TRUE(settled.converged);
  EXPECT_LT(spread, 1e-9);
}

TEST(ExactSolver, RefusesAGridThatDoesNotEncloseTheContact) {
  const Patch patch(20, 1.0);
  EXPECT_THROW(solve_tangential(patch.kernels, patch.normal.pressure, {1e-4, 0, 0}, {}),
               std::invalid_argument);
}

// Hertz's separation B y² sampled every 0.1 mm over +-15 mm.
LateralSeparation sampled_crown(const HertzContact& hertz, double centre = 0) {
  LateralSeparation lateral;
  for (int k = -150; k <= 150; ++k) {
    const double y = centre + k * 1e-4;
    lateral.y.push_back(y);
    lateral.s.push_back(hertz.B * (y - centre) * (y - centre) + 3e-3);
  }
  return lateral;
}

TEST(ExactSolver, SeparationPatchOfHertzsSeparationIsHertzsPatch) {
  const Patch reference(40);
  const HertzContact& h = reference.hertz;
  SeparationPatchInfo info;
  // Off-centre and lifted: only differences of s count, and the grid follows the contact.
  const HertzPatch patch =
      solve_separation_patch(sampled_crown(h, 4e-3), h.A, kLoad, kG, kNu, 40, 40, &info);
  ASSERT_TRUE(patch.normal.converged);
  EXPECT_NEAR(patch.normal.max_pressure, h.pressure, 0.002 * h.pressure);
  EXPECT_NEAR(patch.normal.approach, h.approach, 0.001 * h.approach);
  EXPECT_NEAR(patch.normal.area, M_PI * h.a * h.b, 0.01 * M_PI * h.a * h.b);
  // Every row's leading edge within a tenth of an element of the ellipse's.
  const ContactGrid& g = patch.kernels->grid();
  int rows = 0;
  for (int j = 0; j < g.my; ++j) {
    const double y = g.y(j) - 4e-3;
    if (std::isnan(patch.leading_edge[j]) || std::abs(y) > 0.9 * h.b)
      continue;
    EXPECT_NEAR(patch.leading_edge[j], h.a * std::sqrt(1 - (y / h.b) * (y / h.b)), 0.1 * g.dx)
        << "row " << j;
    ++rows;
  }
  EXPECT_GT(rows, 30);
  // The creep force at small creepage then meets the ellipse's solve to 0.2 %.
  TangentialSettings settings;
  settings.leading_edge = patch.leading_edge;
  const double on_separation =
      solve_tangential(*patch.kernels, patch.normal.pressure, {-1e-3, 0, 0}, {}, settings)
          .forces.Fx;
  const double on_ellipse = solve_tangential(reference.kernels, reference.normal.pressure,
                                             {-1e-3, 0, 0}, {}, reference.settings)
                                .forces.Fx;
  EXPECT_NEAR(on_separation, on_ellipse, 0.002 * std::abs(on_ellipse));
}

TEST(ExactSolver, RollingRadiiGrowingLinearlyAreTheSpinsLongitudinalSlip) {
  const Patch reference(30);
  const HertzContact& h = reference.hertz;
  const double phi = 2.0, radius = 0.46;  // 1/m, m
  LateralSeparation plain = sampled_crown(h), radii = plain;
  for (double y : radii.y)
    radii.rolling_radius.push_back(radius * (1 + phi * y));
  const HertzPatch spin_patch = solve_separation_patch(plain, h.A, kLoad, kG, kNu, 30, 30);
  const HertzPatch radii_patch = solve_separation_patch(radii, h.A, kLoad, kG, kNu, 30, 30);
  ASSERT_EQ(radii_patch.row_longitudinal_slip.size(), 30u);
  EXPECT_TRUE(spin_patch.row_longitudinal_slip.empty());
  for (int j = 0; j < 30; ++j)
    EXPECT_NEAR(radii_patch.row_longitudinal_slip[j], -phi * radii_patch.kernels->grid().y(j),
                1e-12);
  TangentialSettings spin_settings, radii_settings;
  spin_settings.leading_edge = spin_patch.leading_edge;
  radii_settings.leading_edge = radii_patch.leading_edge;
  radii_settings.row_longitudinal_slip = radii_patch.row_longitudinal_slip;
  const Creepages creep{-5e-4, 0, phi};
  const CreepForces with_spin =
      solve_tangential(*spin_patch.kernels, spin_patch.normal.pressure, creep, {}, spin_settings)
          .forces;
  const CreepForces with_radii =
      solve_tangential(*radii_patch.kernels, radii_patch.normal.pressure, creep, {}, radii_settings)
          .forces;
  EXPECT_GT(std::abs(with_spin.Fy), 100);  // the spin acts
  EXPECT_NEAR(with_radii.Fx, with_spin.Fx, 1e-9 * kLoad);
  EXPECT_NEAR(with_radii.Fy, with_spin.Fy, 1e-9 * kLoad);
  // A rigid-slip row per grid row, or the solve refuses.
  radii_settings.row_longitudinal_slip.pop_back();
  EXPECT_THROW(solve_tangential(*radii_patch.kernels, radii_patch.normal.pressure, creep, {},
                                radii_settings),
               std::invalid_argument);
}

TEST(ExactSolver, SeparationPatchRefusesProfilesThatEndInsideTheContact) {
  const Patch reference(20);
  LateralSeparation narrow = sampled_crown(reference.hertz);
  narrow.y.resize(160);  // ends 1 mm past the crown, inside the 5.4 mm half-width
  narrow.s.resize(160);
  EXPECT_THROW(solve_separation_patch(narrow, reference.hertz.A, kLoad, kG, kNu, 20, 20, nullptr),
               std::invalid_argument);
  EXPECT_TRUE(std::isinf(narrow.at(0.5)));
  EXPECT_DOUBLE_EQ(narrow.at(0), 0);
}

}  // namespace
}  // namespace railfe
