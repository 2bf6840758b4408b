// The structural model layer: the line mesh generator's nodes, blocks and sets; the Sections
// table read from a deck (shapes computed, Euler-Bernoulli limit, springs' frames, point-mass
// inertia) and what it refuses, naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "framework/testing/input_error.hpp"
#include "physics/common/structural_sections.hpp"
#include "physics/materials/elastic_material.hpp"
#include "physics/parts/line_mesh.hpp"

namespace railfe {
namespace {

// A line of two segments (3 and 2 elements) with a one-node block at its end.
Mesh two_segments() {
  LineSpec spec;
  spec.points = {0, 0, 0, 3, 0, 0, 3, 4, 0};
  spec.elements = {3, 2};
  spec.end_block = "tip";
  return build_line_mesh(spec, "test");
}

TEST(LineMesh, NodesBlocksAndSets) {
  const Mesh mesh = two_segments();
  ASSERT_EQ(mesh.n_nodes(), 6);
  ASSERT_EQ(mesh.blocks.size(), 2u);
  EXPECT_EQ(mesh.blocks[0].type, ElementType::beam2);
  EXPECT_EQ(mesh.blocks[0].n_elements(), 5);
  EXPECT_EQ(mesh.blocks[1].type, ElementType::point_mass);
  EXPECT_EQ(mesh.blocks[1].element_nodes(0)[0], 5);
  EXPECT_EQ(mesh.node(2)[0], 2.0);  // equally spaced on the first segment
  EXPECT_EQ(mesh.node(4)[1], 2.0);  // and on the second
  EXPECT_EQ(mesh.node_set("start", "", "").nodes, std::vector<GlobalIndex>{0});
  EXPECT_EQ(mesh.node_set("end", "", "").nodes, std::vector<GlobalIndex>{5});
  EXPECT_EQ(mesh.node_set("points", "", "").nodes, (std::vector<GlobalIndex>{0, 3, 5}));
  EXPECT_EQ(mesh.node_set("all", "", "").nodes.size(), 6u);
  for (GlobalIndex e = 0; e < mesh.blocks[0].n_elements(); ++e)  // consecutive nodes
    EXPECT_EQ(mesh.blocks[0].element_nodes(e)[1], mesh.blocks[0].element_nodes(e)[0] + 1);
}

// The message of what reading \p sections (XML of the Sections list's children) over
// two_segments() with a steel material throws, or "" with the table in \p table.
std::string read(const std::string& sections, std::optional<SectionTable>* table = nullptr) {
  const std::string xml = R"x(<ParameterList name="railfe"><ParameterList name="Materials">
    <ParameterList name="steel"><Parameter name="Young's modulus" type="double" value="2e11"/>
    <Parameter name="Poisson's ratio" type="double" value="0.25"/>
    <Parameter name="Density" type="double" value="8000"/></ParameterList></ParameterList>
    <ParameterList name="Sections">)x" +
                          sections + "</ParameterList></ParameterList>";
  Deck deck = parse_deck(xml, "deck.xml", ".");
  const Mesh mesh = two_segments();
  return input_error_of([&] {
    auto& materials = deck.parameters->sublist("Materials");
    auto& list = deck.parameters->sublist("Sections");
    validate_and_complete(materials, *materials_parameters().list(), deck.source, "Materials");
    validate_and_complete(list, *sections_parameters().list(), deck.source, "Sections");
    SectionTable read_table(list, &materials, mesh, deck.source);
    read_table.require_structural_blocks(mesh, deck.source);
    read_table.check_elements(mesh, deck.source);
    if (table != nullptr)
      table->emplace(read_table);
  });
}

const char* const kBeam = R"x(<ParameterList name="girder">
  <Parameter name="Blocks" type="Array(string)" value="{beam}"/>
  <Parameter name="Element" type="string" value="beam"/>
  <Parameter name="Material" type="string" value="steel"/>
  <Parameter name="Orientation" type="Array(double)" value="{0, 0, 1}"/>)x";
const char* const kMass = R"x(<ParameterList name="body">
  <Parameter name="Blocks" type="Array(string)" value="{tip}"/>
  <Parameter name="Element" type="string" value="point mass"/>
  <Parameter name="Mass" type="double" value="5"/>
  <Parameter name="Inertia" type="Array(double)" value="{1, 2, 3, 0.1, 0, 0}"/></ParameterList>)x";

TEST(Sections, ShapesAreComputedAndTheEulerBernoulliLimitTaken) {
  std::optional<SectionTable> table;
  const std::string rectangle = std::string(kBeam) +
                                R"x(<Parameter name="Shape" type="string" value="rectangle"/>
    <Parameter name="Width" type="double" value="0.1"/>
    <Parameter name="Height" type="double" value="0.2"/>
    <Parameter name="Shear deformation" type="bool" value="false"/></ParameterList>)x";
  ASSERT_EQ(read(rectangle + kMass, &table), "");
  const BeamProperties& beam = table->of_block(0).beam;
  EXPECT_NEAR(beam.section.area, 0.02, 1e-15);
  EXPECT_NEAR(beam.section.iy, 0.1 * 0.008 / 12, 1e-18);  // b h^3 / 12 about local y
  EXPECT_NEAR(beam.section.iz, 0.2 * 0.001 / 12, 1e-18);
  EXPECT_EQ(beam.section.shear_area_y, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(beam.material.shear_modulus, 2e11 / 2.5, 1);
  const PointMassProperties& point = table->of_block(1).point;
  EXPECT_EQ(point.mass, 5);
  EXPECT_EQ(point.inertia(0, 1), 0.1);
  EXPECT_EQ(point.inertia(1, 0), 0.1);
  EXPECT_EQ(point.inertia(2, 2), 3);
}

TEST(Sections, WhatTheChosenOptionsIgnoreOrLackIsRefused) {
  const std::string beam = kBeam;
  std::string message = read(beam + R"x(<Parameter name="Shape" type="string" value="rectangle"/>
    <Parameter name="Width" type="double" value="0.1"/><Parameter name="Height" type="double"
    value="0.2"/><Parameter name="Diameter" type="double" value="0.2"/></ParameterList>)x");
  EXPECT_NE(message.find("Sections/girder/Diameter"), std::string::npos) << message;
  message =
      read(beam + R"x(<Parameter name="Shape" type="string" value="circle"/></ParameterList>)x");
  EXPECT_NE(message.find("Sections/girder/Diameter': missing"), std::string::npos) << message;
  message = read(beam + R"x(<Parameter name="Area" type="double" value="0.01"/>
    <Parameter name="Iy" type="double" value="1e-5"/><Parameter name="Iz" type="double"
    value="1e-5"/><Parameter name="Torsion constant" type="double" value="2e-5"/>
    <Parameter name="Shear area y" type="double" value="0.008"/></ParameterList>)x");
  EXPECT_NE(message.find("Sections/girder/Shear area z"), std::string::npos) << message;
  // The orientation along the first segment (x): element 1 is named with its nodes.
  const std::string along_x = R"x(<ParameterList name="girder">
    <Parameter name="Blocks" type="Array(string)" value="{beam}"/>
    <Parameter name="Element" type="string" value="beam"/>
    <Parameter name="Material" type="string" value="steel"/>
    <Parameter name="Shape" type="string" value="circle"/>
    <Parameter name="Diameter" type="double" value="0.1"/>
    <Parameter name="Orientation" type="Array(double)" value="{1, 0, 0}"/></ParameterList>)x";
  message = read(along_x + kMass);
  EXPECT_NE(message.find("element 1 (nodes 1, 2)"), std::string::npos) << message;
  // A point-mass section on the beam block; a beam block left without a section.
  message = read(R"x(<ParameterList name="body">
    <Parameter name="Blocks" type="Array(string)" value="{beam}"/>
    <Parameter name="Element" type="string" value="point mass"/>
    <Parameter name="Mass" type="double" value="5"/></ParameterList>)x");
  EXPECT_NE(message.find("holds BEAM2 elements"), std::string::npos) << message;
  message = read(kMass);
  EXPECT_NE(message.find("block 'beam' (BEAM2) has no section"), std::string::npos) << message;
  // A spring frame whose two vectors are parallel.
  message = read(std::string(kMass) + R"x(<ParameterList name="mount">
    <Parameter name="Blocks" type="Array(string)" value="{beam}"/>
    <Parameter name="Element" type="string" value="spring-damper"/>
    <Parameter name="Axes" type="Array(double)" value="{1, 0, 0, 2, 0, 0}"/></ParameterList>)x");
  EXPECT_NE(message.find("Sections/mount/Axes"), std::string::npos) << message;
}

}  // namespace
}  // namespace railfe
