#pragma once
/// \file
/// Rail cross-sections built from their standard drawings (EN 13674-1, JIS E 1101): the outline
/// as the drawing gives it, circular arcs and straight lines joined tangentially or by fillets
/// (drawing_chain.hpp), so a generated rail has the drawing's exact crown radii rather than a
/// digitized approximation.
/// Coordinates (u, v) in metres: u lateral (the section is symmetric about u = 0), v vertical
/// with v = 0 at the top of the crown and the foot at v = -height.
///
/// Each drawing is a list of curves for the left half (u <= 0), from the crown top down the
/// head, web and foot to the middle of the foot, each joined to the next either at the point
/// where they touch (the drawing makes them tangent) or by a fillet; the right half is its
/// mirror image.

#include <string>
#include <vector>

#include "contact/geometry/drawing_chain.hpp"

namespace railfe {

/// A closed outline, counter-clockwise (the material on the left of the direction of travel).
struct RailOutline {
  std::string name;  ///< the drawing's designation, e.g. "54E1"
  std::vector<OutlineSegment>
      segments;  ///< consecutive pieces; the last ends where the first starts
  /// The pieces of the running surface: the crown arcs and the head's corner arcs, both sides.
  std::vector<std::size_t> running_surface;
};

/// The names of the drawings railfe knows ("54E1", "60E1", "JIS60").
std::vector<std::string> rail_drawing_names();

/// The outline of the named drawing. Throws std::invalid_argument for an unknown name (callers
/// check names against rail_drawing_names() and report input errors themselves).
RailOutline rail_outline(const std::string& name);

/// The running surface and the head's sides of \p outline, from the side at u > 0 over the crown
/// to the side at u < 0: the part of the rail a wheel can touch.
std::vector<OutlineSegment> rail_head(const RailOutline& outline);

/// Points along the outline no farther apart than \p spacing (every segment's ends included,
/// arcs subdivided evenly), in order, without repeating the first point at the end.
std::vector<SectionPoint> sample_outline(const RailOutline& outline, double spacing);

/// Area and second moments of the region an outline encloses, from the exact segments (lines
/// and arcs integrated in closed form).
struct SectionProperties {
  double area = 0;              ///< m²
  SectionPoint centroid{0, 0};  ///< m
  double inertia_horizontal =
      0;  ///< ∫(v − v̄)² dA, about the horizontal axis (vertical bending), m⁴
  double inertia_vertical = 0;  ///< ∫(u − ū)² dA, about the vertical axis (lateral bending), m⁴
};

/// Section properties of \p outline (Green's theorem over each line and arc).
SectionProperties section_properties(const RailOutline& outline);

/// Shortest distance from \p point to the outline (to its exact lines and arcs), metres.
double distance_to_outline(const RailOutline& outline, const SectionPoint& point);

/// Width of the outline along the horizontal line v (the largest minus the smallest u where the
/// outline crosses it), from a fine sampling; 0 when the line misses the outline.
double outline_width_at(const RailOutline& outline, double v);

}  // namespace railfe
