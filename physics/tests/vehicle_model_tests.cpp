// The vehicle part as dense matrices (vehicle mesh generator + DenseStructuralModel): its mass,
// and closed forms of single bodies on their springs with the neighbours held, which check the
// generator's spring positions and the rigid links' levers.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <initializer_list>
#include <memory>

#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "physics/common/dense_structural_model.hpp"
#include "physics/parts/vehicle_mesh.hpp"

namespace railfe {
namespace {

const char* const kSections = R"x(<ParameterList name="railfe">
  <ParameterList name="Sections">
    <ParameterList name="car body"><Parameter name="Blocks" type="Array(string)" value="{car_body}"/>
      <Parameter name="Element" type="string" value="point mass"/><Parameter name="Mass" type="double" value="30000"/>
      <Parameter name="Inertia" type="Array(double)" value="{6e4, 1.5e6, 1.4e6}"/></ParameterList>
    <ParameterList name="bogie"><Parameter name="Blocks" type="Array(string)" value="{bogies}"/>
      <Parameter name="Element" type="string" value="point mass"/><Parameter name="Mass" type="double" value="3000"/>
      <Parameter name="Inertia" type="Array(double)" value="{2000, 3000, 3100}"/></ParameterList>
    <ParameterList name="wheelset"><Parameter name="Blocks" type="Array(string)" value="{wheelsets}"/>
      <Parameter name="Element" type="string" value="point mass"/><Parameter name="Mass" type="double" value="2000"/>
      <Parameter name="Inertia" type="Array(double)" value="{700, 80, 900}"/></ParameterList>
    <ParameterList name="primary"><Parameter name="Blocks" type="Array(string)" value="{primary}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{2e7, 7e6, 4e6, 0, 0, 0}"/>
      <Parameter name="Damping" type="Array(double)" value="{0, 0, 2e4, 0, 0, 0}"/></ParameterList>
    <ParameterList name="secondary"><Parameter name="Blocks" type="Array(string)" value="{secondary}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{2e5, 3e5, 1e6, 0, 0, 0}"/>
      <Parameter name="Damping" type="Array(double)" value="{0, 5e4, 1e4, 0, 0, 0}"/></ParameterList>
  </ParameterList></ParameterList>)x";

constexpr double a = 8.75, b = 1.25, r0 = 0.43, hc = 1.8, hb = 0.6, dp = 0.8, ds = 0.95, hs = 0.9;

struct Vehicle {
  Mesh mesh;
  std::unique_ptr<DenseStructuralModel> model;
};

Vehicle vehicle() {
  VehicleLayout layout;
  layout.half_bogie_spacing = a;
  layout.half_wheelbase = b;
  layout.wheel_radius = r0;
  layout.car_body_height = hc;
  layout.bogie_height = hb;
  layout.primary_half_span = dp;
  layout.secondary_half_span = ds;
  layout.secondary_height = hs;
  layout.floor_height = 1.2;
  Vehicle v{build_vehicle_mesh(layout, "test"), nullptr};
  Deck deck = parse_deck(kSections, "deck.xml", ".");
  auto& list = deck.parameters->sublist("Sections");
  validate_and_complete(list, *sections_parameters().list(), deck.source, "Sections");
  const SectionTable sections(list, nullptr, v.mesh, deck.source);
  v.model = std::make_unique<DenseStructuralModel>(v.mesh, sections, deck.source);
  return v;
}

// ω² of a translation (mass m) and a rotation (inertia J) coupled by translational springs k_i at
// levers e_i from the centre of mass, the rotation also held by \p k_rotation: the roots of
// det([Σk − mω², Σk e; Σk e, Σk e² + k_rotation − Jω²]) = 0.
std::array<double, 2> coupled_pair(double m, double J,
                                   std::initializer_list<std::array<double, 2>> springs,
                                   double k_rotation) {
  double kt = 0, kc = 0, kr = k_rotation;
  for (const auto& [k, e] : springs) {
    kt += k;
    kc += k * e;
    kr += k * e * e;
  }
  const double trace = kt / m + kr / J, det = (kt * kr - kc * kc) / (m * J);
  const double disc = std::sqrt(trace * trace / 4 - det);
  return {trace / 2 - disc, trace / 2 + disc};
}

// The eigenvalues ω² of body \p body (a node) on its springs, every other body held.
Eigen::VectorXd body_eigenvalues(const Vehicle& v, GlobalIndex body) {
  const Eigen::Index o = v.model->unknown_of(body);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      v.model->stiffness().block(o, o, 6, 6), v.model->mass().block(o, o, 6, 6));
  return solver.eigenvalues();
}

TEST(VehicleModel, SevenBodiesCarryTheWholeWeight) {
  const Vehicle v = vehicle();
  EXPECT_EQ(v.model->n_unknowns(), 42);
  const Eigen::VectorXd weight = v.model->gravity_load(Eigen::Vector3d(0, 0, 9.81));
  double total = 0;
  for (GlobalIndex node = 0; node < 7; ++node)
    total += weight(v.model->unknown_of(node) + 2);
  EXPECT_NEAR(total, 9.81 * (30000 + 2 * 3000 + 4 * 2000), 1e-8);
  EXPECT_LT(v.model->unknown_of(8), 0);  // an axle box, carried
}

TEST(VehicleModel, CarBodyOnItsAirSpringsHasTheClosedFormModes) {
  const Vehicle v = vehicle();
  const Eigen::VectorXd w2 = body_eigenvalues(v, vehicle_car_body_node);
  auto has = [&w2](double expected) {
    return ((w2.array() - expected).abs() < 1e-9 * expected).any();
  };
  EXPECT_TRUE(has(4 * 1e6 / 30000)) << "bounce";
  // Pitch with surge: the air springs' longitudinal stiffness acts h_c − h_s below the centre.
  for (double w : coupled_pair(30000, 1.5e6, {{4 * 2e5, hc - hs}}, 4 * 1e6 * a * a))
    EXPECT_TRUE(has(w)) << "pitch and surge";
  EXPECT_TRUE(has((4 * 3e5 * a * a + 4 * 2e5 * ds * ds) / 1.4e6)) << "yaw";
  // Sway: lateral motion and roll coupled by the same lever.
  const auto sway = coupled_pair(30000, 6e4, {{4 * 3e5, hc - hs}}, 4 * 1e6 * ds * ds);
  EXPECT_TRUE(has(sway[0])) << "lower sway";
  EXPECT_TRUE(has(sway[1])) << "upper sway";
}

TEST(VehicleModel, BogieFrameOnPrimaryAndSecondarySprings) {
  const Vehicle v = vehicle();
  const Eigen::VectorXd w2 = body_eigenvalues(v, 1);
  auto has = [&w2](double expected) {
    return ((w2.array() - expected).abs() < 1e-9 * expected).any();
  };
  EXPECT_TRUE(has((4 * 4e6 + 2 * 1e6) / 3000)) << "bounce";
  // Pitch with surge: the axle boxes act h_b − r₀ below the centre, the air springs h_s − h_b
  // above it.
  for (double w :
       coupled_pair(3000, 3000, {{4 * 2e7, hb - r0}, {2 * 2e5, hb - hs}}, 4 * 4e6 * b * b))
    EXPECT_TRUE(has(w)) << "pitch and surge";
  EXPECT_TRUE(has((4 * 7e6 * b * b + 4 * 2e7 * dp * dp + 2 * 2e5 * ds * ds) / 3100)) << "yaw";
}

TEST(VehicleModel, WheelsetSpinIsFreeAndItsYawHeldByTheAxleBoxes) {
  const Vehicle v = vehicle();
  const Eigen::Index w = v.model->unknown_of(vehicle_first_wheelset_node);
  EXPECT_EQ(v.model->stiffness()(w + 4, w + 4), 0.0);
  EXPECT_NEAR(v.model->stiffness()(w + 5, w + 5), 2 * 2e7 * dp * dp, 1e-6);
  EXPECT_NEAR(v.model->damping()(w + 2, w + 2), 2 * 2e4, 1e-9);
}

}  // namespace
}  // namespace railfe
