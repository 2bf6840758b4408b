#include "framework/mesh/mesh_parameters.hpp"

#include <filesystem>

#include <Teuchos_Array.hpp>

#include <cctype>

#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/derived_sets.hpp"
#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/mesh_parts.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/mesh/revolve.hpp"

namespace railfe {

std::string generator_sublist_name(const std::string& name) {
  std::string sublist = name;
  if (!sublist.empty())
    sublist[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sublist[0])));
  return sublist;
}

namespace {

ParameterSpec box_parameters() {
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
  return box;
}

const char* const kRevolvedDoc =
    "Type revolved: a quadrilateral cross-section revolved through 360 degrees about the y "
    "axis, the section point (r, a) going to (x, y, z) = (r cos θ, a, r sin θ), the seam "
    "merged. Each slice spans a chord, so the volume is n sin(2π/n)/2π of the exact body's "
    "for n elements around.";

ParameterSpec revolved_parameters() {
  ParameterSpec revolved(kRevolvedDoc);
  revolved.required_text(
      "Section file",
      "Gmsh .msh 4.1 ASCII mesh of the cross-section, relative to the deck's directory: "
      "quadrangles only, in the x-y plane with x = r > 0 and y = a. Physical surfaces become "
      "blocks; physical curves and points become node sets of their revolved nodes (and side "
      "sets where they follow the section's boundary).");
  revolved.integer("Elements around", 48, "Elements around the axis.", Range::at_least(3));
  return revolved;
}

// The types a single mesh source can have: everything but parts.
std::vector<Choice> source_types(const std::vector<MeshGeneratorDescriptor>& generators) {
  std::vector<Choice> types = {
      {"box", "generate a structured box (sublist Box)"},
      {"exodus", "read an Exodus II file (File)"},
      {"gmsh", "read a Gmsh .msh 4.1 ASCII file (File)"},
      {"revolved", "revolve a Gmsh cross-section about the y axis (sublist Revolved)"}};
  for (const auto& generator : generators) {
    types.push_back({generator.name, generator.summary + " (sublist " +
                                         generator_sublist_name(generator.name) + ")"});
  }
  return types;
}

// The parameters that say where one mesh comes from and which sets the deck derives on it:
// the same at the top level and in every part. \p where says which coordinates the derived
// sets use.
void add_source_parameters(ParameterSpec& spec, const std::vector<Choice>& types,
                           const std::vector<MeshGeneratorDescriptor>& generators,
                           const std::string& where) {
  spec.required_choice("Type", types, "Where the mesh comes from.");
  spec.text("File", "", "Mesh file for Type exodus or gmsh, relative to the deck's directory.");
  spec.real("Length scale", 1.0,
            "Factor applied to file coordinates (Type exodus, gmsh, revolved) to get metres "
            "(0.001 for a mesh in mm).",
            "", Range::positive());
  spec.sublist("Box", box_parameters(), "Generated box (Type box).");
  spec.sublist("Revolved", revolved_parameters(), kRevolvedDoc);
  for (const auto& generator : generators) {
    const ParameterSpec parameters = generator.parameters();
    spec.sublist(generator_sublist_name(generator.name), parameters,
                 "Type " + generator.name + ": " +
                     (parameters.doc().empty() ? generator.summary : parameters.doc()));
  }

  ParameterSpec node_set("A node set selected from the mesh: give Box, Point or Cylinder.");
  node_set.real_array("Box", {}, "Nodes inside {xmin, xmax, ymin, ymax, zmin, zmax}.", "m", 6);
  node_set.real_array("Point", {}, "The single node nearest to {x, y, z}.", "m", 3);
  node_set.real_array("Cylinder", {},
                      "Nodes within a radius of an axis: {x, y, z, ax, ay, az, radius}, a point "
                      "on the axis, its direction and the radius (a wheel's hub and web: its "
                      "axis y through the origin, a radius below the rim).",
                      "m", 7);
  node_set.text("Within", "", "Select only among this node set's nodes ('' = all nodes).");
  ParameterSpec side_set("A side set selected from the mesh's element faces.");
  side_set.required_real_array("Box",
                               "Faces whose nodes all lie in {xmin, xmax, ymin, ymax, "
                               "zmin, zmax}.",
                               "m", 6);
  side_set.text("Within", "", "Select only among this side set's faces ('' = all exterior faces).");
  spec.named_sublists("Node sets", node_set, "Node sets defined from geometry " + where + ".");
  spec.named_sublists("Side sets", side_set, "Side sets defined from geometry " + where + ".");
}

ParameterSpec part_parameters(const std::vector<MeshGeneratorDescriptor>& generators) {
  ParameterSpec part(
      "One part: a mesh of any Type but parts, with the same parameters and sublists as a "
      "top-level Mesh of that Type, placed by a rotation about an axis through the origin "
      "followed by a translation. Its blocks, node sets and side sets are renamed "
      "'<part>.<name>'.");
  add_source_parameters(part, source_types(generators), generators,
                        "in the part's own coordinates, before it is placed");
  part.real_array("Rotation axis", {0, 0, 1}, "Axis of the rotation, through the origin.", "", 3);
  part.real("Rotation angle", 0.0,
            "Angle of the rotation about Rotation axis (right-hand rule), applied first.",
            "degree");
  part.real_array("Translation", {0, 0, 0}, "Translation applied after the rotation.", "m", 3);
  return part;
}

}  // namespace

ParameterSpec mesh_parameters(const std::vector<MeshGeneratorDescriptor>& generators) {
  ParameterSpec spec("The mesh: generated, read from Exodus II or Gmsh, or assembled from parts.");
  std::vector<Choice> types = source_types(generators);
  std::vector<std::string> single_types;
  for (const auto& type : types)
    single_types.push_back(type.value);
  types.push_back({"parts", "assemble the model from several meshes (sublist Parts)"});
  add_source_parameters(spec, types, generators,
                        "(for Type parts: on the assembled model, in its coordinates; Within "
                        "may name a part's set as '<part>.<name>')");
  spec.named_sublists(
      "Parts", part_parameters(generators),
      "Type parts: the parts of the model, in order (nodes and elements are numbered part "
      "after part). Part names may not contain '.'. Parts share no nodes: coincident nodes of "
      "two parts stay distinct unless the deck ties them.");
  std::vector<std::string> source_entries = {"File", "Length scale", "Box", "Revolved"};
  for (const auto& generator : generators)
    source_entries.push_back(generator_sublist_name(generator.name));
  spec.only_when("Type", single_types, source_entries);
  spec.only_when("Type", {"parts"}, {"Parts"});
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

Mesh generate_from_deck(const Teuchos::ParameterList& section, const std::string& path,
                        const Deck& deck) {
  if (!section.isSublist("Box")) {
    throw_input_error(deck.source, path + "/Box", "missing required sublist for Type 'box'",
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
        deck.source, path + "/Box/Elements",
        "asks for " + std::to_string(static_cast<long long>(n_elements)) + " elements",
        "at most 2e8 elements");
  }
  return generate_box(spec);
}

// The sublist a generated type needs; absent only when its spec has required entries.
const Teuchos::ParameterList& type_sublist(const Teuchos::ParameterList& section,
                                           const std::string& name, const std::string& type,
                                           const std::string& path, const Deck& deck) {
  if (!section.isSublist(name)) {
    throw_input_error(deck.source, path + "/" + name,
                      "missing required sublist for Type '" + type + "'",
                      "a " + name + " sublist (see railfe --describe framework)");
  }
  return section.sublist(name);
}

Mesh revolve_from_deck(const Teuchos::ParameterList& section, const std::string& path,
                       const Deck& deck) {
  const auto& revolved = type_sublist(section, "Revolved", "revolved", path, deck);
  SectionMesh cross_section;
  try {
    cross_section = read_gmsh_section(deck.resolve(revolved.get<std::string>("Section file")));
  } catch (const InputError& error) {
    throw_input_error(deck.source, path + "/Revolved/Section file", error.what());
  }
  const double scale = section.get<double>("Length scale");
  for (double& x : cross_section.coordinates)
    x *= scale;
  return revolve(cross_section, revolved.get<int>("Elements around"));
}

Mesh read_from_deck(const Teuchos::ParameterList& section, const std::string& path,
                    const Deck& deck) {
  const auto type = section.get<std::string>("Type");
  const auto file = section.get<std::string>("File");
  if (file.empty()) {
    throw_input_error(deck.source, path + "/File", "missing mesh file for Type '" + type + "'",
                      "a path to the mesh file");
  }
  const std::string resolved = deck.resolve(file);
  if (std::filesystem::is_directory(resolved))
    throw_input_error(deck.source, path + "/File", "'" + resolved + "' is a directory",
                      "a " + type + " mesh file");
  // The reader names the file and line; the deck and the parameter that pointed there come
  // first, so the user knows which deck to mend.
  Mesh mesh;
  try {
    mesh = type == "exodus" ? read_exodus_mesh(resolved) : read_gmsh_mesh(resolved);
  } catch (const InputError& error) {
    throw_input_error(deck.source, path + "/File", error.what());
  }
  const double scale = section.get<double>("Length scale");
  for (double& x : mesh.coordinates)
    x *= scale;
  return mesh;
}

const MeshGeneratorDescriptor* find_generator(
    const std::vector<MeshGeneratorDescriptor>& generators, const std::string& type) {
  for (const auto& generator : generators) {
    if (generator.name == type)
      return &generator;
  }
  return nullptr;
}

// Replaces every occurrence of \p from in \p text by \p to.
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// Runs a registered generator. Generators name their parameters "Mesh/<Sublist>/..."; inside a
// part, messages and the mesh's source are re-rooted at the part's path so they point at the
// sublist the deck actually holds.
Mesh generate_with(const MeshGeneratorDescriptor& generator, const Teuchos::ParameterList& section,
                   const std::string& path, const Deck& deck) {
  const std::string name = generator_sublist_name(generator.name);
  const std::string written = deck.source + ": Mesh/" + name;
  const std::string meant = deck.source + ": " + path + "/" + name;
  try {
    Mesh mesh = generator.build(type_sublist(section, name, generator.name, path, deck), deck);
    mesh.source = replace_all(mesh.source, written, meant);
    return mesh;
  } catch (const InputError& error) {
    if (written == meant)
      throw;
    throw InputError(replace_all(error.what(), written, meant));
  }
}

std::vector<DerivedSetSpec> derived_sets(const Teuchos::ParameterList& section,
                                         const std::string& path) {
  std::vector<DerivedSetSpec> derived;
  const auto& node_sets = section.sublist("Node sets");
  for (auto it = node_sets.begin(); it != node_sets.end(); ++it) {
    const auto& entry = node_sets.sublist(node_sets.name(it));
    DerivedSetSpec spec;
    spec.name = node_sets.name(it);
    spec.path = path + "/Node sets/" + spec.name;
    spec.within = entry.get<std::string>("Within");
    const auto& box = entry.get<Teuchos::Array<double>>("Box");
    const auto& point = entry.get<Teuchos::Array<double>>("Point");
    const auto& cylinder = entry.get<Teuchos::Array<double>>("Cylinder");
    if (!box.empty())
      spec.box = array_of<6>(box);
    if (!point.empty())
      spec.point = array_of<3>(point);
    if (!cylinder.empty())
      spec.cylinder = array_of<7>(cylinder);
    derived.push_back(spec);
  }
  const auto& side_sets = section.sublist("Side sets");
  for (auto it = side_sets.begin(); it != side_sets.end(); ++it) {
    const auto& entry = side_sets.sublist(side_sets.name(it));
    DerivedSetSpec spec;
    spec.name = side_sets.name(it);
    spec.path = path + "/Side sets/" + spec.name;
    spec.side_set = true;
    spec.within = entry.get<std::string>("Within");
    spec.box = array_of<6>(entry.get<Teuchos::Array<double>>("Box"));
    derived.push_back(spec);
  }
  return derived;
}

// Builds the one mesh a validated section of any Type but parts describes (the top-level Mesh,
// or a part at \p path): reads or generates it, scales it, checks it and adds its derived sets.
Mesh build_source(const Teuchos::ParameterList& section, const std::string& path, const Deck& deck,
                  const std::vector<MeshGeneratorDescriptor>& generators) {
  const auto type = section.get<std::string>("Type");
  Mesh mesh;
  if (type == "box") {
    mesh = generate_from_deck(section, path, deck);
  } else if (type == "revolved") {
    mesh = revolve_from_deck(section, path, deck);
  } else if (const auto* generator = find_generator(generators, type)) {
    mesh = generate_with(*generator, section, path, deck);
  } else {
    mesh = read_from_deck(section, path, deck);
  }
  try {
    check_mesh(mesh);
  } catch (const InputError& error) {
    throw_input_error(deck.source, path, error.what());
  }
  add_derived_sets(mesh, derived_sets(section, path), deck.source);
  return mesh;
}

RigidPlacement placement_of(const Teuchos::ParameterList& part, const std::string& path,
                            const Deck& deck) {
  RigidPlacement placement;
  placement.axis = array_of<3>(part.get<Teuchos::Array<double>>("Rotation axis"));
  placement.angle_degrees = part.get<double>("Rotation angle");
  placement.translation = array_of<3>(part.get<Teuchos::Array<double>>("Translation"));
  const auto& a = placement.axis;
  if (!(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] > 0)) {
    throw_input_error(deck.source, path + "/Rotation axis", "has zero length",
                      "a non-zero vector {x, y, z}");
  }
  return placement;
}

// Builds every part in deck order, places it and appends it to one model.
Mesh assemble_parts(const Teuchos::ParameterList& section, const Deck& deck,
                    const std::vector<MeshGeneratorDescriptor>& generators) {
  const auto& parts = section.sublist("Parts");
  if (parts.numParams() == 0) {
    throw_input_error(deck.source, "Mesh/Parts", "has no parts for Type 'parts'",
                      "one sublist per part, each with its own Type");
  }
  Mesh model;
  model.source = deck.source + ": Mesh/Parts";
  for (auto it = parts.begin(); it != parts.end(); ++it) {
    const std::string name = parts.name(it);
    const std::string path = "Mesh/Parts/" + name;
    if (name.empty() || name.find('.') != std::string::npos) {
      throw_input_error(deck.source, path, "a part name may not be empty or contain '.'",
                        "a name without '.' (its sets are named '<part>.<set>')");
    }
    const auto& part = parts.sublist(name);
    const RigidPlacement placement = placement_of(part, path, deck);
    Mesh mesh = build_source(part, path, deck, generators);
    place_mesh(mesh, placement);
    append_part(model, mesh, name);
  }
  return model;
}

}  // namespace

Mesh build_mesh(const Teuchos::ParameterList& section, const Deck& deck,
                const std::vector<MeshGeneratorDescriptor>& generators) {
  if (section.get<std::string>("Type") != "parts")
    return build_source(section, "Mesh", deck, generators);
  Mesh model = assemble_parts(section, deck, generators);
  add_derived_sets(model, derived_sets(section, "Mesh"), deck.source);
  return model;
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
