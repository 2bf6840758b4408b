#include "physics/parts/rail_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "contact/geometry/rail_drawing.hpp"
#include "framework/base/error.hpp"
#include "framework/mesh/gmsh_section.hpp"
#include "framework/mesh/grading.hpp"
#include "framework/mesh/revolve.hpp"

namespace railfe {

namespace {

[[noreturn]] void refuse(const std::string& source, const std::string& parameter,
                         const std::string& problem, const std::string& allowed = "") {
  throw_input_error(source, "Mesh/Rail/" + parameter, problem, allowed);
}

std::string metres(double value) {
  std::ostringstream text;
  text << std::setprecision(6) << value << " m";
  return text.str();
}

}  // namespace

ParameterSpec rail_parameters() {
  ParameterSpec spec(
      "a rail of a standard section (EN 13674-1 drawings: arcs and lines as drawn) extruded "
      "along x from 0 to Length, upright, the crown's top at y = z = 0; graded along x from a "
      "fine solution zone and across the section from the running surface. Block rail; node and "
      "side sets running_surface (the crown and corner arcs), foot_bottom, start_face (x = 0) "
      "and end_face (x = Length). Incline it 1:40 with the part's Rotation angle.");
  spec.choice("Profile", "54E1",
              {{"54E1", "EN 13674-1 54E1 (UIC 54): 159 mm high, 70 mm head, 140 mm foot"},
               {"60E1", "EN 13674-1 60E1 (UIC 60): 172 mm high, 72 mm head, 150 mm foot"}},
              "The rail's section.");
  spec.required_real("Length", "Length of the rail along x.", "m", Range::positive());
  spec.real_array("Solution zone", {},
                  "{start, end} along x of the zone meshed at Zone element size ({} = none: "
                  "uniform at Element size).",
                  "m", 0, Range::non_negative());
  spec.real("Zone element size", 0.001,
            "Element length along x inside the solution zone (only with a Solution zone).", "m",
            Range::closed(0.0002, 0.1));
  spec.real("Element size", 0.02, "Element length along x far from the solution zone.", "m",
            Range::closed(0.0002, 0.5));
  spec.real("Growth", 1.25,
            "Ratio of neighbouring element lengths along x between the zone and the coarse "
            "parts (only with a Solution zone).",
            "", Range::open_closed(1, 2));
  spec.real("Head element size", 0.003,
            "Target size of the section's elements at the running surface (the crown and "
            "corner arcs), growing to Section element size 20 mm below it.",
            "m", Range::closed(0.0002, 0.05));
  spec.real("Section element size", 0.01,
            "Target size of the section's elements in the web and foot.", "m",
            Range::closed(0.0005, 0.05));
  return spec;
}

RailDimensions rail_dimensions(const Teuchos::ParameterList& list, const Deck& deck) {
  RailDimensions d;
  d.profile = list.get<std::string>("Profile");
  d.length = list.get<double>("Length");
  d.solution_zone = list.get<Teuchos::Array<double>>("Solution zone").toVector();
  d.zone_element_size = list.get<double>("Zone element size");
  d.element_size = list.get<double>("Element size");
  d.growth = list.get<double>("Growth");
  d.head_element_size = list.get<double>("Head element size");
  d.section_element_size = list.get<double>("Section element size");
  if (!d.solution_zone.empty()) {
    if (d.solution_zone.size() != 2 || !(d.solution_zone[0] < d.solution_zone[1]) ||
        d.solution_zone[1] > d.length) {
      refuse(deck.source, "Solution zone", "does not lie within the rail's length",
             "{start, end} with 0 <= start < end <= Length (" + metres(d.length) + ")");
    }
  } else {
    for (const char* name : {"Zone element size", "Growth"}) {
      if (!list.getEntry(name).isDefault())
        refuse(deck.source, name, "is given without a Solution zone",
               "a Solution zone with it, or neither");
    }
  }
  if (d.head_element_size > d.section_element_size) {
    refuse(deck.source, "Head element size",
           metres(d.head_element_size) + " is coarser than the Section element size (" +
               metres(d.section_element_size) + ")",
           "at most the Section element size");
  }
  if (!d.solution_zone.empty() && d.zone_element_size > d.element_size) {
    refuse(deck.source, "Zone element size",
           metres(d.zone_element_size) + " is coarser than the Element size (" +
               metres(d.element_size) + ")",
           "at most the Element size");
  }
  return d;
}

std::vector<double> rail_stations(const RailDimensions& d) {
  std::vector<double> stations;
  if (d.solution_zone.empty()) {
    const int n = std::max(1, static_cast<int>(std::ceil(d.length / d.element_size - 1e-9)));
    for (int k = 0; k <= n; ++k)
      stations.push_back(d.length * k / n);
    return stations;
  }
  const double start = d.solution_zone[0], end = d.solution_zone[1];
  const int n =
      std::max(1, static_cast<int>(std::ceil((end - start) / d.zone_element_size - 1e-9)));
  const double h = (end - start) / n;
  const std::vector<double> before = graded_lengths(start, h, d.element_size, d.growth);
  const std::vector<double> after = graded_lengths(d.length - end, h, d.element_size, d.growth);
  stations.push_back(start);
  for (double length : before)
    stations.push_back(stations.back() - length);
  std::reverse(stations.begin(), stations.end());
  stations.front() = 0;
  for (int k = 1; k <= n; ++k)
    stations.push_back(start + (end - start) * k / n);
  for (double length : after)
    stations.push_back(stations.back() + length);
  stations.back() = d.length;  // the scaled lengths end there up to round-off
  return stations;
}

std::string rail_geo_script(const RailDimensions& d) {
  const RailOutline outline = rail_outline(d.profile);
  const auto& segments = outline.segments;
  std::ostringstream geo;
  geo << std::setprecision(15);
  geo << "// railfe rail section " << outline.name << ": x = u (lateral), y = v (up), m\n";
  geo << "h = " << d.section_element_size << ";\n";
  // Point k + 1 starts segment k; arc centres follow.
  for (std::size_t k = 0; k < segments.size(); ++k) {
    geo << "Point(" << k + 1 << ") = {" << segments[k].start[0] << ", " << segments[k].start[1]
        << ", 0, h};\n";
  }
  std::size_t next_point = segments.size() + 1;
  std::ostringstream loop;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const std::size_t from = k + 1, to = (k + 1) % segments.size() + 1;
    if (segments[k].is_arc) {
      geo << "Point(" << next_point << ") = {" << segments[k].centre[0] << ", "
          << segments[k].centre[1] << ", 0, h};\n";
      geo << "Circle(" << k + 1 << ") = {" << from << ", " << next_point++ << ", " << to << "};\n";
    } else {
      geo << "Line(" << k + 1 << ") = {" << from << ", " << to << "};\n";
    }
    loop << (k > 0 ? ", " : "") << k + 1;
  }
  geo << "Curve Loop(1) = {" << loop.str() << "};\nPlane Surface(1) = {1};\n";
  geo << "Physical Surface(\"rail\", 1) = {1};\n";
  std::ostringstream running;
  for (std::size_t i = 0; i < outline.running_surface.size(); ++i)
    running << (i > 0 ? ", " : "") << outline.running_surface[i] + 1;
  geo << "Physical Curve(\"running_surface\", 1) = {" << running.str() << "};\n";
  geo << "Physical Curve(\"foot_bottom\", 2) = {1, " << segments.size() << "};\n";
  // Sizes: Head element size on the running surface, growing to the section's size 20 mm
  // below it. After the blossom full-quad recombination the running surface's edges come out
  // at 0.7-0.85 of the target (measured in rail_mesh_tests): never coarser than asked.
  geo << "Field[1] = Distance;\nField[1].CurvesList = {" << running.str()
      << "};\nField[1].NumPointsPerCurve = 200;\n";
  geo << "Field[2] = Threshold;\nField[2].InField = 1;\nField[2].SizeMin = " << d.head_element_size
      << ";\nField[2].SizeMax = " << d.section_element_size
      << ";\nField[2].DistMin = " << d.head_element_size << ";\nField[2].DistMax = 0.02;\n";
  geo << "Background Field = 2;\nMesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\n"
         "Mesh.MeshSizeExtendFromBoundary = 0;\n";
  geo << "Mesh.Algorithm = 6;\nMesh.RecombineAll = 1;\nMesh.RecombinationAlgorithm = 3;\n";
  return geo.str();
}

Mesh build_rail_mesh(const RailDimensions& d, const std::string& source) {
  const std::vector<double> stations = rail_stations(d);
  const SectionProperties section = section_properties(rail_outline(d.profile));
  // A guard against sizes that would fill the machine: at most the head's size everywhere.
  const double estimate =
      section.area / std::pow(d.head_element_size, 2) * static_cast<double>(stations.size());
  if (estimate > 1e8) {
    refuse(source, "Head element size",
           "with " + std::to_string(stations.size()) + " stations asks for up to about " +
               std::to_string(static_cast<long long>(estimate)) + " elements",
           "at most about 1e8 elements");
  }
  Mesh mesh = extrude(mesh_section_with_gmsh(rail_geo_script(d), source + ": Mesh/Rail"), stations);
  mesh.source = source + ": Mesh/Rail";
  return mesh;
}

MeshGeneratorDescriptor rail_mesh_generator() {
  return {"rail",
          "generate a rail of a standard section extruded along x, graded from a solution zone",
          rail_parameters, [](const Teuchos::ParameterList& sublist, const Deck& deck) {
            return build_rail_mesh(rail_dimensions(sublist, deck), deck.source);
          }};
}

}  // namespace railfe
