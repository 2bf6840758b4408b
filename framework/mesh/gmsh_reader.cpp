#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "framework/base/error.hpp"
#include "framework/mesh/hex8_topology.hpp"
#include "framework/mesh/mesh_readers.hpp"

namespace railfe {

namespace {

// Reads whitespace-separated tokens and remembers the line, so every error can point at it.
class TokenReader {
 public:
  TokenReader(std::string text, std::string path)
      : text_(std::move(text)), path_(std::move(path)) {}

  bool at_end() {
    skip_space();
    return position_ >= text_.size();
  }

  std::string word() {
    skip_space();
    if (position_ >= text_.size())
      fail("unexpected end of file");
    const std::size_t start = position_;
    if (text_[position_] == '"') {
      const std::size_t close = text_.find('"', position_ + 1);
      if (close == std::string::npos)
        fail("unterminated quoted name");
      position_ = close + 1;
      return text_.substr(start + 1, close - start - 1);
    }
    while (position_ < text_.size() &&
           !std::isspace(static_cast<unsigned char>(text_[position_]))) {
      ++position_;
    }
    return text_.substr(start, position_ - start);
  }

  long long integer() {
    const std::string token = word();
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(token.c_str(), &end, 10);
    if (errno != 0 || *end != '\0')
      fail("expected an integer, found '" + token + "'");
    return value;
  }

  double real() {
    const std::string token = word();
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (*end != '\0')
      fail("expected a number, found '" + token + "'");
    return value;
  }

  void expect(const std::string& token) {
    const std::string found = word();
    if (found != token)
      fail("expected '" + token + "', found '" + found + "'");
  }

  void skip_section(const std::string& name) {
    const std::string end_tag = "$End" + name.substr(1);
    while (word() != end_tag) {
    }
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw_input_error(path_, "line " + std::to_string(line_), problem,
                      "Gmsh .msh version 4.1 ASCII (gmsh -format msh41)");
  }

 private:
  void skip_space() {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) {
      if (text_[position_] == '\n')
        ++line_;
      ++position_;
    }
  }

  std::string text_;
  std::string path_;
  std::size_t position_ = 0;
  int line_ = 1;
};

// Nodes per element of the Gmsh element types railfe reads or must skip over.
int gmsh_nodes_per_element(int type) {
  switch (type) {
    case 1:
      return 2;  // line
    case 2:
      return 3;  // triangle
    case 3:
      return 4;  // quadrangle
    case 4:
      return 4;  // tetrahedron
    case 5:
      return 8;  // hexahedron
    case 6:
      return 6;  // prism
    case 7:
      return 5;  // pyramid
    case 15:
      return 1;  // point
    default:
      return -1;
  }
}

const char* gmsh_type_name(int type) {
  switch (type) {
    case 2:
      return "triangle";
    case 5:
      return "hexahedron";
    case 4:
      return "tetrahedron";
    case 6:
      return "prism";
    case 7:
      return "pyramid";
    default:
      return "higher-order or unknown element";
  }
}

using EntityKey = std::pair<int, int>;  // (dimension, entity tag)

struct GmshContent {
  bool planar = false;  // a 2-D section: quadrangles are the elements, there are no volumes
  std::map<EntityKey, std::string> physical_names;         // (dim, physical tag) -> name
  std::map<EntityKey, std::vector<int>> entity_physicals;  // (dim, entity) -> physical tags
  std::vector<double> coordinates;
  std::unordered_map<long long, GlobalIndex> node_index;  // Gmsh node tag -> railfe index
  // Hexahedra per block name, and the block id to write.
  std::map<std::string, std::vector<std::array<GlobalIndex, 8>>> hexes;
  std::map<std::string, int> block_ids;
  std::map<std::string, std::vector<std::array<GlobalIndex, 4>>> quads;  // per physical surface
  // Planar meshes: quadrangles per block name (physical surface, else surface entity).
  std::map<std::string, std::vector<std::array<GlobalIndex, 4>>> section_quads;
  std::map<std::string, std::set<GlobalIndex>> set_nodes;  // per physical group
  std::map<std::string, int> set_ids;
  // 2-node lines per physical curve: the beam2 blocks of a mesh without hexahedra; a curve in
  // two physical curves would give its elements twice.
  std::map<std::string, std::vector<std::array<GlobalIndex, 2>>> lines;
  std::string shared_curve;
};

std::string physical_name(const GmshContent& content, int dim, int tag) {
  auto it = content.physical_names.find({dim, tag});
  if (it != content.physical_names.end())
    return it->second;
  static const char* kPrefix[4] = {"point_", "curve_", "surface_", "volume_"};
  return kPrefix[dim] + std::to_string(tag);
}

void read_physical_names(TokenReader& in, GmshContent& content) {
  const long long count = in.integer();
  for (long long i = 0; i < count; ++i) {
    const int dim = static_cast<int>(in.integer());
    const int tag = static_cast<int>(in.integer());
    content.physical_names[{dim, tag}] = in.word();
  }
  in.expect("$EndPhysicalNames");
}

void read_entities(TokenReader& in, GmshContent& content) {
  long long counts[4];
  for (auto& count : counts)
    count = in.integer();
  for (int dim = 0; dim < 4; ++dim) {
    for (long long i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(in.integer());
      const int n_coordinates = dim == 0 ? 3 : 6;
      for (int c = 0; c < n_coordinates; ++c)
        in.real();
      const long long n_physicals = in.integer();
      auto& physicals = content.entity_physicals[{dim, tag}];
      for (long long p = 0; p < n_physicals; ++p) {
        physicals.push_back(static_cast<int>(std::llabs(in.integer())));
      }
      if (dim > 0) {
        const long long n_bounding = in.integer();
        for (long long b = 0; b < n_bounding; ++b)
          in.integer();
      }
    }
  }
  in.expect("$EndEntities");
}

void read_nodes(TokenReader& in, GmshContent& content) {
  const long long n_blocks = in.integer();
  const long long n_nodes = in.integer();
  in.integer();  // smallest tag
  in.integer();  // largest tag
  content.coordinates.reserve(3 * n_nodes);
  content.node_index.reserve(n_nodes);
  for (long long b = 0; b < n_blocks; ++b) {
    in.integer();  // entity dimension
    in.integer();  // entity tag
    const long long parametric = in.integer();
    const long long count = in.integer();
    std::vector<long long> tags(count);
    for (auto& tag : tags)
      tag = in.integer();
    for (long long i = 0; i < count; ++i) {
      const GlobalIndex index = static_cast<GlobalIndex>(content.coordinates.size() / 3);
      if (!content.node_index.emplace(tags[i], index).second) {
        in.fail("node tag " + std::to_string(tags[i]) + " appears twice");
      }
      for (int d = 0; d < 3; ++d)
        content.coordinates.push_back(in.real());
      if (parametric != 0)
        in.fail("parametric node coordinates are not supported");
    }
  }
  in.expect("$EndNodes");
}

GlobalIndex node_of(TokenReader& in, const GmshContent& content, long long tag) {
  auto it = content.node_index.find(tag);
  if (it == content.node_index.end()) {
    in.fail("element refers to node tag " + std::to_string(tag) + ", which is not in $Nodes");
  }
  return it->second;
}

// The name a block of a volume (dim 3) or, in a planar mesh, a surface (dim 2) gets; records its
// id.
std::string block_of_entity(TokenReader& in, GmshContent& content, int dim, int entity) {
  const auto& physicals = content.entity_physicals[{dim, entity}];
  const char* kind = dim == 3 ? "volume" : "surface";
  if (physicals.size() > 1) {
    in.fail(std::string(kind) + " " + std::to_string(entity) + " belongs to " +
            std::to_string(physicals.size()) + " physical groups; an element block needs one");
  }
  const int tag = physicals.empty() ? entity : physicals[0];
  const std::string name = physicals.empty() ? std::string(kind) + "_" + std::to_string(entity)
                                             : physical_name(content, dim, tag);
  content.block_ids.emplace(name, tag);
  return name;
}

// One element block of a planar mesh: quadrangles form blocks, points and lines of physical
// groups form node sets.
void read_section_elements(TokenReader& in, GmshContent& content, int dim, int entity, int type,
                           long long count) {
  if (dim == 3 || (dim == 2 && type != 3) || gmsh_nodes_per_element(type) < 0) {
    in.fail(std::string(gmsh_type_name(type)) + " elements (Gmsh type " + std::to_string(type) +
            ") in entity " + std::to_string(entity) + " of dimension " + std::to_string(dim) +
            "; a cross-section mesh holds only quadrangles (use Recombine)");
  }
  const int n_nodes = gmsh_nodes_per_element(type);
  const auto& physicals = content.entity_physicals[{dim, entity}];
  const std::string block_name = dim == 2 ? block_of_entity(in, content, dim, entity) : "";
  for (long long e = 0; e < count; ++e) {
    in.integer();  // element tag
    std::array<GlobalIndex, 4> nodes{};
    for (int a = 0; a < n_nodes; ++a)
      nodes[a] = node_of(in, content, in.integer());
    if (dim == 2) {
      content.section_quads[block_name].push_back(nodes);
      continue;
    }
    for (int physical : physicals) {
      const std::string name = physical_name(content, dim, physical);
      content.set_ids.emplace(name, physical);
      content.set_nodes[name].insert(nodes.begin(), nodes.begin() + n_nodes);
    }
  }
}

void read_elements(TokenReader& in, GmshContent& content) {
  const long long n_blocks = in.integer();
  in.integer();  // element count
  in.integer();  // smallest tag
  in.integer();  // largest tag
  for (long long b = 0; b < n_blocks; ++b) {
    const int dim = static_cast<int>(in.integer());
    const int entity = static_cast<int>(in.integer());
    const int type = static_cast<int>(in.integer());
    const long long count = in.integer();
    const int n_nodes = gmsh_nodes_per_element(type);
    const auto& physicals = content.entity_physicals[{dim, entity}];
    if (content.planar) {
      read_section_elements(in, content, dim, entity, type, count);
      continue;
    }
    if (n_nodes < 0 || (dim == 3 && type != 5)) {
      in.fail(std::string(gmsh_type_name(type)) + " elements (Gmsh type " + std::to_string(type) +
              ") in volume " + std::to_string(entity) +
              " are not supported; railfe solids are 8-node hexahedra (use transfinite "
              "meshing with Recombine)");
    }
    if (dim == 2 && type == 2 && !physicals.empty()) {
      in.fail("triangles in a physical surface cannot form a side set of hexahedra");
    }
    const std::string block_name = dim == 3 ? block_of_entity(in, content, dim, entity) : "";
    if (dim == 1 && type == 1 && physicals.size() > 1)
      content.shared_curve = "curve " + std::to_string(entity);
    for (long long e = 0; e < count; ++e) {
      in.integer();  // element tag
      std::array<GlobalIndex, 8> nodes{};
      for (int a = 0; a < n_nodes; ++a)
        nodes[a] = node_of(in, content, in.integer());
      if (dim == 3) {
        content.hexes[block_name].push_back(nodes);
        continue;
      }
      for (int physical : physicals) {
        const std::string name = physical_name(content, dim, physical);
        content.set_ids.emplace(name, physical);
        content.set_nodes[name].insert(nodes.begin(), nodes.begin() + n_nodes);
        if (dim == 2)
          content.quads[name].push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
        if (dim == 1 && type == 1)
          content.lines[name].push_back({nodes[0], nodes[1]});
      }
    }
  }
  in.expect("$EndElements");
}

struct FaceKeyHash {
  std::size_t operator()(const std::array<GlobalIndex, 4>& key) const {
    std::size_t hash = 0;
    for (GlobalIndex node : key)
      hash = hash * 1000003u ^ static_cast<std::size_t>(node);
    return hash;
  }
};

void build_side_sets(const GmshContent& content, Mesh& mesh) {
  using Key = std::array<GlobalIndex, 4>;
  std::unordered_map<Key, Side, FaceKeyHash> wanted;
  for (const auto& [name, quads] : content.quads) {
    for (Key quad : quads) {
      std::sort(quad.begin(), quad.end());
      wanted.emplace(quad, Side{-1, -1});
    }
  }
  if (wanted.empty())
    return;
  for (const auto& block : mesh.blocks) {
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      const GlobalIndex* nodes = block.element_nodes(e);
      for (int face = 0; face < 6; ++face) {
        Key key;
        for (int k = 0; k < 4; ++k)
          key[k] = nodes[kHex8FaceNodes[face][k]];
        std::sort(key.begin(), key.end());
        auto it = wanted.find(key);
        if (it != wanted.end())
          it->second = {block.first_element + e, face};
      }
    }
  }
  for (const auto& [name, quads] : content.quads) {
    SideSet set{name, content.set_ids.at(name), {}};
    for (Key quad : quads) {
      std::sort(quad.begin(), quad.end());
      const Side side = wanted.at(quad);
      if (side.element < 0) {
        throw_input_error(mesh.source, "physical surface " + name,
                          "a quadrangle is not a face of any hexahedron",
                          "surfaces that bound the meshed volumes");
      }
      set.sides.push_back(side);
    }
    mesh.side_sets.push_back(std::move(set));
  }
}

GmshContent parse_file(const std::string& path, bool planar) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw_input_error(path, "", "mesh file not found or not readable");
  std::ostringstream buffer;
  buffer << file.rdbuf();
  TokenReader in(buffer.str(), path);
  GmshContent content;
  content.planar = planar;

  bool saw_format = false;
  while (!in.at_end()) {
    const std::string section = in.word();
    if (section == "$MeshFormat") {
      const std::string version = in.word();
      const long long binary = in.integer();
      in.integer();  // size of double
      if (version != "4.1")
        in.fail("mesh format version " + version + " is not supported");
      if (binary != 0)
        in.fail("binary .msh files are not supported");
      in.expect("$EndMeshFormat");
      saw_format = true;
    } else if (!saw_format) {
      in.fail("the file does not start with $MeshFormat");
    } else if (section == "$PhysicalNames") {
      read_physical_names(in, content);
    } else if (section == "$Entities") {
      read_entities(in, content);
    } else if (section == "$Nodes") {
      read_nodes(in, content);
    } else if (section == "$Elements") {
      read_elements(in, content);
    } else if (!section.empty() && section[0] == '$') {
      in.skip_section(section);
    } else {
      in.fail("unexpected '" + section + "' outside a section");
    }
  }
  if (!saw_format)
    in.fail("empty file");
  return content;
}

}  // namespace

Mesh read_gmsh_mesh(const std::string& path) {
  GmshContent content = parse_file(path, false);
  Mesh mesh;
  mesh.source = path;
  mesh.coordinates = std::move(content.coordinates);
  for (const auto& [name, hexes] : content.hexes) {
    ElementBlock block;
    block.name = name;
    block.id = content.block_ids.at(name);
    block.type = ElementType::hex8;
    for (const auto& hex : hexes)
      block.add_element(hex.data(), 8);
    mesh.blocks.push_back(std::move(block));
  }
  // Without hexahedra, a line model: physical curves are beam2 blocks (their nodes also a node
  // set, as always).
  if (content.hexes.empty()) {
    if (!content.lines.empty() && !content.shared_curve.empty())
      throw_input_error(path, "", content.shared_curve + " lies in two physical curves",
                        "each curve in one physical curve, whose lines become a beam2 block");
    for (const auto& [name, lines] : content.lines) {
      ElementBlock block{name, content.set_ids.at(name), ElementType::beam2, 0, {0}, {}};
      for (const auto& line : lines)
        block.add_element(line.data(), 2);
      mesh.blocks.push_back(std::move(block));
    }
  }
  mesh.number_blocks();
  for (const auto& [name, nodes] : content.set_nodes) {
    mesh.node_sets.push_back({name, content.set_ids.at(name), {nodes.begin(), nodes.end()}});
  }
  build_side_sets(content, mesh);
  return mesh;
}

SectionMesh read_gmsh_section(const std::string& path) {
  const GmshContent content = parse_file(path, true);
  if (content.section_quads.empty()) {
    throw_input_error(path, "", "holds no quadrangles",
                      "a 2-D mesh of quadrangles in the x-y plane (gmsh -2 with Recombine)");
  }
  // Only nodes of quadrangles are kept (geometry points such as arc centres are dropped), and
  // they are renumbered in order of first use.
  const GlobalIndex n_file_nodes = static_cast<GlobalIndex>(content.coordinates.size() / 3);
  std::vector<GlobalIndex> renumbered(n_file_nodes, -1);
  SectionMesh section;
  section.source = path;
  double extent = 0;
  for (double x : content.coordinates)
    extent = std::max(extent, std::abs(x));
  for (const auto& [name, quads] : content.section_quads) {
    const int block = static_cast<int>(section.blocks.size());
    section.blocks.push_back({name, content.block_ids.at(name)});
    for (auto quad : quads) {
      for (GlobalIndex& node : quad) {
        if (renumbered[node] < 0) {
          const double* x = &content.coordinates[3 * node];
          if (std::abs(x[2]) > 1e-9 * extent) {
            throw_input_error(path,
                              "node at (" + std::to_string(x[0]) + ", " + std::to_string(x[1]) +
                                  ", " + std::to_string(x[2]) + ")",
                              "lies off the x-y plane", "a section in the plane z = 0");
          }
          renumbered[node] = section.n_nodes();
          section.coordinates.push_back(x[0]);
          section.coordinates.push_back(x[1]);
        }
        node = renumbered[node];
      }
      section.quads.push_back(quad);
      section.quad_blocks.push_back(block);
    }
  }
  for (const auto& [name, nodes] : content.set_nodes) {
    NodeSet set{name, content.set_ids.at(name), {}};
    for (GlobalIndex node : nodes) {
      if (renumbered[node] >= 0)
        set.nodes.push_back(renumbered[node]);
    }
    std::sort(set.nodes.begin(), set.nodes.end());
    section.node_sets.push_back(std::move(set));
  }
  return section;
}

}  // namespace railfe
