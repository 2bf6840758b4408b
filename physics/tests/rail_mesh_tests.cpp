// The rail mesh generator: stations graded from the solution zone, the section's area against
// the drawing's exact area, the running surface on the drawn arcs, refused dimensions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/geometry/rail_drawing.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/testing/input_error.hpp"
#include "physics/parts/rail_mesh.hpp"

namespace railfe {
namespace {

RailDimensions zoned() {
  RailDimensions d;
  d.length = 1.2;
  d.solution_zone = {0.5, 0.65};
  d.zone_element_size = 0.001;
  d.element_size = 0.03;
  d.head_element_size = 0.006;
  d.section_element_size = 0.012;
  return d;
}

TEST(RailMesh, StationsAreUniformInTheZoneAndGradedAway) {
  const RailDimensions d = zoned();
  const std::vector<double> x = rail_stations(d);
  EXPECT_EQ(x.front(), 0);
  EXPECT_EQ(x.back(), 1.2);
  int in_zone = 0;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double h = x[k + 1] - x[k];
    ASSERT_GT(h, 0);
    EXPECT_LT(h, 1.5 * d.element_size);
    if (x[k] >= 0.5 - 1e-12 && x[k + 1] <= 0.65 + 1e-12) {
      EXPECT_NEAR(h, 0.001, 1e-12);
      ++in_zone;
    }
    if (k + 2 < x.size()) {  // neighbours grow by at most the growth ratio (and its rescaling)
      const double ratio = (x[k + 2] - x[k + 1]) / h;
      EXPECT_LT(std::max(ratio, 1 / ratio), 1.5 * d.growth) << k;
    }
  }
  EXPECT_EQ(in_zone, 150);
  RailDimensions uniform = d;
  uniform.solution_zone.clear();
  EXPECT_EQ(rail_stations(uniform).size(), 41u);
}

TEST(RailMesh, SectionIsTheDrawnSection) {
  RailDimensions d = zoned();
  d.solution_zone = {0.5, 0.52};
  const Mesh mesh = build_rail_mesh(d, "test");
  EXPECT_NO_THROW(check_mesh(mesh));
  const RailOutline outline = rail_outline("54E1");
  // The section's chords cut the convex arcs (less volume) and bridge the concave ones (more):
  // the web's fillets (8-22 mm radii under 12 mm elements) dominate, +2.0e-3 of area x length.
  double volume = 0;
  for (const auto& block : mesh.blocks)
    volume += block_volume(mesh, block);
  const double exact = section_properties(outline).area * d.length;
  EXPECT_NEAR(volume / exact, 1, 3e-3);
  // Running-surface nodes on the drawn arcs, foot nodes on the foot.
  for (GlobalIndex node : mesh.node_set("running_surface", "", "").nodes) {
    const auto p = mesh.node(node);
    EXPECT_LT(distance_to_outline(outline, {p[1], p[2]}), 1e-9);
    EXPECT_GT(p[2], -0.0145);  // down to the 13 mm corner's end at 14.1 mm
  }
  // Running-surface nodes at most the head size apart around the head (in the first slice).
  std::vector<std::array<double, 2>> head;
  for (GlobalIndex node : mesh.node_set("running_surface", "", "").nodes) {
    if (mesh.node(node)[0] == 0)
      head.push_back({mesh.node(node)[1], mesh.node(node)[2]});
  }
  std::sort(head.begin(), head.end());
  ASSERT_GT(head.size(), 10u);
  double widest = 0;
  for (std::size_t i = 0; i + 1 < head.size(); ++i) {
    widest = std::max(widest, std::hypot(head[i + 1][0] - head[i][0], head[i + 1][1] - head[i][1]));
  }
  EXPECT_LT(widest, 1.0 * d.head_element_size);
  EXPECT_GT(widest, 0.5 * d.head_element_size);
  for (GlobalIndex node : mesh.node_set("foot_bottom", "", "").nodes)
    EXPECT_NEAR(mesh.node(node)[2], -0.159, 1e-12);
  EXPECT_GT(mesh.side_set("running_surface", "", "").sides.size(), 0u);
  EXPECT_GT(mesh.side_set("end_face", "", "").sides.size(), 0u);
}

TEST(RailMesh, ContradictoryDimensionsAreRefused) {
  auto refused = [](const std::string& rail) {
    const std::string xml = R"(<ParameterList name="railfe"><ParameterList name="Mesh">
      <Parameter name="Type" type="string" value="rail"/><ParameterList name="Rail">)" +
                            rail + "</ParameterList></ParameterList></ParameterList>";
    Deck deck = parse_deck(xml, "rail.xml", ".");
    auto& mesh = deck.parameters->sublist("Mesh");
    const std::vector<MeshGeneratorDescriptor> generators = {rail_mesh_generator()};
    return input_error_of([&] {
      validate_and_complete(mesh, *mesh_parameters(generators).list(), deck.source, "Mesh");
      rail_dimensions(mesh.sublist("Rail"), deck);
    });
  };
  const std::string length = R"(<Parameter name="Length" type="double" value="1"/>)";
  std::string message = refused(
      length + R"x(<Parameter name="Solution zone" type="Array(double)" value="{0.5, 1.5}"/>)x");
  EXPECT_NE(message.find("Mesh/Rail/Solution zone"), std::string::npos) << message;
  message =
      refused(length + R"(<Parameter name="Zone element size" type="double" value="0.002"/>)");
  EXPECT_NE(message.find("without a Solution zone"), std::string::npos) << message;
  message = refused(length + R"(<Parameter name="Head element size" type="double" value="0.03"/>)");
  EXPECT_NE(message.find("coarser than the Section element size"), std::string::npos) << message;
  message = refused(R"(<Parameter name="Profile" type="string" value="49E1"/>)" + length);
  EXPECT_NE(message.find("Profile"), std::string::npos) << message;
}

}  // namespace
}  // namespace railfe
