#include "physics/parts/vehicle_mesh.hpp"

#include <array>
#include <sstream>
#include <vector>

#include "framework/base/error.hpp"

namespace railfe {

ParameterSpec vehicle_mesh_parameters() {
  ParameterSpec spec(
      "A car body, two bogies and four wheelsets as rigid bodies (point_mass blocks 'car_body', "
      "'bogies', 'wheelsets') on primary and secondary suspensions (spring2 blocks 'primary', "
      "'secondary', optionally 'secondary_rotation'), carried by rigid links (block 'links'); "
      "track axes x forward, y right, z DOWN, origin on the track centre line in the "
      "top-of-rail plane under the vehicle's centre (gravity is +z). Node sets: 'car_body', "
      "'bogies', 'front_bogie', 'rear_bogie', 'wheelsets', 'wheelset_1' .. 'wheelset_4' (front "
      "to rear), 'floor_above_front_bogie', 'floor_above_rear_bogie', 'bodies', 'all'.");
  spec.required_real("Half bogie spacing", "a: bogie centres at x = ±a.", "m", Range::positive());
  spec.required_real("Half wheelbase", "b: the wheelsets at x = ±a ± b (b < a).", "m",
                     Range::positive());
  spec.real("Wheel radius", 0.43,
            "r0: nominal rolling radius; the wheelset centres and the axle boxes are at z = -r0.",
            "m", Range::positive());
  spec.required_real("Car body height", "h_c: the car body's centre of mass above the rails.", "m",
                     Range::positive());
  spec.required_real("Bogie height", "h_b: the bogies' centres of mass above the rails.", "m",
                     Range::positive());
  spec.required_real("Primary half span", "d_p: the axle boxes at y = ±d_p.", "m",
                     Range::positive());
  spec.required_real("Secondary half span", "d_s: the secondary springs at y = ±d_s.", "m",
                     Range::positive());
  spec.required_real("Secondary height",
                     "h_s: the secondary springs' height above the rails (where they act on both "
                     "bodies).",
                     "m", Range::positive());
  spec.real("Floor height", 1.2,
            "h_f: height of the car body's measuring points above the bogie centres (node sets "
            "'floor_above_front_bogie', 'floor_above_rear_bogie').",
            "m", Range::positive());
  spec.flag("Secondary rotation", false,
            "Adds block 'secondary_rotation': a spring2 from the car body's centre to each "
            "bogie's, for rotational components only (an anti-roll bar about x, a yaw stiffness "
            "or damping about z); its Section must leave the translations at zero.");
  return spec;
}

VehicleLayout vehicle_layout(const Teuchos::ParameterList& sublist, const Deck& deck) {
  VehicleLayout layout;
  layout.half_bogie_spacing = sublist.get<double>("Half bogie spacing");
  layout.half_wheelbase = sublist.get<double>("Half wheelbase");
  layout.wheel_radius = sublist.get<double>("Wheel radius");
  layout.car_body_height = sublist.get<double>("Car body height");
  layout.bogie_height = sublist.get<double>("Bogie height");
  layout.primary_half_span = sublist.get<double>("Primary half span");
  layout.secondary_half_span = sublist.get<double>("Secondary half span");
  layout.secondary_height = sublist.get<double>("Secondary height");
  layout.floor_height = sublist.get<double>("Floor height");
  layout.secondary_rotation = sublist.get<bool>("Secondary rotation");
  std::ostringstream what;
  if (layout.half_wheelbase >= layout.half_bogie_spacing) {
    what << "(" << layout.half_wheelbase
         << " m) puts the inner wheelsets of the two bogies on or past each other";
    throw_input_error(deck.source, "Mesh/Vehicle/Half wheelbase", what.str(),
                      "less than Half bogie spacing");
  }
  if (layout.secondary_height <= layout.wheel_radius) {
    what << "is not above the axles (Wheel radius " << layout.wheel_radius << " m)";
    throw_input_error(deck.source, "Mesh/Vehicle/Secondary height", what.str(),
                      "a height above Wheel radius, between bogie frame and car body");
  }
  return layout;
}

Mesh build_vehicle_mesh(const VehicleLayout& layout, const std::string& source) {
  Mesh mesh;
  mesh.source = source;
  const double a = layout.half_bogie_spacing, b = layout.half_wheelbase;
  auto add_node = [&mesh](double x, double y, double z) {
    mesh.coordinates.insert(mesh.coordinates.end(), {x, y, z});
    return mesh.n_nodes() - 1;
  };
  // The bodies first, in the order the header promises.
  add_node(0, 0, -layout.car_body_height);
  const std::array<double, 2> bogie_x{a, -a};
  for (double x : bogie_x)
    add_node(x, 0, -layout.bogie_height);
  const std::array<double, 4> wheelset_x{a + b, a - b, -a + b, -a - b};
  for (double x : wheelset_x)
    add_node(x, 0, -layout.wheel_radius);

  std::vector<std::vector<GlobalIndex>> carried(7);  // per body: the nodes it carries
  auto carried_node = [&](int body, double x, double y, double z) {
    const GlobalIndex node = add_node(x, y, z);
    carried[body].push_back(node);
    return node;
  };
  auto block = [](const std::string& name, ElementType type) {
    ElementBlock block;
    block.name = name;
    block.type = type;
    return block;
  };
  ElementBlock primary = block("primary", ElementType::spring2);
  for (int w = 0; w < vehicle_wheelsets; ++w) {
    const int bogie = 1 + w / 2, wheelset = vehicle_first_wheelset_node + w;
    for (double y : {layout.primary_half_span, -layout.primary_half_span}) {
      const GlobalIndex nodes[2] = {carried_node(bogie, wheelset_x[w], y, -layout.wheel_radius),
                                    carried_node(wheelset, wheelset_x[w], y, -layout.wheel_radius)};
      primary.add_element(nodes, 2);
    }
  }
  ElementBlock secondary = block("secondary", ElementType::spring2);
  for (int k = 0; k < 2; ++k)
    for (double y : {layout.secondary_half_span, -layout.secondary_half_span}) {
      const GlobalIndex nodes[2] = {
          carried_node(vehicle_car_body_node, bogie_x[k], y, -layout.secondary_height),
          carried_node(1 + k, bogie_x[k], y, -layout.secondary_height)};
      secondary.add_element(nodes, 2);
    }
  const double floor = layout.bogie_height + layout.floor_height;
  const GlobalIndex floor_front = carried_node(vehicle_car_body_node, a, 0, -floor);
  const GlobalIndex floor_rear = carried_node(vehicle_car_body_node, -a, 0, -floor);

  ElementBlock bodies[3] = {block("car_body", ElementType::point_mass),
                            block("bogies", ElementType::point_mass),
                            block("wheelsets", ElementType::point_mass)};
  for (GlobalIndex body = 0; body < 7; ++body)
    bodies[body == 0 ? 0 : body < 3 ? 1 : 2].add_element(&body, 1);
  ElementBlock links = block("links", ElementType::rigid_link);
  for (GlobalIndex body = 0; body < 7; ++body) {
    std::vector<GlobalIndex> nodes{body};
    nodes.insert(nodes.end(), carried[body].begin(), carried[body].end());
    links.add_element(nodes.data(), static_cast<int>(nodes.size()));
  }
  for (auto& body : bodies)
    mesh.blocks.push_back(body);
  mesh.blocks.push_back(primary);
  mesh.blocks.push_back(secondary);
  if (layout.secondary_rotation) {
    ElementBlock rotation = block("secondary_rotation", ElementType::spring2);
    for (GlobalIndex bogie : {1, 2}) {
      const GlobalIndex nodes[2] = {vehicle_car_body_node, bogie};
      rotation.add_element(nodes, 2);
    }
    mesh.blocks.push_back(rotation);
  }
  mesh.blocks.push_back(links);
  for (std::size_t i = 0; i < mesh.blocks.size(); ++i)
    mesh.blocks[i].id = static_cast<int>(i) + 1;
  mesh.number_blocks();

  std::vector<NodeSet> sets{{"car_body", 0, {0}},
                            {"bogies", 0, {1, 2}},
                            {"front_bogie", 0, {1}},
                            {"rear_bogie", 0, {2}},
                            {"wheelsets", 0, {3, 4, 5, 6}}};
  for (int w = 0; w < vehicle_wheelsets; ++w)
    sets.push_back({"wheelset_" + std::to_string(w + 1), 0, {vehicle_first_wheelset_node + w}});
  sets.push_back({"floor_above_front_bogie", 0, {floor_front}});
  sets.push_back({"floor_above_rear_bogie", 0, {floor_rear}});
  sets.push_back({"bodies", 0, {0, 1, 2, 3, 4, 5, 6}});
  NodeSet all{"all", 0, {}};
  for (GlobalIndex node = 0; node < mesh.n_nodes(); ++node)
    all.nodes.push_back(node);
  sets.push_back(all);
  for (std::size_t i = 0; i < sets.size(); ++i) {
    sets[i].id = static_cast<int>(i) + 1;
    mesh.node_sets.push_back(sets[i]);
  }
  return mesh;
}

MeshGeneratorDescriptor vehicle_mesh_generator() {
  return {"vehicle",
          "generate a railway vehicle: car body, two bogies, four wheelsets on primary and "
          "secondary suspensions",
          vehicle_mesh_parameters, [](const Teuchos::ParameterList& sublist, const Deck& deck) {
            return build_vehicle_mesh(vehicle_layout(sublist, deck),
                                      deck.source + ": Mesh/Vehicle");
          }};
}

}  // namespace railfe
