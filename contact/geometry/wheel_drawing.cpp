#include "contact/geometry/wheel_drawing.hpp"

#include <cmath>
#include <stdexcept>

namespace railfe {

using namespace drawing_math;

WheelOutline conic_arc_wheel(const std::string& name, const ConicArcWheel& d) {
  const double angle = d.flange_angle * M_PI / 180;
  const SectionPoint face_direction{std::cos(angle), std::sin(angle)};
  const SectionPoint on_face{d.flange_back - d.flange_thickness, d.thickness_height};
  // The tip arc touches the back face with its top at the flange height, so its centre is
  // (back - r, height - r); it touches the face too, so that centre lies r to the face's right:
  // cross(corner - (r, r) - on_face, face) = r.
  const SectionPoint corner{d.flange_back - on_face[0], d.flange_height - on_face[1]};
  const double tip_radius = cross(corner, face_direction) / (1 + cross({1, 1}, face_direction));
  if (!(tip_radius > 0) || d.flange_height <= d.thickness_height)
    throw std::invalid_argument("railfe: wheel drawing " + name + ": no flange tip fits");
  const DrawingCurve cone = drawing_line({0, 0}, {d.cone_slope, 1});
  const DrawingCurve back = drawing_line({d.flange_back, 0}, {0, -1});
  const std::vector<DrawingCurve> curves = {
      cone,
      drawing_circle_touching(cone, {d.arc_start, d.arc_start / d.cone_slope}, d.tread_radius, 1),
      drawing_line(on_face, face_direction), back};
  const std::vector<DrawingJoin> joins = {kTangentJoin, {d.root_radius}, {tip_radius}};
  const double field = d.flange_back - d.rim_width;
  const SectionPoint end{d.flange_back, d.flange_height - tip_radius - d.back_depth};
  WheelOutline wheel;
  wheel.name = name;
  wheel.segments = drawing_chain(curves, joins, {field, field / d.cone_slope}, end);
  for (auto& s : wheel.segments) {
    s.start = 1e-3 * s.start;
    s.end = 1e-3 * s.end;
    s.centre = 1e-3 * s.centre;
    s.radius *= 1e-3;
  }
  wheel.nominal_radius = d.diameter / 2 * 1e-3;
  wheel.flange_back = d.flange_back * 1e-3;
  return wheel;
}

std::vector<std::string> wheel_drawing_names() {
  return {"Shinkansen860"};
}

WheelOutline wheel_outline(const std::string& name) {
  if (name == "Shinkansen860") {
    // An 860 mm Shinkansen-type conic-and-arc wheel. Sourced: the 1:40 cone of the Shinkansen
    // conical tread and the R1000 arc of its arc tread (Japanese Wikipedia, "輪軸 (鉄道車両)",
    // 踏面形状の種類), the 70° flange and 860 mm (issue 19), the tape circle 65 mm from the
    // flange back (the technical regulation's table of wheelset dimensions: wheel-centre line to
    // tread 745 mm with back-to-back 1360 mm on Shinkansen, 560 mm with 990 mm on 1067 mm
    // gauge), rim width and flange height within its 120-135 mm and 25-35 mm. Chosen, as no
    // public drawing was found: the cone up to the tape circle and the arc from there, rim
    // 125 mm, flange height 30 mm, root R15 (wider than the JIS 60 kg rail's R13 gauge corner),
    // flange 30 mm thick 15 mm above the tape circle (tip radius then 14.4 mm).
    return conic_arc_wheel(name, ConicArcWheel{});
  }
  throw std::invalid_argument("railfe: unknown wheel drawing '" + name + "'");
}

}  // namespace railfe
