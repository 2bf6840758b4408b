#include "framework/mesh/mesh_parameters.hpp"

#include <filesystem>

#include <Teuchos_Array.hpp>

#include <cctype>

#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/derived_sets.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/mesh/revolve.hpp"

namespace railfe {

std::string generator_sublist_name(const std::string& name) {
  std::string sublist = name;
  if (!sublist.empty())
    sublist[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sublist[0])));
  return sublist;
}

ParameterSpec mesh_parameters(const std::vector<MeshGeneratorDescriptor>& generators) {
  ParameterSpec box(
      "A structured hex8 box: node and side sets xmin, xmax, ymin, ymax, zmin, zmax "
      "cover its faces.");
  box.real_array("Origin", {0, 0, 0}, "Corner with the smallest coordinates.", "m", 3);
  box.required_real_array("Lengths", "Edge lengths along x, y and z.", "m", 3, Range::positive());
  box.integer_array("Elements", {1, 1, 1}, "Elements along x, y and z.", 3, Range::at_least(1));
  box.real_array("Grading", {1, 1, 1},
                 "Per axis, size of the last element over the first (geometric progression; "
                 "1 = uniform).",
                 "", 3, Range::positive());
  box.text("Block name", "block_1", "Name of the element block.");

  const std::string revolved_doc =
      "Type revolved: a quadrilateral cross-section revolved through 360 degrees about the y "
      "axis, the section point (r, a) going to (x, y, z) = (r cos θ, a, r sin θ), the seam "
      "merged. Each slice spans a chord, so the volume is n sin(2π/n)/2π of the exact body's "
      "for n elements around.";
  ParameterSpec revolved(revolved_doc);
  revolved.required_text(
      "Section file",
      "Gmsh .msh 4.1 ASCII mesh of the cross-section, relative to the deck's directory: "
      "quadrangles only, in the x-y plane with x = r > 0 and y = a. Physical surfaces become "
      "blocks; physical curves and points become node sets of their revolved nodes (and side "
      "sets where they follow the section's boundary).");
  revolved.integer("Elements around", 48, "Elements around the axis.", Range::at_least(3));

  ParameterSpec node_set("A node set selected from the mesh: give Box or Point.");
  node_set.real_array("Box", {}, "Nodes inside {xmin, xmax, ymin, ymax, zmin, zmax}.", "m", 6);
  node_set.real_array("Point", {}, "The single node nearest to {x, y, z}.", "m", 3);
  node_set.text("Within", "", "Select only among this node set's nodes ('' = all nodes).");

  ParameterSpec side_set("A side set selected from the mesh's element faces.");
  side_set.required_real_array("Box",
                               "Faces whose nodes all lie in {xmin, xmax, ymin, ymax, "
                               "zmin, zmax}.",
                               "m", 6);
  side_set.text("Within", "", "Select only among this side set's faces ('' = all exterior faces).");

  ParameterSpec spec("The mesh: generated, or read from Exodus II or Gmsh.");
  std::vector<Choice> types = {
      {"box", "generate a structured box (sublist Box)"},
      {"exodus", "read an Exodus II file (File)"},
      {"gmsh", "read a Gmsh .msh 4.1 ASCII file (File)"},
      {"revolved", "revolve a Gmsh cross-section about the y axis (sublist Revolved)"}};
  for (const auto& generator : generators) {
    types.push_back({generator.name, generator.summary + " (sublist " +
                                         generator_sublist_name(generator.name) + ")"});
  }
  spec.required_choice("Type", types, "Where the mesh comes from.");
  spec.text("File", "", "Mesh file for Type exodus or gmsh, relative to the deck's directory.");
  spec.real("Length scale", 1.0,
            "Factor applied to file coordinates (Type exodus, gmsh, revolved) to get metres "
            "(0.001 for a mesh in mm).",
            "", Range::positive());
  spec.sublist("Box", box, "Generated box (Type box).");
  spec.sublist("Revolved", revolved, revolved_doc);
  for (const auto& generator : generators) {
    const ParameterSpec parameters = generator.parameters();
    spec.sublist(generator_sublist_name(generator.name), parameters,
                 "Type " + generator.name + ": " +
                     (parameters.doc().empty() ? generator.summary : parameters.doc()));
  }
  spec.named_sublists("Node sets", node_set, "Node sets defined from geometry.");
  spec.named_sublists("Side sets", side_set, "Side sets defined from geometry.");
  spec.choice("Partitioner", "multijagged",
              {{"multijagged", "Zoltan2 multi-jagged geometric partitioning"},
               {"rcb", "Zoltan2 recursive coordinate bisection"},
               {"block", "contiguous element ranges (for debugging)"}},
              "How elements are split over MPI ranks.");
  return spec;
}

namespace {

template <std::size_t N>
std::array<double, N> array_of(const Teuchos::Array<double>& values) {
  std::array<double, N> result{};
  for (std::size_t i = 0; i < N; ++i)
    result[i] = values[i];
  return result;
}

Mesh generate_from_deck(const Teuchos::ParameterList& section, const Deck& deck) {
  if (!section.isSublist("Box")) {
    throw_input_error(deck.source, "Mesh/Box", "missing required sublist for Type 'box'",
                      "a Box sublist with Lengths and Elements");
  }
  const auto& box = section.sublist("Box");
  BoxSpec spec;
  spec.origin = array_of<3>(box.get<Teuchos::Array<double>>("Origin"));
  spec.lengths = array_of<3>(box.get<Teuchos::Array<double>>("Lengths"));
  const auto& elements = box.get<Teuchos::Array<int>>("Elements");
  spec.elements = {elements[0], elements[1], elements[2]};
  spec.grading = array_of<3>(box.get<Teuchos::Array<double>>("Grading"));
  spec.block_name = box.get<std::string>("Block name");
  const double n_elements = 1.0 * elements[0] * elements[1] * elements[2];
  if (n_elements > 2e8) {
    throw_input_error(
        deck.source, "Mesh/Box/Elements",
        "asks for " + std::to_string(static_cast<long long>(n_elements)) + " elements",
        "at most 2e8 elements");
  }
  return generate_box(spec);
}

// The sublist a generated type needs; absent only when its spec has required entries.
const Teuchos::ParameterList& type_sublist(const Teuchos::ParameterList& section,
                                           const std::string& name, const std::string& type,
                                           const Deck& deck) {
  if (!section.isSublist(name)) {
    throw_input_error(deck.source, "Mesh/" + name,
                      "missing required sublist for Type '" + type + "'",
                      "a " + name + " sublist (see railfe --describe framework)");
  }
  return section.sublist(name);
}

Mesh revolve_from_deck(const Teuchos::ParameterList& section, const Deck& deck) {
  const auto& revolved = type_sublist(section, "Revolved", "revolved", deck);
  SectionMesh cross_section =
      read_gmsh_section(deck.resolve(revolved.get<std::string>("Section file")));
  const double scale = section.get<double>("Length scale");
  for (double& x : cross_section.coordinates)
    x *= scale;
  return revolve(cross_section, revolved.get<int>("Elements around"));
}

const MeshGeneratorDescriptor* find_generator(
    const std::vector<MeshGeneratorDescriptor>& generators, const std::string& type) {
  for (const auto& generator : generators) {
    if (generator.name == type)
      return &generator;
  }
  return nullptr;
}

}  // namespace

Mesh build_mesh(const Teuchos::ParameterList& section, const Deck& deck,
                const std::vector<MeshGeneratorDescriptor>& generators) {
  const auto type = section.get<std::string>("Type");
  Mesh mesh;
  if (type == "box") {
    mesh = generate_from_deck(section, deck);
  } else if (type == "revolved") {
    mesh = revolve_from_deck(section, deck);
  } else if (const auto* generator = find_generator(generators, type)) {
    const std::string name = generator_sublist_name(type);
    mesh = generator->build(type_sublist(section, name, type, deck), deck);
  } else {
    const auto file = section.get<std::string>("File");
    if (file.empty()) {
      throw_input_error(deck.source, "Mesh/File", "missing mesh file for Type '" + type + "'",
                        "a path to the mesh file");
    }
    const std::string path = deck.resolve(file);
    if (std::filesystem::is_directory(path))
      throw_input_error(deck.source, "Mesh/File", "'" + path + "' is a directory",
                        "a " + type + " mesh file");
    // The reader names the file and line; the deck and the parameter that pointed there come
    // first, so the user knows which deck to mend.
    try {
      mesh = type == "exodus" ? read_exodus_mesh(path) : read_gmsh_mesh(path);
    } catch (const InputError& error) {
      throw_input_error(deck.source, "Mesh/File", error.what());
    }
    const double scale = section.get<double>("Length scale");
    for (double& x : mesh.coordinates)
      x *= scale;
  }

  std::vector<DerivedSetSpec> derived;
  const auto& node_sets = section.sublist("Node sets");
  for (auto it = node_sets.begin(); it != node_sets.end(); ++it) {
    const auto& entry = node_sets.sublist(node_sets.name(it));
    DerivedSetSpec spec;
    spec.name = node_sets.name(it);
    spec.path = "Mesh/Node sets/" + spec.name;
    spec.within = entry.get<std::string>("Within");
    const auto& box = entry.get<Teuchos::Array<double>>("Box");
    const auto& point = entry.get<Teuchos::Array<double>>("Point");
    if (!box.empty())
      spec.box = array_of<6>(box);
    if (!point.empty())
      spec.point = array_of<3>(point);
    derived.push_back(spec);
  }
  const auto& side_sets = section.sublist("Side sets");
  for (auto it = side_sets.begin(); it != side_sets.end(); ++it) {
    const auto& entry = side_sets.sublist(side_sets.name(it));
    DerivedSetSpec spec;
    spec.name = side_sets.name(it);
    spec.path = "Mesh/Side sets/" + spec.name;
    spec.side_set = true;
    spec.within = entry.get<std::string>("Within");
    spec.box = array_of<6>(entry.get<Teuchos::Array<double>>("Box"));
    derived.push_back(spec);
  }
  try {
    check_mesh(mesh);
  } catch (const InputError& error) {
    throw_input_error(deck.source, "Mesh", error.what());
  }
  add_derived_sets(mesh, derived, deck.source);
  return mesh;
}

PartitionMethod partition_method(const Teuchos::ParameterList& section) {
  const auto name = section.get<std::string>("Partitioner");
  if (name == "rcb")
    return PartitionMethod::rcb;
  if (name == "block")
    return PartitionMethod::block;
  return PartitionMethod::multijagged;
}

}  // namespace railfe
