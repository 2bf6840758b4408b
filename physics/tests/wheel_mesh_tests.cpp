// The wheel mesh generator: volume against Pappus' theorem on the section outline, sets, the
// running circle at the nominal radius, the half axle, refused dimensions, Mesh/Type wheel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "contact/geometry/profile_file.hpp"
#include "framework/base/constants.hpp"
#include "framework/base/error.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/testing/input_error.hpp"
#include "physics/parts/wheel_mesh.hpp"

namespace railfe {
namespace {

double volume(const Mesh& mesh, const std::string& block_name) {
  return block_volume(mesh, mesh.blocks[mesh.block_index(block_name, "", "")]);
}

// Pappus: 2π ∫ r dA over the polygon (the tread through every profile point).
double pappus_volume(const std::vector<std::array<double, 2>>& outline) {
  double first_moment = 0;  // ∫ r dA
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const auto& p = outline[i];
    const auto& q = outline[(i + 1) % outline.size()];
    first_moment += (p[0] * q[1] - q[0] * p[1]) * (p[0] + q[0]) / 6;
  }
  return 2 * kPi * first_moment;
}

WheelDimensions coarse() {
  WheelDimensions d;
  d.profile_file = shipped_profile("MBench_S1002_v3.prw");
  d.element_size = 0.02;
  return d;
}

TEST(WheelMesh, VolumeSetsAndRunningCircle) {
  const WheelDimensions d = coarse();
  const Mesh mesh = build_wheel_mesh(d, "test");
  EXPECT_NO_THROW(check_mesh(mesh));
  const int n = wheel_elements_around(d);
  EXPECT_EQ(n, 148);  // π · 920 mm / 20 mm = 144.5, up to a multiple of 4
  EXPECT_EQ(mesh.n_nodes() % n, 0);
  // The slices' chords lose 1 − n sin(2π/n)/2π = 3.0e-4 of the volume, a known factor; what is
  // left is the section mesh's chords across the curved tread: 1.7e-3 at 20 mm, 6.5e-4 at 10 mm,
  // 2.1e-4 at 5 mm.
  const double exact = pappus_volume(wheel_section(d, "test").wheel);
  const double chord_factor = n * std::sin(2 * kPi / n) / (2 * kPi);
  EXPECT_NEAR(volume(mesh, "wheel") / (chord_factor * exact), 1, 2.5e-3);
  const double mass = 7850 * volume(mesh, "wheel");
  EXPECT_GT(mass, 250);  // 341 kg; solid 920 mm wheels weigh roughly 300-400 kg
  EXPECT_LT(mass, 450);

  for (const char* name : {"tread", "bore", "running_circle"}) {
    EXPECT_GT(mesh.node_set(name, "", "").nodes.size(), 0u) << name;
  }
  EXPECT_EQ(mesh.node_set("running_circle", "", "").nodes.size(), static_cast<std::size_t>(n));
  for (GlobalIndex node : mesh.node_set("running_circle", "", "").nodes) {
    const auto x = mesh.node(node);
    EXPECT_NEAR(std::hypot(x[0], x[2]), 0.46, 1e-12);
    EXPECT_NEAR(x[1], 0, 1e-15);
  }
  // The tread's nodes reach from the outer chamfer to the flange back (y = 69.6 mm), and the
  // flange tip stands 28 mm above the running circle.
  double a_min = 1, a_max = -1, r_max = 0;
  for (GlobalIndex node : mesh.node_set("tread", "", "").nodes) {
    const auto x = mesh.node(node);
    a_min = std::min(a_min, x[1]);
    a_max = std::max(a_max, x[1]);
    r_max = std::max(r_max, std::hypot(x[0], x[2]));
  }
  EXPECT_NEAR(a_min, -0.060, 1e-9);
  EXPECT_NEAR(a_max, 0.069612628, 1e-9);
  EXPECT_LE(r_max, 0.46 + 0.028 + 1e-9);
  EXPECT_GT(r_max, 0.46 + 0.025);  // a 20 mm mesh cuts across the tip's rounding
  EXPECT_GT(mesh.side_set("tread", "", "").sides.size(), 0u);
  for (GlobalIndex node : mesh.node_set("bore", "", "").nodes) {
    const auto x = mesh.node(node);
    EXPECT_NEAR(std::hypot(x[0], x[2]), 0.0975, 1e-12);
  }
}

TEST(WheelMesh, HalfAxle) {
  WheelDimensions d = coarse();
  d.half_axle = true;
  d.elements_around = 40;
  const Mesh mesh = build_wheel_mesh(d, "test");
  EXPECT_NO_THROW(check_mesh(mesh));
  EXPECT_FALSE(mesh.has_node_set("bore"));
  const auto& end = mesh.node_set("axle_end", "", "").nodes;
  EXPECT_GT(end.size(), 0u);
  for (GlobalIndex node : end)
    EXPECT_NEAR(mesh.node(node)[1], 0.75, 1e-12);
  const double chord_factor = 40 * std::sin(2 * kPi / 40) / (2 * kPi);
  const WheelSection section = wheel_section(d, "test");
  EXPECT_NEAR(volume(mesh, "axle") / (chord_factor * pappus_volume(section.axle)), 1, 1e-12);
  EXPECT_NEAR(volume(mesh, "wheel") / (chord_factor * pappus_volume(section.wheel)), 1, 2.5e-3);
}

TEST(WheelMesh, RefusesDimensionsThatMakeNoWheel) {
  WheelDimensions d = coarse();
  d.rim_width = 0.12;
  auto message = input_error_of([&] { wheel_section(d, "deck.xml"); });
  EXPECT_NE(message.find("deck.xml: 'Mesh/Wheel/Rim width'"), std::string::npos) << message;
  d = coarse();
  d.web_thickness = 0.2;
  message = input_error_of([&] { wheel_section(d, "deck.xml"); });
  EXPECT_NE(message.find("Web thickness"), std::string::npos) << message;
  d = coarse();
  d.half_axle = true;
  d.axle_diameter = 0.2;
  message = input_error_of([&] { wheel_section(d, "deck.xml"); });
  EXPECT_NE(message.find("Axle diameter"), std::string::npos) << message;
  d = coarse();
  d.profile_file = "no_such_profile.prw";
  message = input_error_of([&] { wheel_section(d, "deck.xml"); });
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(WheelMesh, ApproachArc) {
  // 2 mm over 300-310°, 6 mm over the approach 270-315°, 30 mm elsewhere: every slice of the
  // approach about 6 mm at most, the refined arc uniform, neighbours graded, the circle closed.
  WheelDimensions d = coarse();
  d.element_size = 0.03;
  d.refined_arc = {300, 310};
  d.arc_element_size = 0.002;
  d.approach_arc = {270, 315};
  d.approach_element_size = 0.006;
  const std::vector<double> angles = wheel_slice_angles(d);
  const double radius = d.nominal_diameter / 2, degree = kPi / 180;
  EXPECT_NEAR(angles.front(), 300 * degree, 1e-12);
  int in_arc = 0, in_approach = 0;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double next = k + 1 < angles.size() ? angles[k + 1] : angles[0] + 2 * kPi;
    ASSERT_GT(next, angles[k]) << k;
    const double length = (next - angles[k]) * radius;
    const double middle = std::fmod(0.5 * (angles[k] + next), 2 * kPi);
    if (middle > 300 * degree && middle < 310 * degree) {
      EXPECT_NEAR(length, 10 * degree * radius / 41, 1e-12) << k;  // 80.3 mm in 41 slices
      ++in_arc;
    } else if (middle > 270 * degree && middle < 315 * degree) {
      // The graded slices are stretched to fill the approach exactly: by under half a slice's
      // share over the 30 or so, about 6 % at most here.
      EXPECT_LE(length, 0.006 * 1.07) << k;
      ++in_approach;
    } else {
      EXPECT_LE(length, 0.03 * 1.0001) << k;
    }
    const double previous =
        (angles[k] - (k > 0 ? angles[k - 1] : angles.back() - 2 * kPi)) * radius;
    EXPECT_LT(std::max(length / previous, previous / length), 1.5 * d.growth) << k;
  }
  EXPECT_EQ(in_arc, 41);
  // 36 degrees of approach (289 mm) at up to 6 mm, a few of them graded from 2 mm.
  EXPECT_GE(in_approach, 49);
  EXPECT_LE(in_approach, 60);
  EXPECT_NO_THROW(check_mesh(build_wheel_mesh(d, "test")));
}

// Shortest element edge of the mesh (m).
double shortest_edge(const Mesh& mesh) {
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double shortest = 1e300;
  for (const auto& block : mesh.blocks)
    for (GlobalIndex e = 0; e < block.n_elements(); ++e)
      for (const auto& edge : edges) {
        const auto a = mesh.node(block.element_nodes(e)[edge[0]]);
        const auto b = mesh.node(block.element_nodes(e)[edge[1]]);
        shortest = std::min(shortest, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
      }
  return shortest;
}

TEST(WheelMesh, TransitionRadii) {
  // 2 mm slices over 20° at the running circle, coarsened threefold below r = 300 mm (in the
  // web) and again below 120 mm (in the hub): the same body, fewer and no longer tiny elements.
  WheelDimensions d = coarse();
  d.element_size = 0.03;
  d.half_axle = true;
  d.refined_arc = {300, 320};
  d.arc_element_size = 0.002;
  const Mesh plain = build_wheel_mesh(d, "test");
  d.transition_radii = {0.30, 0.12};
  const Mesh graded = build_wheel_mesh(d, "test");
  EXPECT_NO_THROW(check_mesh(graded));
  EXPECT_LT(graded.n_elements(), plain.n_elements());
  // Coarser slices inscribe fewer chords: at most 9 x 4.3e-3 rad, 1 − sin x / x = 2.5e-4 of
  // the 20° sector's volume.
  for (const char* block : {"wheel", "axle"})
    EXPECT_NEAR(volume(graded, block) / volume(plain, block), 1, 1e-4) << block;
  // The arc's 2 mm slices are 0.13 mm long at the axle's bore (r = 30 mm). Coarsened, the
  // shortest edge there is a graded slice that no three could merge into one within the
  // wheel's 29 mm slices (9.4 mm at the tread, 0.61 mm at the bore): over four times longer.
  EXPECT_LT(shortest_edge(plain), 0.14e-3);
  EXPECT_GT(shortest_edge(graded), 0.6e-3);
  for (const char* name : {"tread", "running_circle", "axle_end"})
    EXPECT_EQ(graded.node_set(name, "", "").nodes.size() > 0, true) << name;
  EXPECT_EQ(graded.node_set("tread", "", "").nodes.size(),
            plain.node_set("tread", "", "").nodes.size());
  const auto& end = graded.side_set("axle_end", "", "");
  ASSERT_FALSE(end.sides.empty());
  for (const Side& side : end.sides) {
    const auto& block = graded.blocks[graded.block_of(side.element)];
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(graded.node(block.element_nodes(side.element)[kHex8FaceNodes[side.face][j]])[1],
                  d.axle_length, 1e-12);
  }
  // Refused: strips that overlap (0.2 m and 0.195 m, each 8 mm deep), a cut below the bore.
  d.transition_radii = {0.2, 0.195};
  auto message = input_error_of([&] { build_wheel_mesh(d, "deck.xml"); });
  EXPECT_NE(message.find("deck.xml: 'Mesh/Wheel/Transition radii'"), std::string::npos) << message;
  EXPECT_NE(message.find("one inside the other"), std::string::npos) << message;
  d.transition_radii = {0.05};
  message = input_error_of([&] { build_wheel_mesh(d, "deck.xml"); });
  EXPECT_NE(message.find("crosses the section's outline 0 times"), std::string::npos) << message;
}

TEST(WheelMesh, RefinedArcAndTread) {
  // 30° refined to 4 mm at the running circle, 30 mm elsewhere; the section 6 mm at the tread.
  WheelDimensions d = coarse();
  d.element_size = 0.03;
  d.tread_element_size = 0.006;
  d.refined_arc = {255, 285};
  d.arc_element_size = 0.004;
  const std::vector<double> angles = wheel_slice_angles(d);
  const double radius = d.nominal_diameter / 2;
  EXPECT_NEAR(angles.front(), 255 * kPi / 180, 1e-12);
  int in_arc = 0;
  double chord_volume_factor = 0;  // Σ sin(Δθ) / 2π: the slices' chords (see revolve())
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double next = k + 1 < angles.size() ? angles[k + 1] : angles[0] + 2 * kPi;
    const double length = (next - angles[k]) * radius;
    EXPECT_LE(length, 0.03 * 1.0001) << k;
    if (angles[k] < 285 * kPi / 180 - 1e-9) {
      EXPECT_NEAR(length, 30 * kPi / 180 * radius / 61, 1e-12) << k;
      ++in_arc;
    }
    if (k > 0) {  // neighbours grow by at most the growth ratio (after rescaling)
      const double previous = (angles[k] - angles[k - 1]) * radius;
      EXPECT_LT(std::max(length / previous, previous / length), 1.5 * d.growth) << k;
    }
    chord_volume_factor += std::sin(next - angles[k]) / (2 * kPi);
  }
  EXPECT_EQ(in_arc, 61);  // 30° of a 460 mm radius = 240.9 mm: 61 slices of 3.95 mm
  const Mesh mesh = build_wheel_mesh(d, "test");
  EXPECT_NO_THROW(check_mesh(mesh));
  const double exact = pappus_volume(wheel_section(d, "test").wheel);
  EXPECT_NEAR(volume(mesh, "wheel") / (chord_volume_factor * exact), 1, 2.5e-3);
  // The tread's nodes lie at most the tread size apart along the profile (in a slice).
  std::vector<std::array<double, 2>> tread;
  for (GlobalIndex node : mesh.node_set("tread", "", "").nodes) {
    if (node < mesh.n_nodes() / static_cast<GlobalIndex>(angles.size()))  // slice 0
      tread.push_back({mesh.node(node)[1], std::hypot(mesh.node(node)[0], mesh.node(node)[2])});
  }
  std::sort(tread.begin(), tread.end());
  ASSERT_GT(tread.size(), 20u);
  double widest = 0;
  for (std::size_t i = 0; i + 1 < tread.size(); ++i)
    widest =
        std::max(widest, std::hypot(tread[i + 1][0] - tread[i][0], tread[i + 1][1] - tread[i][1]));
  EXPECT_LT(widest, 1.0 * 0.006);
  EXPECT_GT(widest, 0.5 * 0.006);
}

TEST(WheelMesh, MeshTypeWheelInADeck) {
  const std::string xml = R"(<ParameterList name="railfe"><ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="wheel"/>
    <ParameterList name="Wheel">
      <Parameter name="Element size" type="double" value="0.03"/>
      <Parameter name="Elements around" type="int" value="24"/>
    </ParameterList></ParameterList></ParameterList>)";
  Deck deck = parse_deck(xml, "wheel.xml", ".");
  auto& section = deck.parameters->sublist("Mesh");
  const std::vector<MeshGeneratorDescriptor> generators = {wheel_mesh_generator()};
  validate_and_complete(section, *mesh_parameters(generators).list(), deck.source, "Mesh");
  const Mesh mesh = build_mesh(section, deck, generators);
  EXPECT_EQ(mesh.n_elements() % 24, 0);
  EXPECT_EQ(mesh.source, "wheel.xml: Mesh/Wheel");

  Deck other = parse_deck(xml, "wheel.xml", ".");
  const auto message = input_error_of([&] {
    validate_and_complete(other.parameters->sublist("Mesh"), *mesh_parameters().list(), "d",
                          "Mesh");
  });
  EXPECT_NE(message.find("Mesh/Type"), std::string::npos) << message;
}

}  // namespace
}  // namespace railfe
