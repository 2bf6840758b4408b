#pragma once
/// \file
/// The wheel mesh generator (Mesh/Type wheel, sublist Mesh/Wheel): a railway wheel with its real
/// tread profile, and optionally half its axle, as a cyclic-symmetric hex8 mesh. The cross-section
/// (the profile as a spline; rim, straight web and hub as lines) is meshed with quadrangles by
/// Gmsh and revolved about the y axis (framework/mesh/revolve.hpp).
///
/// Placement: the axis is the y axis; the running point (the profile's y = 0) lies at (x, y, z) =
/// (nominal radius, 0, 0), i.e. at θ = 0; the flange is on +y. With x forward and z up, y points
/// left, so this is the right-hand wheel of a wheelset whose centre plane is y = +Axle length.
///
/// The default dimensions are representative of a 920 mm passenger-coach wheel with the S1002
/// tread, not those of a measured wheel: EN 13715 fixes the S1002 tread, the 135 mm rim width
/// and the running circle 70 mm from the back of the flange; UIC 510-2 lists 920 mm as a nominal
/// new diameter of coach wheels. Rim, web and hub sizes (65 mm rim below the running circle, 28 mm
/// web, 280 mm hub on a 195 mm bore, 180 mm long) are mid-range values of EN 13979-1-type
/// solid wheels; wheel fillets are left out (sharp corners between web, rim and hub).

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

/// What the Wheel sublist describes (metres). Axial positions a are along y.
struct WheelDimensions {
  std::string profile_file;          ///< SIMPACK .prw wheel profile (a resolved path)
  double nominal_diameter = 0.92;    ///< diameter of the running circle
  double rim_width = 0.135;          ///< back face of the flange to the outer face
  double rim_thickness = 0.065;      ///< running circle to the rim's inner surface, radially
  double web_thickness = 0.028;      ///< axial
  double hub_diameter = 0.28;        ///< outer diameter of the hub
  double hub_length = 0.18;          ///< axial
  double hub_offset = 0.02;          ///< a of the hub's middle (+: flange side)
  double bore_diameter = 0.195;      ///< hub bore = the axle's wheel seat
  bool half_axle = false;            ///< whether the axle, to the wheelset centre, is meshed
  double axle_length = 0.75;         ///< running plane (a = 0) to the wheelset centre plane
  double axle_diameter = 0.18;       ///< axle body between the wheels
  double axle_bore_diameter = 0.06;  ///< the axle's axial bore
  double element_size = 0.01;        ///< target size of the section's elements
  int elements_around = 0;           ///< around the axis; 0 = automatic
  double tread_element_size = 0;     ///< the section's size at the tread; 0 = element_size
  std::vector<double> refined_arc;   ///< {start, end} (degrees) refined around, or empty
  double arc_element_size = 0.001;   ///< length at the running circle inside the refined arc
  /// {start, end} (degrees) around the refined arc meshed at approach_element_size, or empty:
  /// the path a wheel rolls before it reaches the refined arc, fine enough that its chords do not
  /// sag into the contact, not as fine as the arc.
  std::vector<double> approach_arc;
  double approach_element_size = 0.004;  ///< length at the running circle in the approach arc
  double growth = 1.25;                  ///< ratio of neighbouring slices between arc and the rest
  /// Radii (decreasing) below which the slices coarsen threefold (wheel_transitions.hpp).
  std::vector<double> transition_radii;
};

/// The cross-section in (r, a), each outline counter-clockwise with r as the first coordinate.
struct WheelSection {
  /// The wheel: the profile from its field-side end to the flange back (tread_points points, the
  /// running point among them), then the corners of the rim, web, hub and bore and the chamfer.
  std::vector<std::array<double, 2>> wheel;
  std::size_t tread_points = 0;   ///< the first tread_points points of wheel are the tread
  std::size_t running_point = 0;  ///< index in wheel of (nominal radius, 0)
  std::size_t bore_start = 0;     ///< the bore runs from wheel[bore_start] to the next point
  /// The half axle, starting with the bore's two points in reverse; empty without it.
  std::vector<std::array<double, 2>> axle;
};

/// A cut across the wheel's section at a constant radius, where a transition strip begins or
/// ends (wheel_transitions.hpp): the indices in WheelSection::wheel of its two points, in the
/// order the outline meets them.
struct WheelCut {
  double radius = 0;       ///< r of the cut (m)
  std::size_t first = 0;   ///< the point met first along the outline
  std::size_t second = 0;  ///< the other point
  int segments = 0;        ///< Gmsh segments along the cut (even, for the full-quad recombination)
};

/// Valid parameters of the Wheel sublist.
ParameterSpec wheel_parameters();

/// Reads a validated Wheel sublist; the profile path is resolved against the deck.
WheelDimensions wheel_dimensions(const Teuchos::ParameterList& sublist, const Deck& deck);

/// Builds and checks the cross-section: reads the profile (its flange is put on +a, its y = 0 at
/// the nominal radius) and throws InputError naming \p source and "Mesh/Wheel/<parameter>"
/// when the dimensions do not give a valid wheel (a rim narrower than the profile, a web wider
/// than the hub, an axle thicker than the bore...).
WheelSection wheel_section(const WheelDimensions& dimensions, const std::string& source);

/// Elements around the axis: the given count, or (when 0) the fewest, in multiples of 4, that
/// make the elements at the running circle no longer than the element size.
int wheel_elements_around(const WheelDimensions& dimensions);

/// The angles (radians) of the slices: wheel_elements_around() equal ones without a refined
/// arc; with one, slices of Arc element size (at the running circle) over the arc and lengths
/// growing by the growth ratio from both its ends up to the size of the equal slices. The
/// first angle is the arc's start (in [0, 2π)).
std::vector<double> wheel_slice_angles(const WheelDimensions& dimensions);

/// The Gmsh script of the section (elements of \p tread_element_size at the tread growing to
/// \p element_size 20 mm inside it, or \p element_size throughout when it is 0): blocks "wheel" and
/// "axle", node sets "tread" (running surface and flange), "running_circle", "bore" (without axle)
/// and "axle_end" (the axle's face in the wheelset centre plane). With \p cuts (their points in
/// \p section), the strips between each pair of cuts are left out: see wheel_transitions.hpp.
std::string wheel_geo_script(const WheelSection& section, double element_size,
                             double tread_element_size = 0, const std::vector<WheelCut>& cuts = {});

/// The wheel mesh (Gmsh runs in a private temporary directory). Throws InputError naming
/// \p source for bad dimensions and RunError when gmsh is missing.
Mesh build_wheel_mesh(const WheelDimensions& dimensions, const std::string& source);

/// The registry entry of Mesh/Type wheel.
MeshGeneratorDescriptor wheel_mesh_generator();

}  // namespace railfe
