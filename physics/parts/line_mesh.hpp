#pragma once
/// \file
/// The line mesh generator (Mesh/Type line, sublist Mesh/Line): beam2 (or spring2) elements
/// along straight segments through given points, for beams, frames, bridges and spring chains,
/// optionally with a one-node block at the last node (a point mass). Node sets "start" and "end"
/// hold the first and last node, "points" every given point, "all" every node; other stations
/// (a midspan) come from the Mesh's Node sets by Point.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

/// What the Line sublist describes.
struct LineSpec {
  std::vector<double> points;             ///< x, y, z of each point (m), at least two points
  std::vector<int> elements;              ///< elements per segment (one per segment)
  std::string block_name = "beam";        ///< the line's block
  ElementType type = ElementType::beam2;  ///< beam2 or spring2
  std::string end_block;                  ///< a one-node block at the last node ("" = none)
};

/// Valid parameters of the Line sublist.
ParameterSpec line_parameters();

/// Reads a validated Line sublist; throws InputError naming \p deck and "Mesh/Line/<parameter>"
/// for a point count that is not a multiple of three or below two points, an Elements count
/// that matches neither one nor every segment, or two consecutive points that coincide.
LineSpec line_spec(const Teuchos::ParameterList& sublist, const Deck& deck);

/// The mesh: nodes equally spaced on each segment, shared at the points between segments.
Mesh build_line_mesh(const LineSpec& spec, const std::string& source);

/// The registry entry of Mesh/Type line.
MeshGeneratorDescriptor line_mesh_generator();

}  // namespace railfe
