// Meshes: the box generator, checks for bad elements, derived sets, the Exodus and Gmsh readers
// (against files written by the Exodus library directly and by the gmsh program), partitioning.
#include <gtest/gtest.h>

#include <exodusII.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "framework/base/error.hpp"
#include "framework/base/parallel.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/derived_sets.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/mesh/partition.hpp"
#include "framework/testing/input_error.hpp"

namespace railfe {
namespace {

namespace fs = std::filesystem;

// A scratch directory per rank and test.
fs::path scratch(const std::string& name) {
  const auto path = fs::temp_directory_path() /
                    ("railfe_mesh_" + name + "_" + std::to_string(Communicator().rank()));
  fs::remove_all(path);
  fs::create_directories(path);
  return path;
}

TEST(Box, CountsSetsAndGrading) {
  BoxSpec spec;
  spec.lengths = {2, 1, 0.5};
  spec.elements = {4, 3, 2};
  spec.grading = {4, 1, 1};
  const Mesh mesh = generate_box(spec);
  EXPECT_EQ(mesh.n_nodes(), 5 * 4 * 3);
  EXPECT_EQ(mesh.n_elements(), 4 * 3 * 2);
  EXPECT_EQ(mesh.node_set("xmax", "", "").nodes.size(), 4u * 3u);
  EXPECT_EQ(mesh.side_set("zmin", "", "").sides.size(), 4u * 3u);
  EXPECT_NO_THROW(check_mesh(mesh));
  const auto x = graded_positions(0, 2, 4, 4);
  EXPECT_NEAR((x[4] - x[3]) / (x[1] - x[0]), 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(x[4], 2.0);
  // Every side of a face set lies on that face.
  for (const Side& side : mesh.side_set("xmax", "", "").sides) {
    const auto& block = mesh.blocks[0];
    const GlobalIndex* nodes = block.element_nodes(side.element);
    for (int k : {1, 2, 5, 6})
      EXPECT_DOUBLE_EQ(mesh.coordinates[3 * nodes[k]], 2.0);
    EXPECT_EQ(side.face, 1);
  }
}

TEST(MeshChecks, InvertedAndDegenerateElementsAreRefused) {
  BoxSpec spec;
  spec.elements = {2, 1, 1};
  Mesh inverted = generate_box(spec);
  auto& conn = inverted.blocks[0].connectivity;
  std::swap(conn[8 + 0], conn[8 + 4]);  // element 2: bottom and top swapped
  std::swap(conn[8 + 1], conn[8 + 5]);
  std::swap(conn[8 + 2], conn[8 + 6]);
  std::swap(conn[8 + 3], conn[8 + 7]);
  auto message = input_error_of([&] { check_mesh(inverted); });
  EXPECT_NE(message.find("element 2"), std::string::npos) << message;
  EXPECT_NE(message.find("inverted"), std::string::npos) << message;

  Mesh degenerate = generate_box(spec);
  const GlobalIndex* nodes = degenerate.blocks[0].element_nodes(0);
  for (int d = 0; d < 3; ++d) {  // collapse the top face of element 1 onto its bottom face
    for (int k = 0; k < 4; ++k) {
      degenerate.coordinates[3 * nodes[k + 4] + d] = degenerate.coordinates[3 * nodes[k] + d];
    }
  }
  message = input_error_of([&] { check_mesh(degenerate); });
  EXPECT_NE(message.find("degenerate"), std::string::npos) << message;

  Mesh dangling = generate_box(spec);
  dangling.blocks[0].connectivity[3] = 999;
  message = input_error_of([&] { check_mesh(dangling); });
  EXPECT_NE(message.find("node 1000"), std::string::npos) << message;

  const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  EXPECT_NEAR(hex8_jacobian_quality(cube), 1.0, 1e-14);
}

TEST(DerivedSets, BoxPointAndSideSelections) {
  BoxSpec spec;
  spec.elements = {4, 4, 4};
  Mesh mesh = generate_box(spec);
  DerivedSetSpec corner{"corner", false, "", std::nullopt, std::array<double, 3>{1, 1, 1}, "p"};
  DerivedSetSpec slab{"slab",       false, "", std::array<double, 6>{0, 0.5, 0, 1, 0, 1},
                      std::nullopt, "b"};
  DerivedSetSpec patch{"patch",      true, "zmax", std::array<double, 6>{0, 0.5, 0, 0.5, 1, 1},
                       std::nullopt, "s"};
  add_derived_sets(mesh, {corner, slab, patch}, "deck.xml");
  ASSERT_EQ(mesh.node_set("corner", "", "").nodes.size(), 1u);
  EXPECT_EQ(mesh.node_set("corner", "", "").nodes[0], mesh.n_nodes() - 1);
  EXPECT_EQ(mesh.node_set("slab", "", "").nodes.size(), 3u * 25u);
  EXPECT_EQ(mesh.side_set("patch", "", "").sides.size(), 4u);
  EXPECT_EQ(exterior_faces(mesh).size(), 6u * 16u);

  DerivedSetSpec empty{"empty",      false,
                       "",           std::array<double, 6>{5, 6, 5, 6, 5, 6},
                       std::nullopt, "Mesh/Node sets/empty"};
  auto message = input_error_of([&] { add_derived_sets(mesh, {empty}, "deck.xml"); });
  EXPECT_NE(message.find("selects no nodes"), std::string::npos) << message;
  DerivedSetSpec clash{"xmin",       false,
                       "",           std::array<double, 6>{0, 1, 0, 1, 0, 1},
                       std::nullopt, "Mesh/Node sets/xmin"};
  message = input_error_of([&] { add_derived_sets(mesh, {clash}, "deck.xml"); });
  EXPECT_NE(message.find("already exists"), std::string::npos) << message;
  message = input_error_of([&] { mesh.node_set("xmn", "deck.xml", "Steps/s/Node set"); });
  EXPECT_NE(message.find("did you mean 'xmin'"), std::string::npos) << message;

  // The unit cube's 5 x 5 x 5 nodes (spacing 0.25) within 0.3 of the axis x = y = 0.5 along z:
  // the centre column and its four neighbours at 0.25, 5 nodes high; the diagonal ones at 0.354
  // are outside. A tilted direction of the same axis selects the same nodes.
  DerivedSetSpec core{"core",
                      false,
                      "",
                      std::nullopt,
                      std::nullopt,
                      "c",
                      std::array<double, 7>{0.5, 0.5, 0, 0, 0, 2, 0.3}};
  DerivedSetSpec flipped = core;
  flipped.name = "flipped";
  flipped.cylinder = std::array<double, 7>{0.5, 0.5, 7, 0, 0, -1, 0.3};
  add_derived_sets(mesh, {core, flipped}, "deck.xml");
  EXPECT_EQ(mesh.node_set("core", "", "").nodes.size(), 25u);
  EXPECT_EQ(mesh.node_set("flipped", "", "").nodes, mesh.node_set("core", "", "").nodes);
  for (GlobalIndex node : mesh.node_set("core", "", "").nodes)
    EXPECT_LE(std::hypot(mesh.node(node)[0] - 0.5, mesh.node(node)[1] - 0.5), 0.25 + 1e-12);
  DerivedSetSpec both = core;
  both.name = "both";
  both.point = std::array<double, 3>{0, 0, 0};
  message = input_error_of([&] { add_derived_sets(mesh, {both}, "deck.xml"); });
  EXPECT_NE(message.find("exactly one of 'Box', 'Point' and 'Cylinder'"), std::string::npos)
      << message;
  DerivedSetSpec flat = core;
  flat.name = "flat";
  flat.cylinder = std::array<double, 7>{0.5, 0.5, 0, 0, 0, 0, 0.3};
  message = input_error_of([&] { add_derived_sets(mesh, {flat}, "deck.xml"); });
  EXPECT_NE(message.find("no axis direction"), std::string::npos) << message;
}

// Two hexes sharing a face, written with the Exodus library itself (not railfe's writer).
void write_two_hexes(const std::string& path) {
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(id, 0);
  ex_put_init(id, "two hexes", 3, 12, 2, 1, 1, 1);
  double x[12], y[12], z[12];
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) {
        const int n = i + 3 * j + 6 * k;
        x[n] = i;
        y[n] = j;
        z[n] = k;
      }
    }
  }
  ex_put_coord(id, x, y, z);
  ex_put_block(id, EX_ELEM_BLOCK, 10, "HEX8", 2, 8, 0, 0, 0);
  const int conn[16] = {1, 2, 5, 4, 7, 8, 11, 10, 2, 3, 6, 5, 8, 9, 12, 11};
  ex_put_conn(id, EX_ELEM_BLOCK, 10, conn, nullptr, nullptr);
  const char* block_names[1] = {"rail"};
  ex_put_names(id, EX_ELEM_BLOCK, const_cast<char**>(block_names));
  const int set_nodes[4] = {1, 4, 7, 10};
  ex_put_set_param(id, EX_NODE_SET, 5, 4, 0);
  ex_put_set(id, EX_NODE_SET, 5, set_nodes, nullptr);
  const char* set_names[1] = {"fixed"};
  ex_put_names(id, EX_NODE_SET, const_cast<char**>(set_names));
  const int side_elements[1] = {2}, side_faces[1] = {2};
  ex_put_set_param(id, EX_SIDE_SET, 7, 1, 0);
  ex_put_set(id, EX_SIDE_SET, 7, side_elements, side_faces);
  ex_close(id);
}

TEST(ExodusReader, ReadsBlocksSetsAndNames) {
  const auto dir = scratch("exodus");
  const std::string path = (dir / "two.exo").string();
  write_two_hexes(path);
  const Mesh mesh = read_exodus_mesh(path);
  EXPECT_EQ(mesh.n_nodes(), 12);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "rail");
  EXPECT_EQ(mesh.blocks[0].n_elements(), 2);
  EXPECT_EQ(mesh.blocks[0].connectivity[8], 1);  // Exodus node 2, 0-based
  EXPECT_EQ(mesh.node_set("fixed", "", "").nodes, (std::vector<GlobalIndex>{0, 3, 6, 9}));
  const auto& sides = mesh.side_set("surface_7", "", "").sides;  // unnamed: gets a default name
  ASSERT_EQ(sides.size(), 1u);
  EXPECT_EQ(sides[0].element, 1);
  EXPECT_EQ(sides[0].face, 1);
  EXPECT_NO_THROW(check_mesh(mesh));

  auto message = input_error_of([&] { read_exodus_mesh((dir / "missing.exo").string()); });
  EXPECT_NE(message.find("mesh file not found"), std::string::npos) << message;
  std::ofstream(dir / "garbage.exo") << "not a netCDF file";
  message = input_error_of([&] { read_exodus_mesh((dir / "garbage.exo").string()); });
  EXPECT_NE(message.find("cannot be read as an Exodus II file"), std::string::npos) << message;
}

TEST(GmshReader, ReadsWhatGmshWrites) {
  const auto dir = scratch("gmsh");
  std::ofstream(dir / "box.geo") << R"(
Point(1) = {0, 0, 0, 1};
Point(2) = {2, 0, 0, 1};
Line(1) = {1, 2};
Transfinite Line{1} = 3;
face[] = Extrude {0, 1, 0} { Line{1}; Layers{2}; Recombine; };
body[] = Extrude {0, 0, 1} { Surface{face[1]}; Layers{2}; Recombine; };
Physical Volume("solid") = {body[1]};
Physical Surface("bottom") = {face[1]};
Physical Surface("top") = {body[0]};
)";
  const std::string command = "gmsh -3 -format msh41 -o " + (dir / "box.msh").string() + " " +
                              (dir / "box.geo").string() + " > " + (dir / "gmsh.log").string() +
                              " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << "gmsh failed; see " << dir / "gmsh.log";
  const Mesh mesh = read_gmsh_mesh((dir / "box.msh").string());
  EXPECT_EQ(mesh.n_nodes(), 27);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "solid");
  EXPECT_EQ(mesh.blocks[0].n_elements(), 8);
  EXPECT_EQ(mesh.side_set("bottom", "", "").sides.size(), 4u);
  EXPECT_EQ(mesh.node_set("bottom", "", "").nodes.size(), 9u);
  EXPECT_EQ(mesh.side_set("top", "", "").sides.size(), 4u);
  for (GlobalIndex node : mesh.node_set("top", "", "").nodes) {
    EXPECT_NEAR(mesh.coordinates[3 * node + 2], 1.0, 1e-12);
  }
  EXPECT_NO_THROW(check_mesh(mesh));
}

TEST(GmshReader, ReadsALineModelAsBeams) {
  const auto dir = scratch("gmsh_lines");
  std::ofstream(dir / "frame.geo") << R"(
Point(1) = {0, 0, 0}; Point(2) = {0, 0, 3}; Point(3) = {4, 0, 3}; Point(4) = {4, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Transfinite Curve{1, 2, 3} = 11;
Physical Curve("columns") = {1, 3};
Physical Curve("girder") = {2};
Physical Point("feet") = {1, 4};
)";
  const std::string command = "gmsh -1 -format msh41 -o " + (dir / "frame.msh").string() + " " +
                              (dir / "frame.geo").string() + " > " + (dir / "gmsh.log").string() +
                              " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << "gmsh failed; see " << dir / "gmsh.log";
  const Mesh mesh = read_gmsh_mesh((dir / "frame.msh").string());
  EXPECT_EQ(mesh.n_nodes(), 31);  // the corners shared by column and girder
  ASSERT_EQ(mesh.blocks.size(), 2u);
  for (const ElementBlock& block : mesh.blocks) {
    EXPECT_EQ(block.type, ElementType::beam2);
    EXPECT_EQ(block.n_elements(), block.name == "columns" ? 20 : 10) << block.name;
  }
  EXPECT_EQ(mesh.node_set("feet", "", "").nodes.size(), 2u);  // points stay node sets
  EXPECT_EQ(mesh.node_set("girder", "", "").nodes.size(), 11u);
  EXPECT_NO_THROW(check_mesh(mesh));
  // A curve in two physical curves would give its elements twice.
  std::ofstream(dir / "twice.geo") << R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Line(1) = {1, 2};
Physical Curve("a") = {1};
Physical Curve("b") = {1};
)";
  ASSERT_EQ(std::system(("gmsh -1 -format msh41 -o " + (dir / "twice.msh").string() + " " +
                         (dir / "twice.geo").string() + " > /dev/null 2>&1")
                            .c_str()),
            0);
  const std::string message = input_error_of([&] { read_gmsh_mesh((dir / "twice.msh").string()); });
  EXPECT_NE(message.find("curve 1 lies in two physical curves"), std::string::npos) << message;
}

TEST(GmshReader, RefusesWhatItCannotUse) {
  const auto dir = scratch("gmsh_bad");
  std::ofstream(dir / "old.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  auto message = input_error_of([&] { read_gmsh_mesh((dir / "old.msh").string()); });
  EXPECT_NE(message.find("version 2.2 is not supported"), std::string::npos) << message;
  EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  std::ofstream(dir / "tet.msh")
      << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
         "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";
  message = input_error_of([&] { read_gmsh_mesh((dir / "tet.msh").string()); });
  EXPECT_NE(message.find("tetrahedron"), std::string::npos) << message;
  message = input_error_of([&] { read_gmsh_mesh((dir / "none.msh").string()); });
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(Partition, EveryElementAndNodeHasOneOwner) {
  const Communicator comm;
  BoxSpec spec;
  spec.elements = {8, 6, 4};
  const Mesh mesh = generate_box(spec);
  for (PartitionMethod method :
       {PartitionMethod::multijagged, PartitionMethod::rcb, PartitionMethod::block}) {
    const MeshPartition partition(mesh, comm, method);
    const long long elements = comm.sum(static_cast<long long>(partition.n_local_elements()));
    EXPECT_EQ(elements, mesh.n_elements());
    const long long owned = comm.sum(static_cast<long long>(partition.n_owned_nodes()));
    EXPECT_EQ(owned, mesh.n_nodes());
    EXPECT_EQ(partition.n_active_nodes(), mesh.n_nodes());
    // Balanced within a few percent.
    const double share = static_cast<double>(partition.n_local_elements()) / mesh.n_elements();
    EXPECT_NEAR(share, 1.0 / comm.n_ranks(), 0.05);
    // Local numbering: owned nodes first, and the global-to-local map agrees.
    for (LocalIndex n = 0; n < partition.n_local_nodes(); ++n) {
      EXPECT_EQ(partition.local_node(partition.global_node(n)), n);
      EXPECT_EQ(partition.node_ranks()[partition.global_node(n)] == comm.rank(),
                n < partition.n_owned_nodes());
    }
  }
}

}  // namespace
}  // namespace railfe
