#include "physics/parts/line_mesh.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <cmath>

#include "framework/base/error.hpp"

namespace railfe {

ParameterSpec line_parameters() {
  ParameterSpec line(
      "Beam2 (or spring2) elements along straight segments through Points: node sets 'start', "
      "'end' (first "
      "and last node), 'points' (every given point) and 'all'.");
  line.required_real_array("Points",
                           "x, y, z of each point in turn (at least two points): "
                           "{x1, y1, z1, x2, y2, z2, ...}.",
                           "m");
  line.integer_array("Elements", {},
                     "Elements on each segment: one number for every segment, or one per "
                     "segment (required).",
                     0, Range::at_least(1));
  line.text("Block name", "beam", "Name of the line's element block.");
  line.choice("Element type", "beam2",
              {{"beam2", "two-node beams"}, {"spring2", "two-node spring-dampers"}},
              "What the line's elements are (their Sections entry says what they are made of).");
  line.text("End block", "",
            "If given: the name of a one-node (point_mass) block holding the last node, for a "
            "point mass or a spring to the ground there.");
  return line;
}

LineSpec line_spec(const Teuchos::ParameterList& sublist, const Deck& deck) {
  LineSpec spec;
  const auto& points = sublist.get<Teuchos::Array<double>>("Points");
  const auto& elements = sublist.get<Teuchos::Array<int>>("Elements");
  spec.points.assign(points.begin(), points.end());
  if (points.size() % 3 != 0 || points.size() < 6) {
    throw_input_error(deck.source, "Mesh/Line/Points",
                      "has " + std::to_string(points.size()) + " numbers",
                      "x, y, z of at least two points (a multiple of three numbers)");
  }
  const std::size_t n_segments = points.size() / 3 - 1;
  if (elements.empty()) {
    throw_input_error(deck.source, "Mesh/Line/Elements", "missing",
                      "the number of elements on each segment, e.g. {20}");
  }
  if (elements.size() != 1 && static_cast<std::size_t>(elements.size()) != n_segments) {
    throw_input_error(deck.source, "Mesh/Line/Elements",
                      "has " + std::to_string(elements.size()) + " entries for " +
                          std::to_string(n_segments) + " segments",
                      "one number, or one per segment");
  }
  for (std::size_t s = 0; s < n_segments; ++s) {
    spec.elements.push_back(elements[elements.size() == 1 ? 0 : s]);
    double length2 = 0;
    for (int d = 0; d < 3; ++d)
      length2 += std::pow(points[3 * s + 3 + d] - points[3 * s + d], 2);
    if (!(length2 > 0)) {
      throw_input_error(
          deck.source, "Mesh/Line/Points",
          "points " + std::to_string(s + 1) + " and " + std::to_string(s + 2) + " coincide",
          "distinct consecutive points");
    }
  }
  const double total =
      1.0 * spec.elements.size() * *std::max_element(elements.begin(), elements.end());
  if (total > 1e8) {
    throw_input_error(deck.source, "Mesh/Line/Elements",
                      "asks for about " + std::to_string(total) + " elements",
                      "at most 1e8 elements");
  }
  spec.block_name = sublist.get<std::string>("Block name");
  spec.type = sublist.get<std::string>("Element type") == "spring2" ? ElementType::spring2
                                                                    : ElementType::beam2;
  spec.end_block = sublist.get<std::string>("End block");
  if (spec.end_block == spec.block_name) {
    throw_input_error(deck.source, "Mesh/Line/End block",
                      "'" + spec.end_block + "' is also the Block name",
                      "a name of its own for the one-node block");
  }
  return spec;
}

Mesh build_line_mesh(const LineSpec& spec, const std::string& source) {
  Mesh mesh;
  mesh.source = source;
  ElementBlock block;
  block.name = spec.block_name;
  block.id = 1;
  block.type = spec.type;
  NodeSet points{"points", 3, {}};
  const auto add_node = [&](const double* a, const double* b, double t) {
    for (int d = 0; d < 3; ++d)
      mesh.coordinates.push_back(a[d] + t * (b[d] - a[d]));
    return mesh.n_nodes() - 1;
  };
  add_node(&spec.points[0], &spec.points[0], 0);
  points.nodes.push_back(0);
  for (std::size_t s = 0; s < spec.elements.size(); ++s) {
    const double* a = &spec.points[3 * s];
    const double* b = &spec.points[3 * s + 3];
    const int n = spec.elements[s];
    for (int e = 1; e <= n; ++e) {
      GlobalIndex nodes[2] = {mesh.n_nodes() - 1, 0};
      nodes[1] = add_node(a, b, static_cast<double>(e) / n);
      block.add_element(nodes, 2);
    }
    points.nodes.push_back(mesh.n_nodes() - 1);
  }
  mesh.blocks.push_back(block);
  if (!spec.end_block.empty()) {
    ElementBlock end;
    end.name = spec.end_block;
    end.id = 2;
    end.type = ElementType::point_mass;
    const GlobalIndex last = mesh.n_nodes() - 1;
    end.add_element(&last, 1);
    mesh.blocks.push_back(end);
  }
  mesh.number_blocks();
  NodeSet all{"all", 4, {}};
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node)
    all.nodes.push_back(node);
  mesh.node_sets.push_back({"start", 1, {0}});
  mesh.node_sets.push_back({"end", 2, {mesh.n_nodes() - 1}});
  mesh.node_sets.push_back(points);
  mesh.node_sets.push_back(all);
  return mesh;
}

MeshGeneratorDescriptor line_mesh_generator() {
  return {"line", "generate beam2 elements along straight segments through given points",
          line_parameters, [](const Teuchos::ParameterList& sublist, const Deck& deck) {
            return build_line_mesh(line_spec(sublist, deck), deck.source + ": Mesh/Line");
          }};
}

}  // namespace railfe
