// Structural assembly at 1 and 2 ranks: the stiffness, mass and damping of beams, spring2
// elements, springs to the ground and point masses equal the dense sum of the element matrices
// over the whole mesh; gravity loads sum to the model's weight, a point mass off its node adding
// the moment of its weight.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>
#include <map>

#include "framework/deck/deck.hpp"
#include "framework/deck/validation.hpp"
#include "physics/common/structural_assembly.hpp"
#include "physics/elements/point_mass.hpp"
#include "physics/materials/elastic_material.hpp"
#include "physics/parts/line_mesh.hpp"

namespace railfe {
namespace {

// A bent beam of 6 elements, a spring2 from its end to a new node carrying a point mass, and a
// spring from that node to the ground.
Mesh model() {
  LineSpec spec;
  spec.points = {0, 0, 0, 3, 0, 0, 3, 2, 1};
  spec.elements = {4, 2};
  Mesh mesh = build_line_mesh(spec, "test");
  const GlobalIndex end = mesh.n_nodes() - 1;
  for (double x : {3.0, 2.5, 1.0})
    mesh.coordinates.push_back(x);
  const GlobalIndex extra = end + 1;
  const auto add = [&](const std::string& name, ElementType type, std::vector<GlobalIndex> nodes) {
    ElementBlock block;
    block.name = name;
    block.id = static_cast<int>(mesh.blocks.size()) + 1;
    block.type = type;
    block.add_element(nodes.data(), static_cast<int>(nodes.size()));
    mesh.blocks.push_back(block);
  };
  add("spring", ElementType::spring2, {end, extra});
  add("mass", ElementType::point_mass, {extra});
  add("ground", ElementType::point_mass, {extra});
  mesh.number_blocks();
  return mesh;
}

const char* const kDeck = R"x(<ParameterList name="railfe">
  <ParameterList name="Materials"><ParameterList name="steel">
    <Parameter name="Young's modulus" type="double" value="2e11"/>
    <Parameter name="Poisson's ratio" type="double" value="0.3"/>
    <Parameter name="Density" type="double" value="7800"/></ParameterList></ParameterList>
  <ParameterList name="Sections">
    <ParameterList name="girder">
      <Parameter name="Blocks" type="Array(string)" value="{beam}"/>
      <Parameter name="Element" type="string" value="beam"/>
      <Parameter name="Material" type="string" value="steel"/>
      <Parameter name="Shape" type="string" value="tube"/>
      <Parameter name="Diameter" type="double" value="0.2"/>
      <Parameter name="Wall thickness" type="double" value="0.01"/>
      <Parameter name="Orientation" type="Array(double)" value="{0, 0.3, 1}"/></ParameterList>
    <ParameterList name="mount">
      <Parameter name="Blocks" type="Array(string)" value="{spring}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{1e6, 2e6, 3e6, 1e4, 2e4, 3e4}"/>
      <Parameter name="Damping" type="Array(double)" value="{10, 20, 30, 1, 2, 3}"/>
      <Parameter name="Axes" type="Array(double)" value="{1, 1, 0, 0, 0, 1}"/></ParameterList>
    <ParameterList name="body">
      <Parameter name="Blocks" type="Array(string)" value="{mass}"/>
      <Parameter name="Element" type="string" value="point mass"/>
      <Parameter name="Mass" type="double" value="50"/>
      <Parameter name="Inertia" type="Array(double)" value="{3, 4, 5, 0.5, 0.2, 0.1}"/>
      <Parameter name="Offset" type="Array(double)" value="{0.1, 0, 0.5}"/></ParameterList>
    <ParameterList name="support">
      <Parameter name="Blocks" type="Array(string)" value="{ground}"/>
      <Parameter name="Element" type="string" value="spring-damper"/>
      <Parameter name="Stiffness" type="Array(double)" value="{5e5, 5e5, 7e5, 0, 0, 1e3}"/>
      <Parameter name="Damping" type="Array(double)" value="{100, 0, 0, 0, 0, 0}"/></ParameterList>
  </ParameterList></ParameterList>)x";

struct Fixture {
  Communicator comm;
  Mesh mesh = model();
  Deck deck = parse_deck(kDeck, "deck.xml", ".");
  std::unique_ptr<SectionTable> sections;
  std::unique_ptr<MeshPartition> partition;
  std::unique_ptr<DofMap> dofs;

  Fixture() {
    auto& materials = deck.parameters->sublist("Materials");
    auto& list = deck.parameters->sublist("Sections");
    validate_and_complete(materials, *materials_parameters().list(), deck.source, "Materials");
    validate_and_complete(list, *sections_parameters().list(), deck.source, "Sections");
    sections = std::make_unique<SectionTable>(list, &materials, mesh, deck.source);
    partition = std::make_unique<MeshPartition>(mesh, comm, PartitionMethod::multijagged);
    dofs = std::make_unique<DofMap>(*partition, 6);
  }

  // Dense reference: each element's matrix of \p kind (0 K, 1 M, 2 C) summed by global DOF.
  std::map<GlobalIndex, std::map<GlobalIndex, double>> reference(int kind) const {
    std::map<GlobalIndex, std::map<GlobalIndex, double>> sum;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      const ElementBlock& block = mesh.blocks[b];
      const StructuralSection& section = sections->of_block(static_cast<int>(b));
      for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
        const GlobalIndex* nodes = block.element_nodes(e);
        const int n = 6 * block.n_element_nodes(e);
        Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(n, n);
        if (section.kind == StructuralKind::beam && kind < 2) {
          const BeamElement beam = make_beam(&mesh.coordinates[3 * nodes[0]],
                                             &mesh.coordinates[3 * nodes[1]], section.beam);
          matrix = kind == 0 ? beam.stiffness() : beam.mass(BeamMass::consistent);
        } else if (section.kind == StructuralKind::spring && kind != 1) {
          const Matrix6 one = spring_block(
              kind == 0 ? section.spring.stiffness : section.spring.damping, section.spring.axes);
          matrix = n == 6 ? Eigen::MatrixXd(one) : Eigen::MatrixXd(two_node_matrix(one));
        } else if (section.kind == StructuralKind::point_mass && kind == 1) {
          matrix =
              point_mass_matrix(section.point.mass, section.point.inertia, section.point.offset);
        }
        for (int r = 0; r < n; ++r)
          for (int c = 0; c < n; ++c)
            sum[6 * nodes[r / 6] + r % 6][6 * nodes[c / 6] + c % 6] += matrix(r, c);
      }
    }
    return sum;
  }
};

// Compares every owned row of \p A with \p reference (entries missing there are zero).
void expect_rows(const TpetraMatrix& A,
                 const std::map<GlobalIndex, std::map<GlobalIndex, double>>& reference) {
  const auto row_map = A.getRowMap();
  double scale = 0;
  for (const auto& [row, entries] : reference)
    for (const auto& [column, value] : entries)
      scale = std::max(scale, std::abs(value));
  for (std::size_t i = 0; i < row_map->getNodeNumElements(); ++i) {
    const GlobalIndex row = row_map->getGlobalElement(static_cast<LocalIndex>(i));
    std::size_t n = A.getNumEntriesInGlobalRow(row);
    Teuchos::Array<GlobalIndex> columns(n);
    Teuchos::Array<double> values(n);
    A.getGlobalRowCopy(row, columns(), values(), n);
    double checked = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const auto found = reference.count(row) ? reference.at(row).find(columns[k])
                                              : std::map<GlobalIndex, double>::const_iterator();
      const double want =
          reference.count(row) && found != reference.at(row).end() ? found->second : 0.0;
      EXPECT_NEAR(values[k], want, 1e-13 * scale) << "row " << row << " column " << columns[k];
      checked += std::abs(want);
    }
    double expected = 0;
    if (reference.count(row))
      for (const auto& [column, value] : reference.at(row))
        expected += std::abs(value);
    EXPECT_NEAR(checked, expected, 1e-12 * scale) << "row " << row << ": entries missing";
  }
}

TEST(StructuralAssembly, MatricesEqualTheDenseSumOfElementMatrices) {
  Fixture f;
  FeMatrix K(*f.dofs), M(*f.dofs), C(*f.dofs);
  assemble_structural_stiffness(K, *f.sections);
  assemble_structural_stiffness(K, *f.sections);  // reassembly starts from zero
  assemble_structural_mass(M, *f.sections);
  assemble_structural_damping(C, *f.sections);
  expect_rows(*K.matrix(), f.reference(0));
  expect_rows(*M.matrix(), f.reference(1));
  expect_rows(*C.matrix(), f.reference(2));
}

TEST(StructuralAssembly, GravityLoadsSumToTheWeight) {
  Fixture f;
  SolidConditions conditions;
  conditions.gravity = {0, 0, -9.81};
  TpetraVector forces(f.dofs->owned_map());
  assemble_structural_loads(conditions, *f.sections, *f.dofs, forces);
  double fz = 0, my = 0;
  const auto data = forces.getData();
  for (LocalIndex node = 0; node < f.partition->n_owned_nodes(); ++node) {
    fz += data[f.dofs->local_dof(node, 2)];
    my += data[f.dofs->local_dof(node, 4)];
  }
  // The tube's mass rho A L over the two segments, and the point mass.
  const BeamProperties& beam = f.sections->of_block(0).beam;
  const double length = 3 + std::sqrt(5.0);
  const double weight = (7800 * beam.section.area * length + 50) * 9.81;
  EXPECT_NEAR(f.comm.sum(fz), -weight, 1e-12 * weight);
  // The beams' end moments cancel element by element; the point mass's weight acts at its
  // centre, 0.1 m along x from its node: r × m g = (0, 0.1 × 50 × 9.81, 0).
  EXPECT_NEAR(f.comm.sum(my), 0.1 * 50 * 9.81, 1e-12 * weight);
}

}  // namespace
}  // namespace railfe
