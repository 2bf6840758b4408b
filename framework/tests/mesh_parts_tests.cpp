// Models of several parts: placement by a rigid motion against hand-computed coordinates,
// prefixed and renumbered blocks and sets, volumes and face sets carried along, and the deck
// mistakes Mesh/Type parts must refuse with the parameter's path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "framework/base/error.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/mesh_parameters.hpp"
#include "framework/mesh/mesh_parts.hpp"
#include "framework/testing/input_error.hpp"

namespace railfe {
namespace {

namespace fs = std::filesystem;
using Point = std::array<double, 3>;

fs::path source_dir() {
  const char* dir = std::getenv("RAILFE_SOURCE_DIR");
  return dir != nullptr ? fs::path(dir) : fs::path(".");
}

// Parses \p mesh_xml as the deck's Mesh section, validates it and builds the mesh.
Mesh build_from(const std::string& mesh_xml) {
  const std::string xml = "<ParameterList name=\"railfe\"><ParameterList name=\"Mesh\">" +
                          mesh_xml + "</ParameterList></ParameterList>";
  Deck deck = parse_deck(xml, "parts.xml", (source_dir() / "inputs/meshes").string());
  auto& section = deck.parameters->sublist("Mesh");
  validate_and_complete(section, *mesh_parameters().list(), deck.source, "Mesh");
  return build_mesh(section, deck);
}

// The 2 x 1 x 0.5 m box of 4 x 2 x 1 elements every part below is made of.
const char* const kBox = R"~(
  <Parameter name="Type" type="string" value="box"/>
  <ParameterList name="Box">
    <Parameter name="Lengths" type="Array(double)" value="{2, 1, 0.5}"/>
    <Parameter name="Elements" type="Array(int)" value="{4, 2, 1}"/>
  </ParameterList>)~";

BoxSpec box_spec() {
  BoxSpec spec;
  spec.lengths = {2, 1, 0.5};
  spec.elements = {4, 2, 1};
  return spec;
}

// Part "a" as generated; part "b" turned 90 degrees about z and moved by (5, 0, 1), so its
// point (x, y, z) lands at (5 - y, x, z + 1).
std::string two_boxes() {
  return std::string(R"~(<Parameter name="Type" type="string" value="parts"/>
    <ParameterList name="Parts"><ParameterList name="a">)~") +
         kBox + R"~(</ParameterList><ParameterList name="b">)~" + kBox + R"~(
      <Parameter name="Rotation axis" type="Array(double)" value="{0, 0, 2}"/>
      <Parameter name="Rotation angle" type="double" value="90"/>
      <Parameter name="Translation" type="Array(double)" value="{5, 0, 1}"/>
      <ParameterList name="Node sets"><ParameterList name="far_corner">
        <Parameter name="Point" type="Array(double)" value="{2, 1, 0.5}"/>
      </ParameterList></ParameterList>
    </ParameterList></ParameterList>
    <ParameterList name="Node sets"><ParameterList name="top_of_b_end">
      <Parameter name="Box" type="Array(double)" value="{-10, 10, -10, 10, 1.4, 1.6}"/>
      <Parameter name="Within" type="string" value="b.xmax"/>
    </ParameterList></ParameterList>)~";
}

Point b_placed(const Point& p) {
  return {5 - p[1], p[0], p[2] + 1};
}

// The one node three sets share (a corner of a box).
GlobalIndex common_node(const Mesh& mesh, const std::vector<std::string>& sets) {
  std::vector<GlobalIndex> common = mesh.node_set(sets[0], "", "").nodes;
  for (std::size_t i = 1; i < sets.size(); ++i) {
    const auto& nodes = mesh.node_set(sets[i], "", "").nodes;
    std::vector<GlobalIndex> kept;
    std::set_intersection(common.begin(), common.end(), nodes.begin(), nodes.end(),
                          std::back_inserter(kept));
    common = kept;
  }
  EXPECT_EQ(common.size(), 1u);
  return common.empty() ? -1 : common[0];
}

void expect_point(const Point& actual, const Point& expected) {
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(actual[d], expected[d], 1e-14) << "component " << d;
}

// Centroid and area-weighted outward normal of one element face.
std::pair<Point, Point> face_centroid_normal(const Mesh& mesh, const Side& side) {
  const auto& block = mesh.blocks[mesh.block_of(side.element)];
  const GlobalIndex* nodes = block.element_nodes(side.element - block.first_element);
  Point x[4];
  Point centroid{};
  for (int k = 0; k < 4; ++k) {
    x[k] = mesh.node(nodes[kHex8FaceNodes[side.face][k]]);
    for (int d = 0; d < 3; ++d)
      centroid[d] += 0.25 * x[k][d];
  }
  Point u, v;
  for (int d = 0; d < 3; ++d) {
    u[d] = x[2][d] - x[0][d];
    v[d] = x[3][d] - x[1][d];
  }
  return {centroid,
          {0.5 * (u[1] * v[2] - u[2] * v[1]), 0.5 * (u[2] * v[0] - u[0] * v[2]),
           0.5 * (u[0] * v[1] - u[1] * v[0])}};
}

TEST(MeshParts, TwoBoxesPlacedRenamedAndRenumbered) {
  const Mesh mesh = build_from(two_boxes());
  const Mesh reference = generate_box(box_spec());
  const GlobalIndex n = reference.n_nodes();
  ASSERT_EQ(n, 5 * 3 * 2);
  EXPECT_EQ(mesh.n_nodes(), 2 * n);  // no node merged
  EXPECT_EQ(mesh.n_elements(), 2 * 8);
  EXPECT_NO_THROW(check_mesh(mesh));

  // Part a stays where it was generated; part b's node i is reference node i, moved.
  for (GlobalIndex i = 0; i < n; ++i) {
    expect_point(mesh.node(i), reference.node(i));
    expect_point(mesh.node(n + i), b_placed(reference.node(i)));
  }
  // Corners computed by hand: b's origin corner and its far corner (2, 1, 0.5).
  expect_point(mesh.node(common_node(mesh, {"b.xmin", "b.ymin", "b.zmin"})), {5, 0, 1});
  expect_point(mesh.node(common_node(mesh, {"b.xmax", "b.ymax", "b.zmax"})), {4, 2, 1.5});
  expect_point(mesh.node(common_node(mesh, {"a.xmax", "a.ymax", "a.zmax"})), {2, 1, 0.5});
  // The part's own set (selected before placement) and the model's set (after it).
  const GlobalIndex far = common_node(mesh, {"b.xmax", "b.ymax", "b.zmax"});
  EXPECT_EQ(mesh.node_set("b.far_corner", "", "").nodes, std::vector<GlobalIndex>{far});
  EXPECT_EQ(mesh.node_set("top_of_b_end", "", "").nodes.size(), 3u);

  EXPECT_EQ(mesh.block_names(), (std::vector<std::string>{"a.block_1", "b.block_1"}));
  std::set<int> block_ids, node_set_ids, side_set_ids;
  for (const auto& block : mesh.blocks)
    block_ids.insert(block.id);
  for (const auto& set : mesh.node_sets)
    node_set_ids.insert(set.id);
  for (const auto& set : mesh.side_sets)
    side_set_ids.insert(set.id);
  EXPECT_EQ(block_ids.size(), 2u);
  EXPECT_EQ(node_set_ids.size(), mesh.node_sets.size());
  EXPECT_EQ(side_set_ids.size(), mesh.side_sets.size());
  EXPECT_EQ(mesh.side_sets.size(), 12u);
  for (const std::string set : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
    EXPECT_TRUE(mesh.has_node_set("a." + set)) << set;
    EXPECT_TRUE(mesh.has_side_set("b." + set)) << set;
    EXPECT_FALSE(mesh.has_node_set(set)) << set;
  }

  // A rigid motion keeps every element's volume: 2 x 1 x 0.5 m per part.
  EXPECT_NEAR(block_volume(mesh, mesh.blocks[0]), 1.0, 1e-14);
  EXPECT_NEAR(block_volume(mesh, mesh.blocks[1]), 1.0, 1e-14);

  // Face sets still hold the faces they held: same faces, centroids moved and outward normals
  // turned by the same motion (b's xmax faces now face +y).
  for (const std::string set : {"xmax", "ymin", "zmax"}) {
    const auto& placed = mesh.side_set("b." + set, "", "").sides;
    const auto& original = reference.side_set(set, "", "").sides;
    ASSERT_EQ(placed.size(), original.size());
    for (std::size_t s = 0; s < placed.size(); ++s) {
      EXPECT_EQ(placed[s].element, original[s].element + 8);
      EXPECT_EQ(placed[s].face, original[s].face);
      const auto [centroid, normal] = face_centroid_normal(mesh, placed[s]);
      const auto [centroid0, normal0] = face_centroid_normal(reference, original[s]);
      expect_point(centroid, b_placed(centroid0));
      expect_point(normal, {-normal0[1], normal0[0], normal0[2]});
    }
  }
  const auto [centroid, normal] =
      face_centroid_normal(mesh, mesh.side_set("b.xmax", "", "").sides[0]);
  EXPECT_NEAR(centroid[1], 2.0, 1e-14);
  EXPECT_GT(normal[1], 0);
}

// Keeping part b's block only: a's block is emptied but stays (block indices unchanged); b's
// elements renumber from 0, its faces follow them; a's faces and a's nodes' use are gone;
// node sets and coordinates are untouched.
TEST(MeshParts, MeshOfBlocksKeepsOnlyTheirElements) {
  const Mesh mesh = build_from(two_boxes());
  const Mesh kept = mesh_of_blocks(mesh, {1});
  ASSERT_EQ(kept.blocks.size(), 2u);
  EXPECT_EQ(kept.blocks[0].n_elements(), 0);
  EXPECT_EQ(kept.blocks[1].n_elements(), 8);
  EXPECT_EQ(kept.blocks[1].first_element, 0);
  EXPECT_EQ(kept.blocks[1].connectivity, mesh.blocks[1].connectivity);
  EXPECT_EQ(kept.coordinates, mesh.coordinates);
  EXPECT_EQ(kept.node_set("a.xmin", "", "").nodes, mesh.node_set("a.xmin", "", "").nodes);
  EXPECT_TRUE(kept.side_set("a.xmin", "", "").sides.empty());
  const auto& sides = kept.side_set("b.xmax", "", "").sides;
  const auto& before = mesh.side_set("b.xmax", "", "").sides;
  ASSERT_EQ(sides.size(), before.size());
  for (std::size_t s = 0; s < sides.size(); ++s) {
    EXPECT_EQ(sides[s].element, before[s].element - 8);
    EXPECT_EQ(sides[s].face, before[s].face);
  }
  EXPECT_NO_THROW(check_mesh(kept));
  const std::vector<char> used = used_nodes(kept);
  const GlobalIndex n = mesh.n_nodes() / 2;
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node)
    EXPECT_EQ(used[node], node >= n ? 1 : 0) << "node " << node;
}

TEST(MeshParts, RotationAboutASpaceDiagonal) {
  // 120 degrees about (1, 1, 1) sends x to y, y to z and z to x: (x, y, z) -> (z, x, y).
  Mesh mesh = generate_box(box_spec());
  const Mesh reference = mesh;
  place_mesh(mesh, {{1, 1, 1}, 120, {0.5, -1, 2}});
  for (GlobalIndex i = 0; i < mesh.n_nodes(); ++i) {
    const Point p = reference.node(i);
    const Point q = mesh.node(i);
    EXPECT_NEAR(q[0], p[2] + 0.5, 1e-14);
    EXPECT_NEAR(q[1], p[0] - 1, 1e-14);
    EXPECT_NEAR(q[2], p[1] + 2, 1e-14);
  }
  EXPECT_NEAR(block_volume(mesh, mesh.blocks[0]), 1.0, 1e-14);
  EXPECT_NO_THROW(check_mesh(mesh));
  // Half turns are exact: no round-off where coordinates should coincide.
  Mesh turned = generate_box(box_spec());
  place_mesh(turned, {{1, 0, 0}, 180, {0, 0, 0}});
  for (GlobalIndex i = 0; i < turned.n_nodes(); ++i) {
    EXPECT_EQ(turned.node(i)[1], -reference.node(i)[1]);
    EXPECT_EQ(turned.node(i)[2], -reference.node(i)[2]);
  }
}

TEST(MeshParts, FilePartsScaleEach) {
  // The same Gmsh bars twice, the second at half size: each part's own Length scale.
  const Mesh mesh = build_from(R"~(<Parameter name="Type" type="string" value="parts"/>
    <ParameterList name="Parts">
      <ParameterList name="full">
        <Parameter name="Type" type="string" value="gmsh"/>
        <Parameter name="File" type="string" value="tied_bar.msh"/>
      </ParameterList>
      <ParameterList name="half">
        <Parameter name="Type" type="string" value="gmsh"/>
        <Parameter name="File" type="string" value="tied_bar.msh"/>
        <Parameter name="Length scale" type="double" value="0.5"/>
      </ParameterList>
    </ParameterList>)~");
  const GlobalIndex n = mesh.n_nodes() / 2;
  for (GlobalIndex i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d)
      EXPECT_DOUBLE_EQ(mesh.node(n + i)[d], 0.5 * mesh.node(i)[d]);
  }
  EXPECT_EQ(mesh.block_names(),
            (std::vector<std::string>{"full.left", "full.right", "half.left", "half.right"}));
  EXPECT_TRUE(mesh.has_node_set("half.interface_right"));
}

void expect_refused(const std::string& mesh_xml, const std::string& path,
                    const std::string& words) {
  const std::string message = input_error_of([&] { build_from(mesh_xml); });
  EXPECT_NE(message.find("parts.xml: '" + path + "':"), std::string::npos) << message;
  EXPECT_NE(message.find(words), std::string::npos) << message;
}

// A Mesh of Type parts holding one part whose body is \p part.
std::string one_part(const std::string& name, const std::string& part) {
  return R"~(<Parameter name="Type" type="string" value="parts"/>
    <ParameterList name="Parts"><ParameterList name=")~" +
         name + "\">" + part + "</ParameterList></ParameterList>";
}

TEST(MeshParts, BadInputNamesThePath) {
  expect_refused(one_part("p", R"~(<Parameter name="Type" type="string" value="parts"/>)~"),
                 "Mesh/Parts/p/Type", "'parts'");
  expect_refused(one_part("p", std::string(kBox) +
                                   R"~(<Parameter name="Rotation axis" type="Array(double)"
                                       value="{0, 0, 0}"/>)~"),
                 "Mesh/Parts/p/Rotation axis", "zero length");
  expect_refused(one_part("a.b", kBox), "Mesh/Parts/a.b", "'.'");
  expect_refused(one_part("p", R"~(<Parameter name="Type" type="string" value="box"/>)~"),
                 "Mesh/Parts/p/Box", "missing required sublist");
  expect_refused(one_part("p", R"~(<Parameter name="Type" type="string" value="gmsh"/>
                                  <Parameter name="File" type="string" value="none.msh"/>)~"),
                 "Mesh/Parts/p/File", "none.msh");
  expect_refused(R"~(<Parameter name="Type" type="string" value="parts"/>)~", "Mesh/Parts",
                 "no parts");
  // Placement belongs to parts; a single mesh has no Parts; a model of parts has no File.
  expect_refused(std::string(kBox) + R"~(<Parameter name="Rotation angle" type="double"
                                         value="90"/>)~",
                 "Mesh/Rotation angle", "unknown parameter");
  expect_refused(std::string(kBox) + R"~(<ParameterList name="Parts"><ParameterList name="p">)~" +
                     kBox + "</ParameterList></ParameterList>",
                 "Mesh/Parts", "only when Type is 'parts'");
  expect_refused(one_part("p", kBox) + R"~(<Parameter name="File" type="string" value="x.msh"/>)~",
                 "Mesh/File", "Type is 'parts'");
  // A part's sets exist only under the prefixed name.
  expect_refused(one_part("p", kBox) + R"~(<ParameterList name="Node sets">
                   <ParameterList name="s"><Parameter name="Box" type="Array(double)"
                   value="{0, 1, 0, 1, 0, 1}"/><Parameter name="Within" type="string"
                   value="xmax"/></ParameterList></ParameterList>)~",
                 "Mesh/Node sets/s/Within", "p.xmax");
}

}  // namespace
}  // namespace railfe
