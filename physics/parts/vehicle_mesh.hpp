#pragma once
/// \file
/// The vehicle mesh generator (Mesh/Type vehicle, sublist Mesh/Vehicle): a railway vehicle of a
/// car body, two bogies and four wheelsets as rigid bodies (point_mass blocks at their centres of
/// mass) joined by primary and secondary suspensions (spring2 blocks, bushings between coincident
/// nodes, each node carried by its body through a rigid_link block), in track axes: x forward,
/// y to the right, z down, origin on the track centre line in the top-of-rail plane under the
/// vehicle's centre. The deck's Sections give masses, inertias and spring–dampers by block, so
/// the same part serves the modal module (its modes with the wheelsets held) and the vehicle
/// dynamics module (the wheelsets on the rails). Blocks, node sets and node order are listed in
/// docs/user-guide.md ("Vehicle part").

#include <string>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

/// The vehicle's dimensions (m).
struct VehicleLayout {
  double half_bogie_spacing = 0;   ///< a: bogie centres at x = ±a
  double half_wheelbase = 0;       ///< b: wheelsets at x = ±a ± b
  double wheel_radius = 0;         ///< r₀: wheelset centres at z = −r₀, the axle boxes too
  double car_body_height = 0;      ///< h_c: car body centre of mass at z = −h_c
  double bogie_height = 0;         ///< h_b: bogie centres of mass at z = −h_b
  double primary_half_span = 0;    ///< d_p: axle boxes at y = ±d_p
  double secondary_half_span = 0;  ///< d_s: secondary springs at y = ±d_s
  double secondary_height = 0;     ///< h_s: secondary springs at z = −h_s
  double floor_height = 0;         ///< h_f: the car body's measuring points at z = −h_f
  /// Whether each bogie has a rotational spring–damper to the car body (anti-roll bar, yaw
  /// stiffness or yaw dampers as an equivalent): block "secondary_rotation".
  bool secondary_rotation = false;
};

/// Node of the car body's centre of mass; the bogies' are 1 and 2 (front, rear), the wheelsets'
/// 3 to 6 (front to rear). These seven are the bodies; every other node is carried by one.
constexpr int vehicle_car_body_node = 0;
/// Node of the first wheelset's centre (see vehicle_car_body_node).
constexpr int vehicle_first_wheelset_node = 3;
/// Wheelsets of the vehicle.
constexpr int vehicle_wheelsets = 4;

/// Valid parameters of the Vehicle sublist.
ParameterSpec vehicle_mesh_parameters();

/// Reads a validated Vehicle sublist; throws InputError naming \p deck and
/// "Mesh/Vehicle/<parameter>" for dimensions that make bodies overlap or springs sit where they
/// cannot act (a wheelbase longer than the bogie spacing, a secondary spring below the axle).
VehicleLayout vehicle_layout(const Teuchos::ParameterList& sublist, const Deck& deck);

/// The mesh of \p layout (see the file comment), \p source naming it in messages.
Mesh build_vehicle_mesh(const VehicleLayout& layout, const std::string& source);

/// The generator's descriptor for the registry.
MeshGeneratorDescriptor vehicle_mesh_generator();

}  // namespace railfe
