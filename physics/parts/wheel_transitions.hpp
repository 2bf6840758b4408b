#pragma once
/// \file
/// Transitions of a wheel's slices (Mesh/Wheel/Transition radii). A Refined arc's slices, 1 mm
/// long at the running circle, would otherwise run down through web, hub and axle, ever
/// thinner: about 0.07 mm at an axle's bore, where they set the explicit step (or take on
/// hundreds of kilograms of mass scaling). Below each transition radius the slices coarsen
/// threefold. The section is cut at r and r − width across the web or the hub; Gmsh meshes the
/// parts between these strips with equal points on each strip's two cuts, each strip is one
/// row of quads made here, and revolve() turns it into its 3-to-1 template
/// (framework/mesh/revolve.hpp).

#include <string>
#include <vector>

#include "framework/mesh/revolve.hpp"
#include "physics/parts/wheel_mesh.hpp"

namespace railfe {

/// The strip's radial width for \p dimensions: four Arc element sizes, so that the template's
/// pieces are no thinner radially than the finer slices are long.
double transition_width(const WheelDimensions& dimensions);

/// Inserts into \p section's outline the points where each transition's two cuts (at r and
/// r − \p width, for r in \p radii) cross it, and returns the cuts, outermost first, each
/// divided into segments of about \p spacing / 2 (the final quads' size). Throws
/// InputError naming \p source and Mesh/Wheel/Transition radii unless every cut crosses the
/// outline exactly twice, on its straight lines (not the tread, not through a corner), the
/// strips nested one inside the other above the bore.
std::vector<WheelCut> cut_wheel_section(WheelSection& section, const std::vector<double>& radii,
                                        double width, double spacing, const std::string& source);

/// Whether outline segment \p s (from wheel[s] to the next point) is a side of a strip, which
/// Gmsh does not mesh.
bool strip_side(const std::vector<WheelCut>& cuts, std::size_t s);

/// The tag of the Gmsh line along outline segment \p s of the rim, web and hub (s from
/// tread_points − 1: the tread itself is splines 1 and 2).
int outline_line_tag(const WheelSection& section, std::size_t s);

/// The Gmsh lines of the cuts (tags from \p first_tag), their equal point counts per strip, and
/// the plane surfaces of the parts between the strips, all in Physical Surface "wheel" (the
/// outermost is surface 1).
std::string cut_surfaces_geo(const WheelSection& section, const std::vector<WheelCut>& cuts,
                             int first_tag);

/// Adds each strip's row of quads (block "wheel") to the Gmsh section and returns the level of
/// every section node: the number of strips above it. Throws RunError when Gmsh did not put
/// the same number of points on a strip's two cuts.
std::vector<int> add_transition_strips(SectionMesh& mesh, const std::vector<WheelCut>& cuts,
                                       const WheelSection& section);

/// The angle indices of each coarser level (revolve()'s coarser_slices): three slices of the
/// level above merged wherever together they span no more than that level's \p largest
/// (radians), the others kept.
std::vector<std::vector<std::size_t>> coarser_wheel_slices(const std::vector<double>& angles,
                                                           const std::vector<double>& largest);

/// The largest merged slice of each level (radians): one no longer at its transition radius
/// than the section's Element size, and no coarser than the wheel's slices away from the arcs.
std::vector<double> largest_wheel_slices(const WheelDimensions& dimensions);

}  // namespace railfe
