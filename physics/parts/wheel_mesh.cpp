#include "physics/parts/wheel_mesh.hpp"
#include "framework/base/constants.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "contact/geometry/profile_file.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/gmsh_section.hpp"
#include "framework/mesh/grading.hpp"
#include "framework/mesh/revolve.hpp"
#include "physics/parts/wheel_transitions.hpp"

namespace railfe {

namespace {

using Point = std::array<double, 2>;  // (r, a)

[[noreturn]] void refuse(const std::string& source, const std::string& parameter,
                         const std::string& problem, const std::string& allowed = "") {
  throw_input_error(source, "Mesh/Wheel/" + parameter, problem, allowed);
}

std::string mm(double metres) {
  std::ostringstream text;
  text << std::setprecision(4) << metres * 1000 << " mm";
  return text.str();
}

// The profile as (r, a) with the flange on +a and its y = 0 at the nominal radius.
std::vector<Point> tread_of(const WheelDimensions& d, const std::string& source) {
  const ProfileFile profile = read_profile_file(d.profile_file);
  if (profile.type != ProfileType::wheel)
    refuse(source, "Profile file", "'" + d.profile_file + "' is a rail profile", "a wheel profile");
  auto points = profile.points;
  // The flange is the profile's highest part; put it on +a.
  const auto tip = std::max_element(points.begin(), points.end(),
                                    [](const Point& p, const Point& q) { return p[1] < q[1]; });
  if ((*tip)[0] < 0.5 * (points.front()[0] + points.back()[0])) {
    for (auto& point : points)
      point[0] = -point[0];
    std::reverse(points.begin(), points.end());
  }
  if (!(points.front()[0] < 0 && points.back()[0] > 0)) {
    refuse(source, "Profile file", "the profile does not reach across its running point y = 0",
           "a wheel profile with the running point inside it");
  }
  std::size_t above = 0;
  while (points[above][0] < 0)
    ++above;
  const Point& p = points[above - 1];
  const Point& q = points[above];
  const double z0 = p[1] + (q[1] - p[1]) * (0 - p[0]) / (q[0] - p[0]);
  const double radius = d.nominal_diameter / 2;
  std::vector<Point> tread;
  for (const Point& point : points) {
    if (point[0] >= 0 && (tread.empty() || tread.back()[1] < 0))
      tread.push_back({radius, 0});  // the running point
    // Profile points within 0.1 mm of it would make a needlessly short spline segment.
    if (std::abs(point[0]) > 1e-4)
      tread.push_back({radius + point[1] - z0, point[0]});
  }
  return tread;
}

void check_axle(const WheelDimensions& d, double hub_inner_face, const std::string& source) {
  if (d.axle_length <= hub_inner_face + d.element_size) {
    refuse(source, "Axle length",
           mm(d.axle_length) +
               " does not reach past the hub's inner face at a = " + mm(hub_inner_face),
           "a wheelset centre plane beyond the hub by more than one element");
  }
  if (d.axle_diameter > d.bore_diameter) {
    refuse(source, "Axle diameter",
           mm(d.axle_diameter) + " is larger than the wheel seat (Bore diameter, " +
               mm(d.bore_diameter) + ")",
           "at most the bore diameter");
  }
  if (d.axle_bore_diameter >= d.axle_diameter) {
    refuse(source, "Axle bore diameter",
           mm(d.axle_bore_diameter) + " leaves no axle inside " + mm(d.axle_diameter),
           "less than the axle diameter");
  }
}

}  // namespace

ParameterSpec wheel_parameters() {
  ParameterSpec spec(
      "a railway wheel with its tread profile, optionally with half its axle, revolved about the "
      "y axis: the running point (profile y = 0) at (nominal radius, 0, 0), the flange on +y. "
      "Blocks wheel and axle; node and side sets tread (running surface and flange), bore "
      "(without axle) and axle_end (the axle's face in the wheelset centre plane); node set "
      "running_circle. Defaults: a representative 920 mm coach wheel with the S1002 tread "
      "(EN 13715: 135 mm rim, running circle 70 mm from the flange back), not a measured one.");
  spec.text("Profile file", "",
            "SIMPACK .prw wheel profile, relative to the deck's directory ('' = the S1002 "
            "profile shipped in inputs/profiles). Its flange goes on +y; y = 0 is the running "
            "point.");
  spec.real("Nominal diameter", 0.92, "Diameter of the running circle.", "m", Range::positive());
  spec.real("Rim width", 0.135,
            "Axial width of the rim, from the back of the flange (the profile's flange-side end) "
            "to the outer face; a 45-degree chamfer joins the profile's field-side end to it.",
            "m", Range::positive());
  spec.real("Rim thickness", 0.065, "Radial depth of the rim below the running circle.", "m",
            Range::positive());
  spec.real("Web thickness", 0.028,
            "Axial thickness of the straight web, which joins the middle of the rim to the "
            "middle of the hub.",
            "m", Range::positive());
  spec.real("Hub diameter", 0.28, "Outer diameter of the hub.", "m", Range::positive());
  spec.real("Hub length", 0.18, "Axial length of the hub.", "m", Range::positive());
  spec.real("Hub offset", 0.02,
            "Axial position of the hub's middle from the running plane (+: flange side).", "m");
  spec.real("Bore diameter", 0.195, "Diameter of the hub's bore (the axle's wheel seat).", "m",
            Range::positive());
  spec.flag("Half axle", false,
            "Mesh the axle from the hub's outer face to the wheelset centre plane (block axle, "
            "merged with the hub at the bore: a rigid press fit).");
  spec.real("Axle length", 0.75,
            "From the running plane to the wheelset centre plane (0.75 m: running circles 1.5 m "
            "apart on standard gauge).",
            "m", Range::positive());
  spec.real("Axle diameter", 0.18, "Diameter of the axle body between the wheels.", "m",
            Range::positive());
  spec.real("Axle bore diameter", 0.06,
            "Diameter of the axle's axial bore, so that no node lies on the axis. Hollow axles "
            "are common (bores of 30-65 mm); bending stiffness falls by (bore/diameter)^4, 1.2% "
            "for the defaults.",
            "m", Range::positive());
  spec.real("Element size", 0.01, "Target size of the cross-section's quadrilaterals.", "m",
            Range::closed(5e-4, 0.1));
  spec.integer("Elements around", 0,
               "Elements around the axis (0 = the fewest, in multiples of 4, that keep them no "
               "longer than Element size at the running circle).",
               Range::at_least(0));
  spec.real("Tread element size", 0,
            "Target size of the section's elements at the tread (running surface and flange), "
            "growing to Element size 20 mm inside it (0 = Element size throughout).",
            "m", Range::closed(0, 0.1));
  spec.real_array("Refined arc", {},
                  "{start, end} angles (degrees, about +y from +x towards +z: the lowest point "
                  "is at 270) of the arc meshed at Arc element size ({} = none).",
                  "degree", 0);
  spec.real("Arc element size", 0.001,
            "Element length at the running circle inside the Refined arc (only with one).", "m",
            Range::closed(2e-4, 0.1));
  spec.real_array("Approach arc", {},
                  "{start, end} angles (degrees) of an arc around the Refined arc meshed at "
                  "Approach element size, graded into it with Growth: the path rolled before the "
                  "refined arc, fine enough that the slices' chords do not sag into the contact "
                  "({} = none).",
                  "degree", 0);
  spec.real("Approach element size", 0.004,
            "Element length at the running circle inside the Approach arc (only with one).", "m",
            Range::closed(2e-4, 0.1));
  spec.real("Growth", 1.25,
            "Ratio of neighbouring element lengths around the axis between the refined arc and "
            "the rest (only with a Refined arc).",
            "", Range::open_closed(1, 2));
  spec.real_array("Transition radii", {},
                  "Radii (decreasing), each across the web or the hub, below which the slices "
                  "of the Refined and Approach arcs coarsen threefold, so that slices fine at "
                  "the tread do not reach the hub and axle even thinner (where they would set "
                  "the explicit step). Each transition is a strip 4 x Arc element size deep "
                  "meshed with a conforming 3-to-1 template ({} = none; only with a Refined "
                  "arc).",
                  "m", 0);
  return spec;
}

WheelDimensions wheel_dimensions(const Teuchos::ParameterList& list, const Deck& deck) {
  WheelDimensions d;
  const auto file = list.get<std::string>("Profile file");
  d.profile_file = file.empty() ? shipped_profile("MBench_S1002_v3.prw") : deck.resolve(file);
  d.nominal_diameter = list.get<double>("Nominal diameter");
  d.rim_width = list.get<double>("Rim width");
  d.rim_thickness = list.get<double>("Rim thickness");
  d.web_thickness = list.get<double>("Web thickness");
  d.hub_diameter = list.get<double>("Hub diameter");
  d.hub_length = list.get<double>("Hub length");
  d.hub_offset = list.get<double>("Hub offset");
  d.bore_diameter = list.get<double>("Bore diameter");
  d.half_axle = list.get<bool>("Half axle");
  d.axle_length = list.get<double>("Axle length");
  d.axle_diameter = list.get<double>("Axle diameter");
  d.axle_bore_diameter = list.get<double>("Axle bore diameter");
  d.element_size = list.get<double>("Element size");
  d.elements_around = list.get<int>("Elements around");
  d.tread_element_size = list.get<double>("Tread element size");
  d.refined_arc = list.get<Teuchos::Array<double>>("Refined arc").toVector();
  d.arc_element_size = list.get<double>("Arc element size");
  d.growth = list.get<double>("Growth");
  d.approach_arc = list.get<Teuchos::Array<double>>("Approach arc").toVector();
  d.approach_element_size = list.get<double>("Approach element size");
  d.transition_radii = list.get<Teuchos::Array<double>>("Transition radii").toVector();
  if (!d.transition_radii.empty() && d.refined_arc.empty())
    refuse(deck.source, "Transition radii", "is given without a Refined arc",
           "a Refined arc with it (without one the slices are equal and coarse)");
  for (std::size_t i = 0; i < d.transition_radii.size(); ++i)
    if (!(d.transition_radii[i] > 0) ||
        (i > 0 && !(d.transition_radii[i] < d.transition_radii[i - 1])))
      refuse(deck.source, "Transition radii", "is not a list of decreasing positive radii",
             "decreasing radii in metres, each across the web or the hub");
  if (d.approach_arc.empty() && !list.getEntry("Approach element size").isDefault())
    refuse(deck.source, "Approach element size", "is given without an Approach arc",
           "an Approach arc with it");
  if (!d.approach_arc.empty()) {
    if (d.refined_arc.empty())
      refuse(deck.source, "Approach arc", "is given without a Refined arc",
             "a Refined arc inside it");
    if (d.approach_arc.size() != 2 || !(d.approach_arc[0] <= d.refined_arc[0]) ||
        !(d.approach_arc[1] >= d.refined_arc[1]) || d.approach_arc[1] - d.approach_arc[0] >= 360)
      refuse(deck.source, "Approach arc", "does not enclose the Refined arc",
             "{start, end} in degrees with start <= the Refined arc's start, end >= its end and "
             "end < start + 360");
    if (!(d.approach_element_size > d.arc_element_size) ||
        !(d.approach_element_size < 2 * kPi * d.nominal_diameter / 2 / wheel_elements_around(d)))
      refuse(deck.source, "Approach element size",
             "is not between the Arc element size and the slices' size elsewhere",
             "Arc element size < Approach element size < the circumference / Elements around");
  }
  if (d.refined_arc.empty()) {
    for (const char* name : {"Arc element size", "Growth"}) {
      if (!list.getEntry(name).isDefault())
        refuse(deck.source, name, "is given without a Refined arc", "a Refined arc with it");
    }
  } else if (d.refined_arc.size() != 2 || !(d.refined_arc[1] > d.refined_arc[0]) ||
             d.refined_arc[1] - d.refined_arc[0] >= 360) {
    refuse(deck.source, "Refined arc", "is not an arc",
           "{start, end} in degrees with start < end < start + 360");
  }
  if (d.tread_element_size > d.element_size) {
    refuse(deck.source, "Tread element size", "is coarser than the Element size",
           "at most the Element size (0 = the Element size)");
  }
  if (d.elements_around > 0 && d.elements_around < 3) {
    refuse(deck.source, "Elements around", "is " + std::to_string(d.elements_around),
           "0 (automatic) or at least 3");
  }
  return d;
}

WheelSection wheel_section(const WheelDimensions& d, const std::string& source) {
  WheelSection section;
  section.wheel = tread_of(d, source);
  section.tread_points = section.wheel.size();
  for (std::size_t i = 0; i < section.wheel.size(); ++i) {
    if (section.wheel[i][1] == 0)
      section.running_point = i;
  }
  const Point field_end = section.wheel.front(), flange_back = section.wheel.back();
  const double back = flange_back[1], outer = back - d.rim_width;
  const double chamfer = field_end[1] - outer;
  if (chamfer < 1e-3) {
    refuse(source, "Rim width",
           mm(d.rim_width) + " does not reach 1 mm past the profile, which is " +
               mm(back - field_end[1]) + " wide",
           "more than the profile's width + 1 mm (the outer chamfer)");
  }
  const Point chamfer_foot{field_end[0] - chamfer, outer};
  const double rim = d.nominal_diameter / 2 - d.rim_thickness;
  double lowest = std::min(chamfer_foot[0], flange_back[0]);
  for (std::size_t i = 0; i < section.tread_points; ++i)
    lowest = std::min(lowest, section.wheel[i][0]);
  if (rim >= lowest - 1e-3) {
    refuse(source, "Rim thickness",
           mm(d.rim_thickness) + " leaves less than 1 mm of rim under the chamfer or flange back",
           "a rim reaching more than 1 mm below the tread's lowest point");
  }
  const double hub = d.hub_diameter / 2, bore = d.bore_diameter / 2;
  if (bore >= hub)
    refuse(source, "Bore diameter", mm(d.bore_diameter) + " leaves no hub", "< Hub diameter");
  if (hub >= rim - d.element_size) {
    refuse(source, "Hub diameter",
           mm(d.hub_diameter) + " leaves no room for a web below the rim (inner diameter " +
               mm(2 * rim) + ")",
           "a hub smaller than the rim's inner diameter by more than two elements");
  }
  const double hub_low = d.hub_offset - d.hub_length / 2,
               hub_high = d.hub_offset + d.hub_length / 2;
  const double web_rim = 0.5 * (back + outer), web_hub = d.hub_offset, half = d.web_thickness / 2;
  if (web_rim - half < outer + 1e-3 || web_rim + half > back - 1e-3 ||
      web_hub - half < hub_low + 1e-3 || web_hub + half > hub_high - 1e-3) {
    refuse(source, "Web thickness",
           mm(d.web_thickness) + " does not fit 1 mm inside the rim (" + mm(d.rim_width) +
               ") and the hub (" + mm(d.hub_length) + ")",
           "a web narrower than the rim and the hub by 2 mm");
  }
  const std::vector<Point> corners = {{rim, back},     {rim, web_rim + half}, {hub, web_hub + half},
                                      {hub, hub_high}, {bore, hub_high},      {bore, hub_low},
                                      {hub, hub_low},  {hub, web_hub - half}, {rim, web_rim - half},
                                      {rim, outer},    chamfer_foot};
  section.bore_start = section.wheel.size() + 4;
  section.wheel.insert(section.wheel.end(), corners.begin(), corners.end());
  if (d.half_axle) {
    check_axle(d, hub_high, source);
    const double body = d.axle_diameter / 2, centre = d.axle_length;
    section.axle = {{bore, hub_low}, {bore, hub_high}};
    if (body < bore)
      section.axle.push_back({body, hub_high});
    section.axle.insert(
        section.axle.end(),
        {{body, centre}, {d.axle_bore_diameter / 2, centre}, {d.axle_bore_diameter / 2, hub_low}});
  }
  return section;
}

int wheel_elements_around(const WheelDimensions& d) {
  if (d.elements_around > 0)
    return d.elements_around;
  return 4 * static_cast<int>(std::ceil(kPi * d.nominal_diameter / (4 * d.element_size)));
}

std::vector<double> wheel_slice_angles(const WheelDimensions& d) {
  const int n = wheel_elements_around(d);
  std::vector<double> angles;
  if (d.refined_arc.empty()) {
    for (int k = 0; k < n; ++k)
      angles.push_back(2 * kPi * k / n);
    return angles;
  }
  const double radius = d.nominal_diameter / 2;
  double start = std::fmod(d.refined_arc[0], 360.0);
  start = (start < 0 ? start + 360 : start) * kPi / 180;
  const double arc = (d.refined_arc[1] - d.refined_arc[0]) * kPi / 180;
  const int m = std::max(1, static_cast<int>(std::ceil(arc * radius / d.arc_element_size - 1e-9)));
  for (int k = 0; k < m; ++k)
    angles.push_back(start + arc * k / m);
  // The approach arc on either side (graded from the arc's size up to its own), then the rest
  // of the circle, graded from both ends towards its middle.
  double at = start + arc, gap = 2 * kPi * radius - arc * radius, edge = arc * radius / m;
  std::vector<double> before;  // lengths from the refined arc's start backwards
  if (!d.approach_arc.empty()) {
    const double ahead = (d.approach_arc[1] - d.refined_arc[1]) * kPi / 180 * radius;
    const double behind = (d.refined_arc[0] - d.approach_arc[0]) * kPi / 180 * radius;
    if (ahead > 0)
      for (double length : graded_lengths(ahead, edge, d.approach_element_size, d.growth)) {
        angles.push_back(at);
        at += length / radius;
      }
    if (behind > 0)
      before = graded_lengths(behind, edge, d.approach_element_size, d.growth);
    gap -= ahead + behind;
    edge = d.approach_element_size;
  }
  const std::vector<double> half = graded_lengths(gap / 2, edge, 2 * kPi * radius / n, d.growth);
  for (double length : half) {
    angles.push_back(at);
    at += length / radius;
  }
  for (auto it = half.rbegin(); it + 1 != half.rend(); ++it) {
    angles.push_back(at);
    at += *it / radius;
  }
  if (half.size() > 0)
    angles.push_back(at);
  for (auto it = before.rbegin(); it != before.rend(); ++it) {
    at += (it == before.rbegin() ? half.front() : *(it - 1)) / radius;
    angles.push_back(at);
  }
  return angles;
}

std::string wheel_geo_script(const WheelSection& section, double element_size,
                             double tread_element_size, const std::vector<WheelCut>& cuts) {
  std::ostringstream geo;
  geo << std::setprecision(15);
  geo << "// railfe wheel cross-section: x = r, y = a (m)\nh = " << element_size << ";\n";
  const auto& wheel = section.wheel;
  for (std::size_t i = 0; i < wheel.size(); ++i)
    geo << "Point(" << i + 1 << ") = {" << wheel[i][0] << ", " << wheel[i][1] << ", 0, h};\n";
  auto spline = [&](int tag, std::size_t first, std::size_t last) {
    geo << "Spline(" << tag << ") = {";
    for (std::size_t i = first; i <= last; ++i)
      geo << (i > first ? ", " : "") << i + 1;
    geo << "};\n";
  };
  spline(1, 0, section.running_point);
  spline(2, section.running_point, section.tread_points - 1);
  // Lines from the flange back round to the field-side end: line 3 + k leaves wheel[i] with
  // i = tread_points - 1 + k; the last one closes the loop.
  const std::size_t n_lines = wheel.size() - section.tread_points + 1;
  std::ostringstream loop;
  loop << "Curve Loop(1) = {1, 2";
  for (std::size_t k = 0; k < n_lines; ++k) {
    const std::size_t i = section.tread_points - 1 + k, next = (i + 1) % wheel.size();
    if (!strip_side(cuts, i))
      geo << "Line(" << outline_line_tag(section, i) << ") = {" << i + 1 << ", " << next + 1
          << "};\n";
    loop << ", " << outline_line_tag(section, i);
  }
  // Cut lines follow the axle's lines; 1000 is clear of them (an axle has at most 6 points).
  if (cuts.empty())
    geo << loop.str() << "};\nPlane Surface(1) = {1};\nPhysical Surface(\"wheel\", 1) = {1};\n";
  else
    geo << cut_surfaces_geo(section, cuts, static_cast<int>(3 + n_lines + 1000));
  geo << "Physical Curve(\"tread\", 1) = {1, 2};\n";
  geo << "Physical Point(\"running_circle\", 2) = {" << section.running_point + 1 << "};\n";
  const std::size_t bore_line = 3 + (section.bore_start + 1 - section.tread_points);
  if (section.axle.empty()) {
    geo << "Physical Curve(\"bore\", 3) = {" << bore_line << "};\n";
  } else {
    // The axle shares the bore's two points and line; its other points follow the wheel's.
    const auto& axle = section.axle;
    const std::size_t first = wheel.size() + 1, line0 = 3 + n_lines;
    for (std::size_t i = 2; i < axle.size(); ++i) {
      geo << "Point(" << first + i - 2 << ") = {" << axle[i][0] << ", " << axle[i][1]
          << ", 0, h};\n";
    }
    auto tag = [&](std::size_t i) {
      return i == 0 ? section.bore_start + 2 : i == 1 ? section.bore_start + 1 : first + i - 2;
    };
    std::ostringstream axle_loop;
    axle_loop << "Curve Loop(2) = {-" << bore_line;
    for (std::size_t i = 1; i < axle.size(); ++i) {
      geo << "Line(" << line0 + i - 1 << ") = {" << tag(i) << ", " << tag((i + 1) % axle.size())
          << "};\n";
      axle_loop << ", " << line0 + i - 1;
    }
    geo << axle_loop.str() << "};\nPlane Surface(2) = {2};\n";
    geo << "Physical Surface(\"axle\", 2) = {2};\n";
    geo << "Physical Curve(\"axle_end\", 4) = {" << line0 + axle.size() - 4 << "};\n";
  }
  // Frontal-Delaunay triangles recombined by the blossom full-quad algorithm: all quadrangles
  // (Gmsh 4.8's quad-specific algorithm 8 crashes on the long tread spline).
  geo << "Mesh.Algorithm = 6;\nMesh.RecombineAll = 1;\nMesh.RecombinationAlgorithm = 3;\n"
         "Mesh.MeshSizeMax = h;\n";
  if (tread_element_size > 0 && tread_element_size < element_size) {
    // Sizes graded from the tread's splines inwards (as the rail's from its running surface;
    // 1.5 x the target for the full-quad subdivision, measured in wheel_mesh_tests).
    geo << "Field[1] = Distance;\nField[1].CurvesList = {1, 2};\nField[1].NumPointsPerCurve = "
           "400;\nField[2] = Threshold;\nField[2].InField = 1;\nField[2].SizeMin = "
        << tread_element_size
        << ";\nField[2].SizeMax = h;\nField[2].DistMin = " << tread_element_size
        << ";\nField[2].DistMax = 0.02;\nBackground Field = 2;\n"
        << "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\n"
           "Mesh.MeshSizeExtendFromBoundary = 0;\n";
  }
  return geo.str();
}

Mesh build_wheel_mesh(const WheelDimensions& dimensions, const std::string& source) {
  const WheelSection section = wheel_section(dimensions, source);
  const std::vector<double> angles = wheel_slice_angles(dimensions);
  const double n_around = static_cast<double>(angles.size());
  // A guard against sizes that would fill the machine: about two quadrangles per h².
  double area = 0;
  for (const auto* outline : {&section.wheel, &section.axle}) {
    for (std::size_t i = 0; i < outline->size(); ++i) {
      const Point& p = (*outline)[i];
      const Point& q = (*outline)[(i + 1) % outline->size()];
      area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
  }
  double estimate = 2 * area / std::pow(dimensions.element_size, 2) * n_around;
  if (dimensions.tread_element_size > 0)  // a band about 20 mm deep under a 0.2 m tread
    estimate += 2 * 0.2 * 0.02 / std::pow(dimensions.tread_element_size, 2) * n_around;
  if (estimate > 1e8) {
    refuse(source, "Element size",
           "asks for about " + std::to_string(static_cast<long long>(estimate)) + " elements",
           "at most about 1e8 elements");
  }
  WheelSection cut_section = section;
  const std::vector<WheelCut> cuts =
      dimensions.transition_radii.empty()
          ? std::vector<WheelCut>{}
          : cut_wheel_section(cut_section, dimensions.transition_radii,
                              transition_width(dimensions), dimensions.element_size, source);
  SectionMesh planar = mesh_section_with_gmsh(
      wheel_geo_script(cut_section, dimensions.element_size, dimensions.tread_element_size, cuts),
      source + ": Mesh/Wheel");
  Mesh mesh;
  if (cuts.empty()) {
    mesh = revolve(planar, angles);
  } else {
    const std::vector<int> levels = add_transition_strips(planar, cuts, cut_section);
    mesh = revolve(planar, angles, levels,
                   coarser_wheel_slices(angles, largest_wheel_slices(dimensions)));
  }
  mesh.source = source + ": Mesh/Wheel";
  return mesh;
}

MeshGeneratorDescriptor wheel_mesh_generator() {
  return {"wheel", "generate a railway wheel from its profile, optionally with half its axle",
          wheel_parameters, [](const Teuchos::ParameterList& sublist, const Deck& deck) {
            return build_wheel_mesh(wheel_dimensions(sublist, deck), deck.source);
          }};
}

}  // namespace railfe
