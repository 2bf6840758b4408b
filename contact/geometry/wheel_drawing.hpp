#pragma once
/// \file
/// Wheel profiles built from their drawings: the tread and flange as lines and circular arcs
/// (drawing_chain.hpp), in a wheel profile file's axes: y from the tape circle (the running
/// point) towards the flange, z radially outwards from the tape circle, metres. A drawing of
/// another family is a chain of its own; a wheel of the conic-and-arc family (a cone through the
/// tape circle, a tread arc, a flange root, a straight flange face, a flange tip) is its
/// dimensions in ConicArcWheel.

#include <string>
#include <vector>

#include "contact/geometry/drawing_chain.hpp"

namespace railfe {

/// A wheel profile as drawn.
struct WheelOutline {
  std::string name;  ///< the drawing's designation, e.g. "Shinkansen860"
  /// From the field side of the rim to the flange back face, in that order.
  std::vector<OutlineSegment> segments;
  double nominal_radius = 0;  ///< radius of the tape circle (y = 0), m
  double flange_back = 0;     ///< y of the flange back face, m
};

/// The dimensions of a conic-and-arc wheel (millimetres and degrees, as drawings give them).
struct ConicArcWheel {
  double diameter = 860;         ///< at the tape circle
  double rim_width = 125;        ///< from the rim's field side to the flange back face
  double flange_back = 65;       ///< from the tape circle to the flange back face
  double cone_slope = 40;        ///< the tread's cone: 1 in cone_slope, rising to the flange
  double arc_start = 0;          ///< y where the tread arc takes over from the cone
  double tread_radius = 1000;    ///< the tread arc, concave, touching the cone at arc_start
  double root_radius = 15;       ///< the flange root: a fillet from the tread arc to the face
  double flange_angle = 70;      ///< the straight flange face against the axle, degrees
  double flange_height = 30;     ///< the flange tip above the tape circle
  double flange_thickness = 30;  ///< from the back face to the flange face ...
  double thickness_height = 15;  ///< ... this far above the tape circle
  double back_depth = 5;         ///< how far the back face is drawn below the tip arc's end
};

/// The profile of a conic-and-arc wheel: the cone from the rim's field side, the tread arc, the
/// root fillet, the flange face, the tip arc (touching the face and the back face, its radius
/// set by the flange height) and the back face. Throws std::invalid_argument for dimensions
/// that do not make a flange.
WheelOutline conic_arc_wheel(const std::string& name, const ConicArcWheel& dimensions);

/// The names of the wheel drawings railfe knows ("Shinkansen860").
std::vector<std::string> wheel_drawing_names();

/// The profile of the named drawing. Throws std::invalid_argument for an unknown name (callers
/// check names against wheel_drawing_names() and report input errors themselves).
WheelOutline wheel_outline(const std::string& name);

}  // namespace railfe
