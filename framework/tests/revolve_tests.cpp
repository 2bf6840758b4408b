// Bodies of revolution: revolving a quadrilateral section (volume against the inscribed-polygon
// formula, node count, orientation, sets), reading sections from Gmsh, and Mesh/Type revolved.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "framework/base/constants.hpp"
#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/mesh_parameters.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/mesh/revolve.hpp"
#include "framework/testing/input_error.hpp"

namespace railfe {
namespace {

namespace fs = std::filesystem;

fs::path source_dir() {
  const char* dir = std::getenv("RAILFE_SOURCE_DIR");
  return dir != nullptr ? fs::path(dir) : fs::path(".");
}

// Volume of every block.
double volume(const Mesh& mesh) {
  double sum = 0;
  for (const auto& block : mesh.blocks)
    sum += block_volume(mesh, block);
  return sum;
}

// [r0, r1] × [a0, a1] in nr × na quads; odd rows listed clockwise, to test the orientation.
SectionMesh rectangle(double r0, double r1, double a0, double a1, int nr, int na) {
  SectionMesh section;
  section.source = "rectangle";
  section.blocks.push_back({"annulus", 7});
  for (int j = 0; j <= na; ++j) {
    for (int i = 0; i <= nr; ++i) {
      section.coordinates.push_back(r0 + (r1 - r0) * i / nr);
      section.coordinates.push_back(a0 + (a1 - a0) * j / na);
    }
  }
  auto node = [&](int i, int j) { return static_cast<GlobalIndex>(i + (nr + 1) * j); };
  for (int j = 0; j < na; ++j) {
    for (int i = 0; i < nr; ++i) {
      std::array<GlobalIndex, 4> quad{node(i, j), node(i + 1, j), node(i + 1, j + 1),
                                      node(i, j + 1)};
      if (j % 2 == 1)
        std::swap(quad[1], quad[3]);
      section.quads.push_back(quad);
      section.quad_blocks.push_back(0);
    }
  }
  NodeSet inner{"inner", 3, {}};
  for (int j = 0; j <= na; ++j)
    inner.nodes.push_back(node(0, j));
  section.node_sets.push_back(inner);
  return section;
}

TEST(Revolve, AnnulusVolumeCountsAndSets) {
  const double r0 = 0.2, r1 = 0.5, a0 = -0.1, a1 = 0.3;
  const int nr = 3, na = 4, n = 12;
  const Mesh mesh = revolve(rectangle(r0, r1, a0, a1, nr, na), n);
  EXPECT_EQ(mesh.n_nodes(), n * (nr + 1) * (na + 1));  // the seam is merged
  EXPECT_EQ(mesh.n_elements(), n * nr * na);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "annulus");
  EXPECT_EQ(mesh.blocks[0].id, 7);
  EXPECT_NO_THROW(check_mesh(mesh));  // positive Jacobians although half the quads were clockwise

  // Each slice of the rectangle is a trapezoid prism of area (r1² − r0²) sin(2π/n)/2, so the
  // mesh holds the inscribed polygonal annulus exactly, and falls short of the true annulus by
  // 1 − sin(x)/x = x²/6 − x⁴/120 + O(x⁶) with x = 2π/n (4.5% for n = 12).
  const double exact = kPi * (r1 * r1 - r0 * r0) * (a1 - a0);
  const double polygon = n * std::sin(2 * kPi / n) / (2 * kPi) * exact;
  EXPECT_NEAR(volume(mesh), polygon, 1e-13 * exact);
  const double x = 2 * kPi / n;
  EXPECT_NEAR(1 - volume(mesh) / exact, x * x / 6 - std::pow(x, 4) / 120, std::pow(x, 6) / 5040);

  const auto& inner = mesh.node_set("inner", "", "");
  EXPECT_EQ(inner.nodes.size(), static_cast<std::size_t>(n * (na + 1)));
  EXPECT_EQ(inner.id, 3);
  for (GlobalIndex node : inner.nodes) {
    const auto x = mesh.node(node);
    EXPECT_NEAR(std::hypot(x[0], x[2]), r0, 1e-15);
  }
  const auto& sides = mesh.side_set("inner", "", "");
  EXPECT_EQ(sides.sides.size(), static_cast<std::size_t>(n * na));
  for (const Side& side : sides.sides) {
    EXPECT_EQ(side.face, 3);  // the r = r0 edge of each quad, once oriented
    const int b = mesh.block_of(side.element);
    const GlobalIndex* nodes = mesh.blocks[b].element_nodes(side.element);
    for (int k : {0, 3, 4, 7}) {
      const auto x = mesh.node(nodes[k]);
      EXPECT_NEAR(std::hypot(x[0], x[2]), r0, 1e-15);
    }
  }
}

TEST(Revolve, UnequalAnglesGiveTheInscribedPolygonOfThoseChords) {
  // Slices of 10° over a quarter turn and 30° elsewhere: the volume is the sum of each slice's
  // chord prism, (r1² − r0²) sin(Δθ)/2 × height.
  std::vector<double> angles;
  for (int d = 0; d < 90; d += 10)
    angles.push_back(d * kPi / 180);
  for (int d = 90; d < 360; d += 30)
    angles.push_back(d * kPi / 180);
  const Mesh mesh = revolve(rectangle(0.2, 0.5, 0, 0.1, 2, 1), angles);
  EXPECT_NO_THROW(check_mesh(mesh));
  const double prism = (0.25 - 0.04) / 2 * 0.1;
  EXPECT_NEAR(volume(mesh), prism * (9 * std::sin(kPi / 18) + 9 * std::sin(kPi / 6)), 1e-15);
}

// Rows r = 0.4-0.5 at 12 slices, 0.2-0.3 at 4 (every third angle), the 3-to-1 template between.
Mesh coarsening_annulus(std::vector<std::vector<std::size_t>> coarser = {{0, 3, 6, 9}}) {
  const SectionMesh section = rectangle(0.2, 0.5, 0, 0.1, 3, 2);
  std::vector<int> level;
  for (GlobalIndex i = 0; i < section.n_nodes(); ++i)
    level.push_back(section.coordinates[2 * i] < 0.35 ? 1 : 0);
  std::vector<double> angles;
  for (int k = 0; k < 12; ++k)
    angles.push_back(2 * kPi * k / 12);
  return revolve(section, angles, level, coarser);
}

TEST(Revolve, CoarseningSlicesTileTheBodyConformingly) {
  const Mesh mesh = coarsening_annulus();
  // Nodes: 2 radii x 3 heights at 12 angles, 2 x 3 at 4, and the templates' middles on the 3
  // edges that join the levels at the 8 angles between. Hexes: 12 x 2, 4 x 4 x 2, 4 x 2.
  EXPECT_EQ(mesh.n_nodes(), 72 + 24 + 24);
  EXPECT_EQ(mesh.n_elements(), 24 + 32 + 8);
  EXPECT_NO_THROW(check_mesh(mesh));
  // Every piece is a right prism over straight-edged quads that tile the ring between the
  // outer 12-gon and the inner 4-gon, so the volume is exact: h (A12(0.5) − A4(0.2)).
  auto polygon = [](int n, double r) { return n * r * r * std::sin(2 * kPi / n) / 2; };
  EXPECT_NEAR(volume(mesh), 0.1 * (polygon(12, 0.5) - polygon(4, 0.2)), 1e-15);
  // Conforming: every face is shared by two hexes or lies on the outside (24 at r = 0.5, 8 at
  // r = 0.2, 12 + 16 + 4 on each end plane); a hanging node would leave more faces single.
  std::map<std::array<GlobalIndex, 4>, int> faces;
  for (const auto& block : mesh.blocks)
    for (GlobalIndex e = 0; e < block.n_elements(); ++e)
      for (int f = 0; f < 6; ++f) {
        std::array<GlobalIndex, 4> face;
        for (int j = 0; j < 4; ++j)
          face[j] = block.element_nodes(e)[kHex8FaceNodes[f][j]];
        std::sort(face.begin(), face.end());
        ++faces[face];
      }
  int single = 0, shared = 0;
  for (const auto& [face, count] : faces) {
    single += count == 1;
    shared += count == 2;
    EXPECT_LE(count, 2);
  }
  EXPECT_EQ(single, 24 + 8 + 2 * 32);
  EXPECT_EQ(shared, (6 * 64 - single) / 2);
  const auto& inner = mesh.node_set("inner", "", "");
  EXPECT_EQ(inner.nodes.size(), 12u);
  const auto& sides = mesh.side_set("inner", "", "");
  ASSERT_EQ(sides.sides.size(), 8u);
  for (const Side& side : sides.sides) {
    const GlobalIndex* nodes = mesh.blocks[0].element_nodes(side.element);
    for (int j = 0; j < 4; ++j) {
      const auto x = mesh.node(nodes[kHex8FaceNodes[side.face][j]]);
      EXPECT_NEAR(std::hypot(x[0], x[2]), 0.2, 1e-15);
    }
  }
}

TEST(Revolve, CoarseningSlicesMustSpanOneOrThree) {
  EXPECT_THROW(coarsening_annulus({{0, 2, 6, 9}}), std::logic_error);
  EXPECT_THROW(coarsening_annulus({{1, 3, 6, 9}}), std::logic_error);
  EXPECT_NO_THROW(coarsening_annulus({{0, 1, 2, 3, 6, 9}}));
}

TEST(Extrude, PrismVolumeSetsAndEndFaces) {
  // A 0.3 × 0.4 section swept over graded stations: volume = area × length, every Jacobian
  // positive (half the quads listed clockwise), the section's set along the whole length, and
  // the end faces at the first and last stations.
  const std::vector<double> stations = {-0.1, 0.0, 0.05, 0.07, 0.08, 0.2};
  const Mesh mesh = extrude(rectangle(0.2, 0.5, -0.1, 0.3, 3, 4), stations);
  EXPECT_EQ(mesh.n_nodes(), 6 * 4 * 5);
  EXPECT_EQ(mesh.n_elements(), 5 * 3 * 4);
  EXPECT_NO_THROW(check_mesh(mesh));
  EXPECT_NEAR(volume(mesh), 0.3 * 0.4 * 0.3, 1e-15);
  EXPECT_EQ(mesh.side_set("inner", "", "").sides.size(), 5u * 4u);
  for (const char* name : {"start_face", "end_face"}) {
    const double x = name[0] == 's' ? stations.front() : stations.back();
    EXPECT_EQ(mesh.node_set(name, "", "").nodes.size(), 20u) << name;
    const auto& sides = mesh.side_set(name, "", "");
    ASSERT_EQ(sides.sides.size(), 12u) << name;
    for (const Side& side : sides.sides) {
      const int b = mesh.block_of(side.element);
      const GlobalIndex* nodes = mesh.blocks[b].element_nodes(side.element);
      for (int k = 0; k < 4; ++k)
        EXPECT_DOUBLE_EQ(mesh.node(nodes[kHex8FaceNodes[side.face][k]])[0], x) << name;
    }
  }
}

TEST(Revolve, RefusesNodesOnTheAxisAndTooFewSlices) {
  SectionMesh section = rectangle(0, 1, 0, 1, 2, 2);
  auto message = input_error_of([&] { revolve(section, 8); });
  EXPECT_NE(message.find("section node 1 has r = 0"), std::string::npos) << message;
  EXPECT_NE(message.find("small bore"), std::string::npos) << message;
  message = input_error_of([&] { revolve(rectangle(1, 2, 0, 1, 1, 1), 2); });
  EXPECT_NE(message.find("at least 3"), std::string::npos) << message;
}

TEST(Revolve, RingSectionFromGmsh) {
  const auto path = (source_dir() / "inputs/meshes/ring_section.msh").string();
  const SectionMesh section = read_gmsh_section(path);
  ASSERT_EQ(section.blocks.size(), 1u);
  EXPECT_EQ(section.blocks[0].name, "ring");
  EXPECT_EQ(section.n_nodes(), 9 * 9 + 4 * 8 * 4);  // O-grid, n = 8: the centre point dropped
  const int n = 64;
  const Mesh ring = revolve(section, n);
  EXPECT_EQ(ring.n_nodes(), n * section.n_nodes());
  EXPECT_NO_THROW(check_mesh(ring));
  // The circle is a regular 32-gon symmetric about r = R, so the volume is n sin(2π/n) R A.
  const double R = 1, rho = 0.05, area = 16 * rho * rho * std::sin(kPi / 16);
  EXPECT_NEAR(section.area(), area, 1e-15);
  EXPECT_NEAR(volume(ring), n * std::sin(2 * kPi / n) * R * area, 1e-12);
  EXPECT_EQ(ring.node_set("surface", "", "").nodes.size(), static_cast<std::size_t>(n * 32));
  EXPECT_EQ(ring.side_set("surface", "", "").sides.size(), static_cast<std::size_t>(n * 32));
}

TEST(Revolve, GmshSectionMustBeQuadrangles) {
  const auto dir =
      fs::temp_directory_path() / ("railfe_revolve_" + std::to_string(Communicator().rank()));
  fs::create_directories(dir);
  std::ofstream(dir / "tri.geo") << "Point(1) = {1, 0, 0, 0.5};\nPoint(2) = {2, 0, 0, 0.5};\n"
                                    "Point(3) = {1, 1, 0, 0.5};\nLine(1) = {1, 2};\n"
                                    "Line(2) = {2, 3};\nLine(3) = {3, 1};\n"
                                    "Curve Loop(1) = {1, 2, 3};\nPlane Surface(1) = {1};\n";
  const std::string command = "gmsh -2 -format msh41 -o " + (dir / "tri.msh").string() + " " +
                              (dir / "tri.geo").string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const auto message = input_error_of([&] { read_gmsh_section((dir / "tri.msh").string()); });
  EXPECT_NE(message.find("only quadrangles"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(Revolve, MeshTypeRevolvedInADeck) {
  const auto dir = source_dir() / "inputs/meshes";
  const std::string xml = R"(<ParameterList name="railfe"><ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="revolved"/>
    <ParameterList name="Revolved">
      <Parameter name="Section file" type="string" value="ring_section.msh"/>
      <Parameter name="Elements around" type="int" value="16"/>
    </ParameterList></ParameterList></ParameterList>)";
  Deck deck = parse_deck(xml, "ring.xml", dir.string());
  auto& section = deck.parameters->sublist("Mesh");
  validate_and_complete(section, *mesh_parameters().list(), deck.source, "Mesh");
  const Mesh mesh = build_mesh(section, deck);
  EXPECT_EQ(mesh.n_elements(), 16 * (64 + 4 * 8 * 4));
  EXPECT_TRUE(mesh.has_node_set("surface"));

  section.sublist("Revolved").set("Elements around", 2);
  const auto message = input_error_of(
      [&] { validate_and_complete(section, *mesh_parameters().list(), "d", "Mesh"); });
  EXPECT_NE(message.find("Mesh/Revolved/Elements around"), std::string::npos) << message;
}

}  // namespace
}  // namespace railfe
