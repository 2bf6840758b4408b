#include "physics/common/structural_sections.hpp"

#include <Teuchos_Array.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/app/model.hpp"
#include "framework/base/error.hpp"
#include "physics/elements/point_mass.hpp"

namespace railfe {

namespace {

const std::vector<std::string> kShapes = {"rectangle", "circle", "tube", "I"};

ParameterSpec section_parameters() {
  ParameterSpec s(
      "A section: what the listed beam2, spring2 or point_mass blocks are made of. Give only the "
      "parameters of its Element (and, for a beam, of its Shape).");
  s.required_text_array("Blocks", "Element blocks this section applies to.");
  s.required_choice(
      "Element",
      {{"beam", "beam2 blocks: Timoshenko beam (Euler-Bernoulli without shear deformation)"},
       {"spring-damper",
        "spring2 blocks: a spring-damper between the two nodes; one-node (point_mass) blocks: "
        "a spring-damper from each node to the ground"},
       {"point mass", "one-node (point_mass) blocks: a mass with rotary inertia at each node"}},
      "What the section describes.");
  // Beams.
  s.text("Material", "", "Beam: the name of an entry of Materials (E, nu, rho).");
  s.choice("Shape", "general",
           {{"rectangle", "solid rectangle: Width (local y) x Height (local z)"},
            {"circle", "solid circle: Diameter"},
            {"tube", "circular tube: Diameter (outer) and Wall thickness"},
            {"I",
             "doubly symmetric I: Depth (along local z), Flange width, Flange thickness, "
             "Web thickness"},
            {"general",
             "Area, Iy, Iz, Torsion constant given; Shear area y and z optional "
             "(left out: no shear deformation)"}},
           "Beam: the cross-section.");
  s.real("Width", 0, "Shape rectangle: side along local y.", "m", Range::positive());
  s.real("Height", 0, "Shape rectangle: side along local z.", "m", Range::positive());
  s.real("Diameter", 0, "Shape circle or tube: the (outer) diameter.", "m", Range::positive());
  s.real("Wall thickness", 0, "Shape tube: wall thickness (below the radius).", "m",
         Range::positive());
  s.real("Depth", 0, "Shape I: overall depth along local z (the web).", "m", Range::positive());
  s.real("Flange width", 0, "Shape I: flange width along local y.", "m", Range::positive());
  s.real("Flange thickness", 0, "Shape I: flange thickness.", "m", Range::positive());
  s.real("Web thickness", 0, "Shape I: web thickness.", "m", Range::positive());
  s.real("Area", 0, "Shape general: cross-section area A.", "m^2", Range::positive());
  s.real("Iy", 0, "Shape general: Iy = integral of z^2 dA (bending in the local x-z plane).", "m^4",
         Range::positive());
  s.real("Iz", 0, "Shape general: Iz = integral of y^2 dA (bending in the local x-y plane).", "m^4",
         Range::positive());
  s.real("Torsion constant", 0, "Shape general: Saint-Venant torsion constant J.", "m^4",
         Range::positive());
  s.real("Shear area y", 0,
         "Shape general: shear area along local y, kappa_y A (left out: no shear deformation).",
         "m^2", Range::positive());
  s.real("Shear area z", 0,
         "Shape general: shear area along local z, kappa_z A (left out: no shear deformation).",
         "m^2", Range::positive());
  s.flag("Shear deformation", true,
         "Shapes rectangle, circle, tube, I: Timoshenko with Cowper's shear areas; false: "
         "Euler-Bernoulli (no shear deformation).");
  s.real_array("Orientation", {0, 0, 1},
               "Beam: a vector giving the local y axis (its part normal to the beam); it may not "
               "lie along the beam.",
               "", 3);
  s.choice("Mass matrix", "consistent",
           {{"consistent", "from the Timoshenko interpolation"},
            {"lumped", "diagonal (HRZ lumping of the consistent one)"}},
           "Beam: how the mass matrix is formed.");
  s.flag("Rotary inertia", true,
         "Beam: add the rotary inertia rho I of the section to the bending mass (Rayleigh and "
         "Timoshenko beams); false: translational mass rho A only.");
  // Spring-dampers.
  s.real_array("Stiffness", {0, 0, 0, 0, 0, 0},
               "Spring-damper: k along local x, y, z (N/m), then about local x, y, z (N m/rad).",
               "", 6, Range::non_negative());
  s.real_array("Damping", {0, 0, 0, 0, 0, 0},
               "Spring-damper: c along local x, y, z (N s/m), then about local x, y, z "
               "(N m s/rad).",
               "", 6, Range::non_negative());
  s.real_array("Axes", {1, 0, 0, 0, 1, 0},
               "Spring-damper: the local x axis, then a vector whose part normal to it is the "
               "local y axis (global components); z = x cross y.",
               "", 6);
  // Point masses.
  s.real("Mass", 0, "Point mass: the mass at each node.", "kg", Range::non_negative());
  s.real_array(
      "Inertia", {},
      "Point mass: rotary inertia about its centre of mass in global axes, {Ixx, Iyy, Izz} or "
      "{Ixx, Iyy, Izz, Ixy, Iyz, Izx} (left out: none).",
      "kg m^2", 0);
  s.only_when("Element", {"beam"},
              {"Material", "Shape", "Orientation", "Mass matrix", "Rotary inertia"});
  s.only_when("Element", {"spring-damper"}, {"Stiffness", "Damping", "Axes"});
  s.real_array("Offset", {0, 0, 0},
               "Point mass: its centre of mass from the node (global axes); the node carries it "
               "rigidly (small rotations), Inertia being about the centre of mass.",
               "m", 3);
  s.only_when("Element", {"point mass"}, {"Mass", "Inertia", "Offset"});
  s.only_when("Shape", {"rectangle"}, {"Width", "Height"});
  s.only_when("Shape", {"circle", "tube"}, {"Diameter"});
  s.only_when("Shape", {"tube"}, {"Wall thickness"});
  s.only_when("Shape", {"I"}, {"Depth", "Flange width", "Flange thickness", "Web thickness"});
  s.only_when("Shape", {"general"},
              {"Area", "Iy", "Iz", "Torsion constant", "Shear area y", "Shear area z"});
  s.only_when("Shape", kShapes, {"Shear deformation"});
  return s;
}

Eigen::Vector3d vector3(const Teuchos::Array<double>& values, std::size_t first = 0) {
  return {values[first], values[first + 1], values[first + 2]};
}

// A value of the section \p list that its Shape needs: given, or an InputError.
double needed(const Teuchos::ParameterList& list, const std::string& name, const std::string& deck,
              const std::string& path) {
  if (list.getEntry(name).isDefault()) {
    throw_input_error(deck, path + "/" + name,
                      "missing: Shape '" + list.get<std::string>("Shape") + "' needs it",
                      "a positive value");
  }
  return list.get<double>(name);
}

BeamSection read_shape(const Teuchos::ParameterList& list, double poisson, const std::string& deck,
                       const std::string& path) {
  const auto shape = list.get<std::string>("Shape");
  const auto get = [&](const char* name) { return needed(list, name, deck, path); };
  BeamSection section;
  try {
    if (shape == "rectangle") {
      section = rectangle_section(get("Width"), get("Height"), poisson);
    } else if (shape == "circle") {
      section = circle_section(get("Diameter"), poisson);
    } else if (shape == "tube") {
      section = tube_section(get("Diameter"), get("Wall thickness"), poisson);
    } else if (shape == "I") {
      section = i_section(get("Depth"), get("Flange width"), get("Flange thickness"),
                          get("Web thickness"), poisson);
    } else {
      section.area = get("Area");
      section.iy = get("Iy");
      section.iz = get("Iz");
      section.torsion = get("Torsion constant");
      const double infinite = std::numeric_limits<double>::infinity();
      const bool y = !list.getEntry("Shear area y").isDefault();
      const bool z = !list.getEntry("Shear area z").isDefault();
      if (y != z) {
        throw_input_error(deck, path + (y ? "/Shear area z" : "/Shear area y"),
                          "missing while the other shear area is given",
                          "both shear areas (Timoshenko) or neither (Euler-Bernoulli)");
      }
      section.shear_area_y = y ? list.get<double>("Shear area y") : infinite;
      section.shear_area_z = z ? list.get<double>("Shear area z") : infinite;
    }
    if (shape != "general" && !list.get<bool>("Shear deformation"))
      section = euler_bernoulli(section);
    check_section(section);
  } catch (const std::invalid_argument& error) {
    throw_input_error(deck, path + "/Shape", "'" + shape + "': " + error.what(),
                      "dimensions that make a valid section");
  }
  return section;
}

BeamProperties read_beam(const Teuchos::ParameterList& list,
                         const Teuchos::ParameterList* materials, const std::string& deck,
                         const std::string& path) {
  BeamProperties beam;
  beam.material_name = list.get<std::string>("Material");
  if (beam.material_name.empty()) {
    throw_input_error(deck, path + "/Material", "missing: a beam needs a material",
                      "the name of an entry of Materials");
  }
  if (materials == nullptr || !materials->isSublist(beam.material_name)) {
    throw_input_error(deck, path + "/Material",
                      "'" + beam.material_name + "' is not an entry of Materials",
                      "the name of an entry of Materials (E, Poisson's ratio, Density)");
  }
  const auto& material = materials->sublist(beam.material_name);
  beam.poisson = material.get<double>("Poisson's ratio");
  beam.material = isotropic_beam_material(material.get<double>("Young's modulus"), beam.poisson,
                                          material.get<double>("Density"));
  beam.section = read_shape(list, beam.poisson, deck, path);
  beam.orientation = vector3(list.get<Teuchos::Array<double>>("Orientation"));
  if (!(beam.orientation.norm() > 0)) {
    throw_input_error(deck, path + "/Orientation", "is the zero vector",
                      "a vector giving the local y axis, not along the beam");
  }
  beam.mass =
      list.get<std::string>("Mass matrix") == "lumped" ? BeamMass::lumped : BeamMass::consistent;
  beam.rotary_inertia = list.get<bool>("Rotary inertia");
  return beam;
}

SpringDamper read_spring(const Teuchos::ParameterList& list, const std::string& deck,
                         const std::string& path) {
  SpringDamper spring;
  const auto& k = list.get<Teuchos::Array<double>>("Stiffness");
  const auto& c = list.get<Teuchos::Array<double>>("Damping");
  for (int i = 0; i < 6; ++i) {
    spring.stiffness[i] = k[i];
    spring.damping[i] = c[i];
  }
  const auto& axes = list.get<Teuchos::Array<double>>("Axes");
  const Eigen::Vector3d x = vector3(axes, 0), y = vector3(axes, 3);
  const Eigen::Vector3d normal = y - (y.dot(x) / std::max(x.squaredNorm(), 1e-300)) * x;
  if (!(x.norm() > 0) || !(normal.norm() > 1e-6 * y.norm())) {
    throw_input_error(deck, path + "/Axes", "does not define a frame (zero or parallel vectors)",
                      "{x axis, y vector} with y not along x, e.g. {1, 0, 0, 0, 1, 0}");
  }
  spring.axes.row(0) = x.normalized();
  spring.axes.row(1) = normal.normalized();
  spring.axes.row(2) = spring.axes.row(0).cross(spring.axes.row(1));
  return spring;
}

PointMassProperties read_point_mass(const Teuchos::ParameterList& list, const std::string& deck,
                                    const std::string& path) {
  PointMassProperties point;
  point.mass = list.get<double>("Mass");
  const auto& inertia = list.get<Teuchos::Array<double>>("Inertia");
  if (inertia.size() == 3 || inertia.size() == 6) {
    point.inertia.diagonal() = vector3(inertia);
    if (inertia.size() == 6) {
      point.inertia(0, 1) = point.inertia(1, 0) = inertia[3];
      point.inertia(1, 2) = point.inertia(2, 1) = inertia[4];
      point.inertia(2, 0) = point.inertia(0, 2) = inertia[5];
    }
  } else if (!inertia.empty()) {
    throw_input_error(deck, path + "/Inertia", "has " + std::to_string(inertia.size()) + " entries",
                      "3 entries {Ixx, Iyy, Izz} or 6 {Ixx, Iyy, Izz, Ixy, Iyz, Izx}");
  }
  if (!(point.mass > 0) && point.inertia.isZero()) {
    throw_input_error(deck, path + "/Mass", "missing: the point mass has neither mass nor inertia",
                      "a positive Mass, an Inertia, or both");
  }
  point.offset = vector3(list.get<Teuchos::Array<double>>("Offset"));
  try {
    point_mass_matrix(point.mass, point.inertia, point.offset);
  } catch (const std::invalid_argument& error) {
    throw_input_error(deck, path + "/Inertia", error.what(),
                      "a symmetric positive semi-definite inertia tensor");
  }
  return point;
}

// Whether a section of \p kind may apply to a block of \p type.
bool fits(StructuralKind kind, ElementType type) {
  switch (kind) {
    case StructuralKind::beam:
      return type == ElementType::beam2;
    case StructuralKind::spring:
      return type == ElementType::spring2 || type == ElementType::point_mass;
    case StructuralKind::point_mass:
      return type == ElementType::point_mass;
  }
  return false;
}

}  // namespace

ParameterSpec sections_parameters() {
  ParameterSpec sections(
      "Sections of the structural blocks (beam2, spring2, point_mass), one sublist each, under a "
      "name of your choice.");
  const ParameterSpec each = section_parameters();
  sections.list()->set(kAnyName, *each.list(), each.doc());
  return sections;
}

bool is_structural_type(ElementType type) {
  return type == ElementType::beam2 || type == ElementType::spring2 ||
         type == ElementType::point_mass;
}

bool has_structural_blocks(const Mesh& mesh) {
  for (const auto& block : mesh.blocks)
    if (is_structural_type(block.type))
      return true;
  return false;
}

bool has_solid_blocks(const Mesh& mesh) {
  for (const auto& block : mesh.blocks)
    if (block.type == ElementType::hex8)
      return true;
  return false;
}

SectionTable::SectionTable(const Teuchos::ParameterList& sections,
                           const Teuchos::ParameterList* materials, const Mesh& mesh,
                           const std::string& deck)
    : assignment_(mesh.blocks.size(), -1) {
  for (auto it = sections.begin(); it != sections.end(); ++it) {
    StructuralSection section;
    section.name = sections.name(it);
    const std::string path = "Sections/" + section.name;
    const auto& list = sections.sublist(section.name);
    const auto element = list.get<std::string>("Element");
    if (element == "beam") {
      section.kind = StructuralKind::beam;
      section.beam = read_beam(list, materials, deck, path);
    } else if (element == "spring-damper") {
      section.kind = StructuralKind::spring;
      section.spring = read_spring(list, deck, path);
    } else {
      section.kind = StructuralKind::point_mass;
      section.point = read_point_mass(list, deck, path);
    }
    const int index = static_cast<int>(sections_.size());
    for (const auto& block_name : list.get<Teuchos::Array<std::string>>("Blocks")) {
      const int block = mesh.block_index(block_name, deck, path + "/Blocks");
      const ElementType type = mesh.blocks[block].type;
      if (!fits(section.kind, type)) {
        throw_input_error(deck, path + "/Blocks",
                          "block '" + block_name + "' holds " + element_type_name(type) +
                              " elements, which a '" + element + "' section does not describe",
                          "beam: BEAM2 blocks; spring-damper: SPRING2 or one-node blocks; "
                          "point mass: one-node blocks");
      }
      if (assignment_[block] >= 0) {
        throw_input_error(deck, path + "/Blocks",
                          "block '" + block_name + "' already has section '" +
                              sections_[assignment_[block]].name + "'",
                          "one section per block");
      }
      assignment_[block] = index;
    }
    sections_.push_back(section);
  }
}

void SectionTable::require_structural_blocks(const Mesh& mesh, const std::string& deck) const {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (is_structural_type(mesh.blocks[b].type) && assignment_[b] < 0) {
      throw_input_error(deck, "Sections",
                        "block '" + mesh.blocks[b].name + "' (" +
                            element_type_name(mesh.blocks[b].type) + ") has no section",
                        "list it under Blocks of one of the Sections");
    }
  }
}

BeamElement make_beam(const double* a, const double* b, const BeamProperties& beam) {
  return BeamElement(Eigen::Vector3d(a[0], a[1], a[2]), Eigen::Vector3d(b[0], b[1], b[2]),
                     beam.orientation, beam.material, beam.section, beam.rotary_inertia);
}

void SectionTable::check_elements(const Mesh& mesh, const std::string& deck) const {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const ElementBlock& block = mesh.blocks[b];
    if (assignment_[b] < 0 || of_block(static_cast<int>(b)).kind != StructuralKind::beam)
      continue;
    const StructuralSection& section = of_block(static_cast<int>(b));
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      try {
        make_beam(&mesh.coordinates[3 * nodes[0]], &mesh.coordinates[3 * nodes[1]], section.beam);
      } catch (const std::invalid_argument& error) {
        throw_input_error(deck, "Sections/" + section.name,
                          "block '" + block.name + "', element " +
                              std::to_string(block.first_element + e + 1) + " (nodes " +
                              std::to_string(nodes[0] + 1) + ", " + std::to_string(nodes[1] + 1) +
                              "): " + error.what(),
                          "distinct nodes and an Orientation not along the beam");
      }
    }
  }
}

std::vector<char> massless_components(const Mesh& mesh, const SectionTable& sections) {
  std::vector<char> massless(6 * static_cast<std::size_t>(mesh.n_nodes()), 1);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const ElementBlock& block = mesh.blocks[b];
    if (!sections.has_section(static_cast<int>(b)))
      continue;
    const StructuralSection& section = sections.of_block(static_cast<int>(b));
    std::array<bool, 6> mass{};  // which components the block's elements give mass
    if (section.kind == StructuralKind::beam) {
      mass.fill(section.beam.material.density > 0);
    } else if (section.kind == StructuralKind::point_mass) {
      for (int c = 0; c < 3; ++c) {
        mass[c] = section.point.mass > 0;
        mass[3 + c] =
            section.point.inertia(c, c) > 0 ||
            (section.point.mass > 0 && section.point.offset.squaredNorm() >
                                           section.point.offset(c) * section.point.offset(c));
      }
    }
    for (GlobalIndex node : block.connectivity)
      for (int c = 0; c < 6; ++c)
        if (mass[c])
          massless[6 * static_cast<std::size_t>(node) + c] = 0;
  }
  return massless;
}

SectionTable structural_sections(const Model& model, const std::string& step) {
  const std::string& deck = model.deck().source;
  if (!model.has_section("Sections")) {
    throw_input_error(
        deck, "Sections",
        "missing: " + step + " needs a section for every beam2, spring2 and point_mass block",
        "a Sections section");
  }
  const Teuchos::ParameterList* materials =
      model.has_section("Materials") ? &model.section("Materials") : nullptr;
  SectionTable table(model.section("Sections"), materials, model.mesh(), deck);
  table.require_structural_blocks(model.mesh(), deck);
  table.check_elements(model.mesh(), deck);
  return table;
}

}  // namespace railfe
