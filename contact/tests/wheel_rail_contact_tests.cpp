// The wheel–rail contact element against closed forms: a 1:40 cone on a 300 mm circular crown,
// where the contact angle, curvatures and lever arms are known, so Hertz's normal force and
// Kalker's linear creep forces at the element's creepages can be written down independently.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact/enforcement/wheel_rail_contact.hpp"
#include "contact/laws/creep_table.hpp"

namespace railfe {
namespace {

constexpr double kRail = 0.3;        // crown radius (m)
constexpr double kGamma = 1.0 / 40;  // cone slope

std::shared_ptr<const WheelRailGeometry> cone_on_crown() {
  TrackLayout track;
  track.profile_inclined = true;
  const double offset = std::sqrt(kRail * kRail - std::pow(kRail - track.gauge_depth, 2));
  track.gauge = 2 * (0.75 - offset);  // crown tops under the running points
  const double reach = std::acos(1 - 0.020 / kRail);
  auto rail = arc_curve({0, kRail}, kRail, -M_PI / 2 - reach, -M_PI / 2 + reach);
  auto wheel = line_curve({-0.06, -0.06 * kGamma}, {0.07, 0.07 * kGamma});
  return std::make_shared<WheelRailGeometry>(std::move(rail), std::move(wheel), track,
                                             WheelsetLayout{});
}

ContactKinematics rolling_state() {
  ContactKinematics state;
  state.wheelset_u = {0, 0.002, 1e-4, 0, 0, 2e-3};  // shifted, pressed down 0.1 mm, yawed
  state.wheelset_v = {0.01, 0.03, 0, 0, 0, 0};
  state.speed = 30;
  state.spin = -state.speed / WheelsetLayout{}.nominal_radius;
  return state;
}

TEST(WheelRailContact, ForcesAtAPoseAreHertzAndKalkersLinearTheory) {
  WheelRailContactSettings settings;
  settings.wheel = settings.rail = ElasticBody{210e9, 0.3};
  const auto geometry = cone_on_crown();
  WheelRailContact contact(geometry, TrackSide::right, false, settings);
  const ContactKinematics state = rolling_state();
  const ContactState c = contact.evaluate(state);
  ASSERT_TRUE(c.active);
  const double delta = std::atan(kGamma);
  EXPECT_NEAR(c.point.contact_angle, delta, 1e-12);
  // Normal force: Hertz with the cone's rolling curvature cos(δ)/R and the crown's 1/R.
  const double R = c.point.rolling_radius;
  const double E = contact_modulus(settings.wheel, settings.rail);
  const HertzContact hertz =
      hertz_from_approach(std::cos(delta) / (2 * R), 1 / (2 * kRail), E, -c.point.gap);
  EXPECT_NEAR(c.hertz.load, hertz.load, 1e-9 * hertz.load);
  // Creepages of a wheel spinning at Ω about its yawed axle a = (−sin ψ, cos ψ, 0), its contact
  // point r below the centre; slip = V ex + v + Ω a × r; t = n × ex; spin = Ω a·n / V.
  const double V = state.speed, W = state.spin, psi = state.wheelset_u[5];
  const double n_y = -std::sin(delta), n_z = -std::cos(delta);  // tilted towards the flange
  const double r_y = c.point.rail_point.y + c.point.gap * n_y - state.wheelset_u[1];
  const double r_z = c.point.rail_point.z + c.point.gap * n_z - (state.wheelset_u[2] - 0.46);
  const double slip_x = V + state.wheelset_v[0] + W * std::cos(psi) * r_z;
  const double slip_y = state.wheelset_v[1] + W * std::sin(psi) * r_z;
  const double slip_z = -W * std::sin(psi) * r_y;
  const double xi = slip_x / V, eta = (n_z * slip_y - n_y * slip_z) / V;
  const double phi = W * std::cos(psi) * n_y / V;
  EXPECT_NEAR(c.creepage.longitudinal, xi, 1e-12);
  EXPECT_NEAR(c.creepage.lateral, eta, 1e-12);
  EXPECT_NEAR(c.creepage.spin, phi, 1e-12);
  // Kalker's linear forces on the wheel with G = E / 2(1 + ν).
  const double G = 210e9 / (2 * 1.3), a = hertz.a, b = hertz.b, ab = a * b, root = std::sqrt(ab);
  const KalkerCoefficients k = KalkerTable::shipped().at(a, b, 0.3);
  const double Fx = -G * ab * k.C11 * xi, Fy = -G * ab * (k.C22 * eta + root * k.C23 * phi);
  const double Mz = G * ab * root * (k.C23 * eta - root * k.C33 * phi);
  const double N = hertz.load;
  const double force[3] = {Fx, N * n_y + Fy * n_z, N * n_z - Fy * n_y};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(c.force[i], force[i], 1e-9 * N) << i;
  // Moment about the centre: r × F plus the spin moment about the normal.
  const double r[3] = {0, r_y, r_z};
  const double moment[3] = {r[1] * force[2] - r[2] * force[1] + 0,
                            r[2] * force[0] - r[0] * force[2] + Mz * n_y,
                            r[0] * force[1] - r[1] * force[0] + Mz * n_z};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(c.moment[i], moment[i], 1e-9 * N * 0.5) << i;
  // The element's internal forces: the wheelset gets −F, the internal node +F.
  double wheelset[6], node[3];
  WheelRailContact::internal_forces(c, state, wheelset, node);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(wheelset[i], -c.force[i]);
    EXPECT_EQ(node[i], c.force[i]);
  }
  EXPECT_EQ(wheelset[3], -c.moment[0]);
  EXPECT_EQ(wheelset[5], -c.moment[2]);
}

TEST(WheelRailContact, LiftedWheelCarriesNothing) {
  WheelRailContact contact(cone_on_crown(), TrackSide::left, false, {});
  ContactKinematics state = rolling_state();
  state.wheelset_u[2] = -1e-4;  // lifted by 0.1 mm
  const ContactState c = contact.evaluate(state);
  EXPECT_FALSE(c.active);
  EXPECT_GT(c.point.gap, 0);
  for (double f : c.force)
    EXPECT_EQ(f, 0);
}

TEST(WheelRailContact, TangentMatchesCentralDifferences) {
  for (CreepTheory theory : {CreepTheory::linear, CreepTheory::fastsim, CreepTheory::polach}) {
    WheelRailContactSettings settings;
    settings.theory = theory;
    settings.friction = 0.3;
    WheelRailContact contact(cone_on_crown(), TrackSide::right, false, settings);
    ContactKinematics state = rolling_state();
    state.wheelset_u[3] = 1e-3;  // some roll, so every coupling is there
    const ContactState at = contact.evaluate(state);
    ASSERT_TRUE(at.active);
    double stiffness[81], damping[81];
    contact.tangent(state, at, stiffness, damping);
    // Central differences with a larger step of the full evaluation over every position and
    // every velocity: fd[pass][j][i] = ∂f_i/∂(u or v)_j.
    double fd[2][9][9], scale = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < 9; ++j) {
        const double h = pass == 0 ? 1e-7 : 1e-4;
        double plus[9], minus[9];
        ContactKinematics up = state, down = state;
        auto entry = [pass, j](ContactKinematics& k) -> double& {
          if (pass == 0)
            return j < 6 ? k.wheelset_u[j] : k.node_u[j - 6];
          return j < 6 ? k.wheelset_v[j] : k.node_v[j - 6];
        };
        entry(up) += h;
        entry(down) -= h;
        WheelRailContact::internal_forces(contact.evaluate(up), up, plus, plus + 6);
        WheelRailContact::internal_forces(contact.evaluate(down), down, minus, minus + 6);
        for (int i = 0; i < 9; ++i) {
          fd[pass][j][i] = (plus[i] - minus[i]) / (2 * h);
          scale = std::max(scale, std::abs(fd[pass][j][i]));
        }
      }
    const std::string name = creep_theory_name(theory);
    auto column_scale = [](const double* matrix, int j) {
      double s = 0;
      for (int i = 0; i < 9; ++i)
        s = std::max(s, std::abs(matrix[i * 9 + j]));
      return s;
    };
    // The vertical position's column, and every velocity's (the damping comes from the
    // creepages' rates J, which must be the rates of the creepages the forces take).
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(stiffness[i * 9 + 2], fd[0][2][i], 2e-4 * column_scale(stiffness, 2))
          << name << " position column 2 row " << i;
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
        EXPECT_NEAR(damping[i * 9 + j], fd[1][j][i],
                    2e-4 * std::max(column_scale(damping, j), 1e-9 * scale))
            << name << " velocity column " << j << " row " << i;
    // The tangent takes no differences for x, the spin angle and the node's x (the forces do not
    // depend on them) and takes the node's y and z columns as the wheelset's negated (the forces
    // see them only through the relative pose): the full evaluation must agree.
    for (int j : {0, 4, 6})
      for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(stiffness[i * 9 + j], 0.0);
        EXPECT_NEAR(fd[0][j][i], 0.0, 1e-9 * scale) << name << " position column " << j;
      }
    for (int j : {1, 2})
      for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(stiffness[i * 9 + j + 6], -stiffness[i * 9 + j]);
        EXPECT_NEAR(fd[0][j + 6][i], -fd[0][j][i], 1e-9 * scale)
            << name << " node column " << j + 6 << " row " << i;
      }
  }
}

TEST(WheelRailContact, KalkerDampingIsTheLinearTheorysConsistentTangent) {
  // For Kalker's linear theory the creep forces are −D J v, so Jᵀ D J (the seed's constant
  // damping) must equal the forward-difference damping of the same theory.
  WheelRailContactSettings consistent, seed;
  seed.kalker_damping = true;
  WheelRailContact a(cone_on_crown(), TrackSide::right, false, consistent);
  WheelRailContact b(cone_on_crown(), TrackSide::right, false, seed);
  ContactKinematics state = rolling_state();
  state.wheelset_u[3] = 1e-3;
  const ContactState at = a.evaluate(state);
  ASSERT_TRUE(at.active);
  b.evaluate(state);
  double ka[81], ca[81], kb[81], cb[81];
  a.tangent(state, at, ka, ca);
  b.tangent(state, at, kb, cb);
  double scale = 0;
  for (double v : ca)
    scale = std::max(scale, std::abs(v));
  for (int i = 0; i < 81; ++i) {
    EXPECT_NEAR(cb[i], ca[i], 1e-6 * scale) << "entry " << i;
    EXPECT_EQ(kb[i], ka[i]);
  }
}

TEST(WheelRailContact, NearlyConformalCurvaturesAreRaisedToTheRatioLimit) {
  // A concave tread of radius 0.31 m on the 0.3 m crown: B = (1/0.3 − 1/0.31)/2 = 0.054 /m
  // against A = 1/(2 r) ≈ 1.09 /m, a ratio of 20. The limit 10 raises B to A/10; without a limit
  // Hertz takes the curvatures as they are.
  TrackLayout track;
  track.profile_inclined = true;
  const double offset = std::sqrt(kRail * kRail - std::pow(kRail - track.gauge_depth, 2));
  track.gauge = 2 * (0.75 - offset);
  const double reach = std::acos(1 - 0.020 / kRail), radius = 0.31;
  auto rail = arc_curve({0, kRail}, kRail, -M_PI / 2 - reach, -M_PI / 2 + reach);
  auto wheel = arc_curve({0, radius}, radius, -M_PI / 2 - 0.15, -M_PI / 2 + 0.15);
  auto geometry = std::make_shared<WheelRailGeometry>(std::move(rail), std::move(wheel), track,
                                                      WheelsetLayout{});
  ContactKinematics state;
  state.wheelset_u = {0, 0, 5e-5, 0, 0, 0};
  for (double limit : {10.0, 0.0}) {
    WheelRailContactSettings settings;
    settings.curvature_ratio_limit = limit;
    WheelRailContact contact(geometry, TrackSide::right, false, settings);
    const ContactState c = contact.evaluate(state);
    ASSERT_TRUE(c.active);
    const double A = c.point.relative_curvature_rolling();
    const double B = c.point.relative_curvature_lateral();
    EXPECT_NEAR(B, 0.5 * (1 / kRail - 1 / radius), 1e-9);
    const double E = contact_modulus(settings.wheel, settings.rail);
    const HertzContact expected =
        hertz_from_approach(A, limit > 0 ? A / limit : B, E, -c.point.gap);
    EXPECT_EQ(c.conformal, limit > 0);
    EXPECT_NEAR(c.hertz.load, expected.load, 1e-9 * expected.load);
  }
}

TEST(WheelRailContact, TableRefusesAnotherPoissonsRatio) {
  WheelRailContactSettings settings;
  settings.theory = CreepTheory::table;
  settings.wheel = settings.rail = ElasticBody{210e9, 0.28};
  EXPECT_THROW(WheelRailContact(cone_on_crown(), TrackSide::right, false, settings),
               std::invalid_argument);
}

}  // namespace
}  // namespace railfe
