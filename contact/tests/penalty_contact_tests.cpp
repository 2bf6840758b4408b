// Penalty contact of one slave node on one flat master face: the normal force is k times the
// penetration, shared by the face's nodes with the bilinear shape functions; Coulomb friction
// by return mapping sticks (elastic, f_t = −k Δe) below μN and slides at μN above it,
// dissipating μN times the slip; the velocity-dependent law gives μ(Δe/Δt).

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "contact/enforcement/penalty_contact_pair.hpp"

namespace railfe {
namespace {

constexpr double kStiffness = 2e8;  // N/m

// Surface nodes 0-3: the unit square z = 0 (normal +z); node 4: the slave.
PenaltyContactPair one_face_pair(FrictionLaw friction = {}, double damping = 0,
                                 std::vector<double> slave_stiffness = {}) {
  PenaltyPairGeometry geometry;
  geometry.n_surface_nodes = 5;
  geometry.master_faces = {{0, 1, 2, 3}};
  geometry.face_stiffness = {kStiffness};
  geometry.slave_stiffness = std::move(slave_stiffness);
  geometry.slave_nodes = {4};
  geometry.slave_area = {1e-4};
  geometry.mass = {1, 1, 1, 1, 0.5};
  PenaltyPairSettings settings;
  settings.name = "test";
  settings.friction = friction;
  settings.damping_fraction = damping;
  settings.search_margin = 0.1;
  return PenaltyContactPair(geometry, settings);
}

std::vector<double> positions(double x, double y, double z) {
  return {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, x, y, z};
}

TEST(PenaltyContact, NormalForceIsStiffnessTimesPenetrationSharedByShapeFunctions) {
  PenaltyContactPair pair = one_face_pair();
  const auto x = positions(0.3, 0.4, -1e-5);
  std::vector<double> du(15, 0.0), force(15, 0.0);
  pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
  const double normal = kStiffness * 1e-5;
  EXPECT_NEAR(force[14], normal, 1e-9 * normal);
  EXPECT_NEAR(force[12], 0, 1e-12 * normal);
  // Bilinear shares at (ξ, η) = (−0.4, −0.2): N0 = (1.4)(1.2)/4 ...
  const double shares[4] = {0.7 * 0.6, 0.3 * 0.6, 0.3 * 0.4, 0.7 * 0.4};
  for (int a = 0; a < 4; ++a)
    EXPECT_NEAR(force[3 * a + 2], -shares[a] * normal, 1e-9 * normal) << "master node " << a;
  EXPECT_EQ(pair.totals().active, 1);
  EXPECT_NEAR(pair.totals().stored_energy, 0.5 * kStiffness * 1e-10, 1e-9 * kStiffness * 1e-10);
  EXPECT_NEAR(pair.totals().area, 1e-4, 1e-18);
}

TEST(PenaltyContact, SeparatedNodeFeelsNothing) {
  PenaltyContactPair pair = one_face_pair();
  const auto x = positions(0.3, 0.4, 1e-5);
  std::vector<double> du(15, 0.0), force(15, 0.0);
  pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
  for (double f : force)
    EXPECT_EQ(f, 0.0);
  EXPECT_EQ(pair.totals().active, 0);
}

TEST(PenaltyContact, CoulombSticksBelowTheBoundAndSlidesAtIt) {
  const double mu = 0.3, penetration = 1e-5;
  const double normal = kStiffness * penetration;
  FrictionLaw coulomb{FrictionLaw::Kind::coulomb, mu, 0, 0};
  PenaltyContactPair pair = one_face_pair(coulomb);
  const auto x = positions(0.5, 0.5, -penetration);
  std::vector<double> du(15, 0.0), force(15, 0.0);
  // A tangential increment a tenth of the elastic range: stick, f_t = −k Δe.
  const double elastic_range = mu * normal / kStiffness;
  du[12] = 0.1 * elastic_range;
  pair.evaluate(x.data(), du.data(), 1e-7, 1.0, force.data());
  EXPECT_NEAR(force[12], -0.1 * mu * normal, 1e-9 * normal);
  EXPECT_FALSE(pair.slaves()[0].slipping);
  EXPECT_EQ(pair.totals().frictional_work, 0.0);
  // The same again: the stick force accumulates (the friction history is kept).
  std::fill(force.begin(), force.end(), 0.0);
  pair.evaluate(x.data(), du.data(), 1e-7, 1.0, force.data());
  EXPECT_NEAR(force[12], -0.2 * mu * normal, 1e-9 * normal);
  // Far past the range: slide at μN against the motion; slip = trial excess over k.
  std::fill(force.begin(), force.end(), 0.0);
  du[12] = 3 * elastic_range;
  pair.evaluate(x.data(), du.data(), 1e-7, 1.0, force.data());
  EXPECT_NEAR(force[12], -mu * normal, 1e-9 * normal);
  EXPECT_TRUE(pair.slaves()[0].slipping);
  const double slip = (0.2 + 3 - 1) * elastic_range;
  EXPECT_NEAR(pair.totals().frictional_work, mu * normal * slip, 1e-9 * mu * normal * slip);
  EXPECT_NEAR(pair.slaves()[0].slip_velocity[0], slip / 1e-7, 1e-9 * slip / 1e-7);
  // Master nodes take the reaction: the forces sum to zero.
  double sum = 0;
  for (int node = 0; node < 5; ++node)
    sum += force[3 * node];
  EXPECT_NEAR(sum, 0, 1e-9 * normal);
}

TEST(PenaltyContact, VelocityDependentCoefficientFollowsTheSlipSpeed) {
  // 1 m/s of slip over 0.1 us moves 0.1 um: 20 N of trial force against a 2 N normal force.
  const double penetration = 1e-8, dt = 1e-7;
  const double normal = kStiffness * penetration;
  FrictionLaw falling{FrictionLaw::Kind::velocity_dependent, 0.45, 0.3, 2.0};
  PenaltyContactPair pair = one_face_pair(falling);
  const auto x = positions(0.5, 0.5, -penetration);
  std::vector<double> du(15, 0.0), force(15, 0.0);
  du[13] = 1e-7;  // 1 m/s of slip in y
  pair.evaluate(x.data(), du.data(), dt, 1.0, force.data());
  const double mu = 0.3 + 0.15 * std::exp(-2.0 * 1.0);
  EXPECT_NEAR(pair.slaves()[0].coefficient, mu, 1e-12);
  EXPECT_NEAR(force[13], -mu * normal, 1e-9 * normal);
  EXPECT_NEAR(pair.totals().friction_bound, mu * normal, 1e-9 * normal);
}

// Springs that agree to 0.1 % are grouped (the group's lightest mass, stiffest spring); lone
// springs, as in these tests, keep their own values, so the step is exact.
void expect_step(const PenaltyContactPair& pair, double exact) {
  EXPECT_NEAR(pair.stable_step(), exact, 1e-12 * exact);
}

TEST(PenaltyContact, CriticalStepIsTwiceRootOfReducedMassOverStiffness) {
  PenaltyContactPair pair = one_face_pair();
  // Slave 0.5 kg, face mean 1 kg: reduced mass 1/3 kg.
  expect_step(pair, 2 * std::sqrt((1.0 / 3) / kStiffness));
}

// A slave node's cap (LS-DYNA's smaller of node and segment): a softer slave sets the force and
// the step; a stiffer one changes nothing.
TEST(PenaltyContact, SlaveCapTakesTheSofterOfNodeAndFace) {
  for (const double slave : {0.25 * kStiffness, 4 * kStiffness}) {
    PenaltyContactPair pair = one_face_pair({}, 0, {slave});
    const double k = std::min(slave, kStiffness);
    EXPECT_EQ(pair.stiffness(0, 0), k);
    const auto x = positions(0.3, 0.4, -1e-5);
    std::vector<double> du(15, 0.0), force(15, 0.0);
    pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
    EXPECT_NEAR(force[14], k * 1e-5, 1e-9 * k * 1e-5) << "slave stiffness " << slave;
    EXPECT_NEAR(pair.totals().stored_energy, 0.5 * k * 1e-10, 1e-9 * k * 1e-10);
    // Reduced mass 1/3 (slave 0.5, face 1).
    expect_step(pair, 2 * std::sqrt((1.0 / 3) / k));
  }
}

TEST(PenaltyContact, CappedStepIsTheSmallestOverEveryNodeOnEveryFace) {
  // Face 0 light and soft, face 1 heavy and stiff; slave 8 light and soft, slave 9 heavy and
  // stiff. The pairing of the lightest slave with the stiffest face (the uncapped rule) never
  // happens at that stiffness: slave 8 caps it.
  PenaltyPairGeometry geometry;
  geometry.n_surface_nodes = 10;
  geometry.master_faces = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  geometry.face_stiffness = {1e8, 1e10};
  geometry.slave_stiffness = {2e8, 5e9};
  geometry.slave_nodes = {8, 9};
  geometry.slave_area = {1e-4, 1e-4};
  geometry.mass = {0.2, 0.2, 0.2, 0.2, 3, 3, 3, 3, 0.1, 2};
  PenaltyPairSettings settings;
  settings.name = "two by two";
  const PenaltyContactPair pair(geometry, settings);
  double exact = 1e300;
  const double face_mass[2] = {0.2, 3}, slave_mass[2] = {0.1, 2};
  for (int s = 0; s < 2; ++s)
    for (int f = 0; f < 2; ++f) {
      const double reduced = slave_mass[s] * face_mass[f] / (slave_mass[s] + face_mass[f]);
      const double k = std::min(geometry.slave_stiffness[s], geometry.face_stiffness[f]);
      exact = std::min(exact, 2 * std::sqrt(reduced / k));
    }
  expect_step(pair, exact);
  // Without the caps, the lightest slave on the stiffest face.
  geometry.slave_stiffness.clear();
  const PenaltyContactPair uncapped(geometry, settings);
  expect_step(uncapped, 2 * std::sqrt((0.1 * 3 / 3.1) / 1e10));
}

TEST(PenaltyContact, DampingNeverPullsTheSurfacesTogether) {
  PenaltyContactPair pair = one_face_pair({}, 1.0);
  const auto x = positions(0.5, 0.5, -1e-6);
  std::vector<double> du(15, 0.0), force(15, 0.0);
  du[14] = 1e-3;  // separating fast: the damper would pull, and is clipped at zero force
  pair.evaluate(x.data(), du.data(), 1e-7, 1e4, force.data());
  EXPECT_EQ(pair.slaves()[0].normal_force, 0.0);
  EXPECT_NEAR(force[14], 0, 1e-12);
}

// A node behind the plane of the face but past its free edge (a block past the end of a plate)
// is beside the surface: no force, also at the corner.
TEST(PenaltyContact, NodePastAFreeEdgeFeelsNothing) {
  PenaltyContactPair pair = one_face_pair();
  for (const auto& where : {std::array<double, 2>{1.001, 0.5}, std::array<double, 2>{0.5, -0.001},
                            std::array<double, 2>{1.001, 1.001}}) {
    const auto x = positions(where[0], where[1], -1e-5);
    std::vector<double> du(15, 0.0), force(15, 0.0);
    pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
    EXPECT_EQ(pair.totals().active, 0) << where[0] << ", " << where[1];
  }
}

// A slave node pressed into the valley between two faces of a dented one-layer slab (nodes on
// the surface's rim, as in a plane-strain model) stays in contact wherever it crosses the
// shared edge: it is never lost between the faces.
TEST(PenaltyContact, NodeCrossingTheEdgeOfAValleyIsNeverLost) {
  const double h = 0.25e-3, t = 1e-3, slope = 6.25e-4, depth = 0.85e-6;
  PenaltyPairGeometry geometry;
  geometry.n_surface_nodes = 7;
  // Nodes 0-2 at y = 0 (x = −h, 0, h), 3-5 at y = t; node 6 the slave.
  geometry.master_faces = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  geometry.face_stiffness = {kStiffness, kStiffness};
  geometry.slave_nodes = {6};
  geometry.slave_area = {1e-7};
  geometry.mass = {1, 1, 1, 1, 1, 1, 0.5};
  PenaltyPairSettings settings;
  settings.name = "valley";
  settings.search_margin = h;
  PenaltyContactPair pair(geometry, settings);
  for (int k = -200; k <= 200; ++k) {
    const double offset = k * 1e-11;
    for (double y : {0.0, 0.5 * t, t}) {
      const std::vector<double> x = {-h, 0,         h * slope, 0,         0,         0, h,
                                     0,  h * slope, -h,        t,         h * slope, 0, t,
                                     0,  h,         t,         h * slope, offset,    y, -depth};
      std::vector<double> du(21, 0.0), force(21, 0.0);
      pair.evaluate(x.data(), du.data(), 1e-7, 0, force.data());
      ASSERT_EQ(pair.totals().active, 1) << "slave at x = " << offset << ", y = " << y;
      EXPECT_NEAR(force[20], kStiffness * depth, 1e-3 * kStiffness * depth)
          << "slave at x = " << offset << ", y = " << y;
    }
  }
}

// Forty slaves at 0 to 117 µm above a strip of ten unit faces close on it at 2 µm a step (slaves
// down, master up, 10 m/s each). Between searches only the window's slaves are evaluated; every
// step must give the same forces, bit for bit, as a pair that searches every step (and so
// evaluates every slave), and the window must hold fewer slaves than the pair.
TEST(PenaltyContact, WindowBetweenSearchesMissesNoContact) {
  const int faces = 10, slaves = 40;
  const auto strip = [&](int interval) {
    PenaltyPairGeometry geometry;
    geometry.n_surface_nodes = 2 * (faces + 1) + slaves;
    for (int f = 0; f < faces; ++f) {
      geometry.master_faces.push_back({2 * f, 2 * f + 2, 2 * f + 3, 2 * f + 1});
      geometry.face_stiffness.push_back(kStiffness);
    }
    for (int s = 0; s < slaves; ++s) {
      geometry.slave_nodes.push_back(2 * (faces + 1) + s);
      geometry.slave_area.push_back(1e-6);
    }
    geometry.mass.assign(geometry.n_surface_nodes, 1.0);
    PenaltyPairSettings settings;
    settings.name = "strip";
    settings.search_margin = 0.1;
    settings.search_interval = interval;
    return PenaltyContactPair(geometry, settings);
  };
  PenaltyContactPair windowed = strip(10), reference = strip(1);
  const double dt = 1e-7, speed = 10;
  std::vector<double> x(3 * (2 * (faces + 1) + slaves), 0.0);
  std::vector<double> du(x.size(), 0.0);
  for (int i = 0; i <= faces; ++i)
    for (int j = 0; j < 2; ++j) {
      x[3 * (2 * i + j)] = i;
      x[3 * (2 * i + j) + 1] = j;
      du[3 * (2 * i + j) + 2] = speed * dt;
    }
  for (int s = 0; s < slaves; ++s) {
    const int node = 2 * (faces + 1) + s;
    x[3 * node] = 2.3 + 0.01 * s;
    x[3 * node + 1] = 0.5;
    x[3 * node + 2] = 3e-6 * s;
    du[3 * node + 2] = -speed * dt;
  }
  int most_active = 0;
  for (int step = 0; step < 70; ++step) {
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] += du[i];
    std::vector<double> force(x.size(), 0.0), expected(x.size(), 0.0);
    windowed.evaluate(x.data(), du.data(), dt, speed, force.data());
    reference.evaluate(x.data(), du.data(), dt, speed, expected.data());
    ASSERT_EQ(force, expected) << "step " << step;
    ASSERT_EQ(windowed.totals().active, reference.totals().active) << "step " << step;
    most_active = std::max(most_active, windowed.totals().active);
    if (step == 0) {
      // Face 2 (nodes 4-7) lies under the slaves; face 7 (nodes 14-17) is far from them.
      const std::vector<int>& window = windowed.window_nodes();
      const auto holds = [&](int node) {
        return std::binary_search(window.begin(), window.end(), node);
      };
      int window_slaves = 0;
      for (int s = 0; s < slaves; ++s)
        window_slaves += holds(2 * (faces + 1) + s) ? 1 : 0;
      EXPECT_GT(window_slaves, 0);
      EXPECT_LT(window_slaves, slaves);
      for (int node : {4, 5, 6, 7})
        EXPECT_TRUE(holds(node)) << "master node " << node;
      EXPECT_FALSE(holds(14));
    }
  }
  EXPECT_EQ(most_active, slaves);  // every slave came into contact on the way
}

}  // namespace
}  // namespace railfe
