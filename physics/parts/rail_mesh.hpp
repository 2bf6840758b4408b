#pragma once
/// \file
/// The rail mesh generator (Mesh/Type rail, sublist Mesh/Rail): a rail of a standard section
/// (contact/geometry/rail_drawing.hpp: 54E1, 60E1 with their drawings' exact arcs) extruded
/// along x, its elements graded along the track from a fine solution zone (where the wheel's
/// contact patch passes) to coarse elements away from it, and across the section from the
/// running surface to the web and foot.
///
/// Placement: x along the track from 0 to Length, y lateral with the section's axis of symmetry
/// at y = 0, z up with the top of the crown at z = 0; upright (the 1:40 inclination and the
/// rail's place in the track are the part's Rotation and Translation).

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

/// What the Rail sublist describes (metres).
struct RailDimensions {
  std::string profile = "54E1";        ///< the standard section (rail_drawing_names())
  double length = 0;                   ///< along x
  std::vector<double> solution_zone;   ///< {start, end} along x, or empty for none
  double zone_element_size = 0.001;    ///< along x inside the solution zone
  double element_size = 0.02;          ///< along x far from the zone
  double growth = 1.25;                ///< ratio of neighbouring lengths along x between the two
  double head_element_size = 0.003;    ///< the section's elements at the running surface
  double section_element_size = 0.01;  ///< the section's elements in the web and foot
};

/// Valid parameters of the Rail sublist.
ParameterSpec rail_parameters();

/// Reads a validated Rail sublist; throws InputError naming \p deck and "Mesh/Rail/<parameter>"
/// for values that contradict each other (a zone outside the rail, a zone size without a zone,
/// a head coarser than the section).
RailDimensions rail_dimensions(const Teuchos::ParameterList& sublist, const Deck& deck);

/// The stations along x: uniform at the zone size over the solution zone, lengths growing by
/// the growth ratio away from it up to the element size, each side's lengths scaled so the
/// last station falls on the rail's end (uniform at the element size without a zone).
std::vector<double> rail_stations(const RailDimensions& dimensions);

/// The Gmsh script of the section: block "rail", node sets "running_surface" (the crown and
/// corner arcs, both sides) and "foot_bottom", sizes graded from the running surface.
std::string rail_geo_script(const RailDimensions& dimensions);

/// The rail mesh (Gmsh runs in a private temporary directory). Throws InputError naming
/// \p source for sizes that would exceed about 1e8 elements, RunError when gmsh is missing.
Mesh build_rail_mesh(const RailDimensions& dimensions, const std::string& source);

/// The registry entry of Mesh/Type rail.
MeshGeneratorDescriptor rail_mesh_generator();

}  // namespace railfe
