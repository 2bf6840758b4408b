#include "framework/output/exodus_writer.hpp"

#include <exodusII.h>

#include <stdexcept>

#include "framework/mesh/exodus_file.hpp"

namespace railfe {

namespace {

// Exodus stores names of at most 32 characters by default.
std::string short_name(const std::string& name) {
  return name.substr(0, 32);
}

void put_names(const ExodusFile& file, ex_entity_type type, const std::vector<std::string>& names) {
  if (names.empty())
    return;
  std::vector<std::string> trimmed;
  for (const auto& name : names)
    trimmed.push_back(short_name(name));
  std::vector<char*> pointers;
  for (auto& name : trimmed)
    pointers.push_back(name.data());
  file.check(ex_put_names(file.id(), type, pointers.data()), "writing names");
}

void put_variable_names(const ExodusFile& file, ex_entity_type type,
                        const std::vector<std::string>& names) {
  if (names.empty())
    return;
  file.check(ex_put_variable_param(file.id(), type, static_cast<int>(names.size())),
             "declaring variables");
  std::vector<std::string> trimmed;
  for (const auto& name : names)
    trimmed.push_back(short_name(name));
  std::vector<char*> pointers;
  for (auto& name : trimmed)
    pointers.push_back(name.data());
  file.check(
      ex_put_variable_names(file.id(), type, static_cast<int>(names.size()), pointers.data()),
      "writing variable names");
}

}  // namespace

ExodusWriter::ExodusWriter(const std::string& path, const Mesh& mesh, const std::string& title,
                           const std::vector<std::string>& nodal_variables,
                           const std::vector<std::string>& element_variables, bool active)
    : mesh_(&mesh), n_nodal_(nodal_variables.size()), n_element_(element_variables.size()) {
  if (!active)
    return;
  file_ = std::make_unique<ExodusFile>(path, ExodusMode::create);
  const ExodusFile& file = *file_;
  file.check(ex_put_init(file.id(), title.substr(0, MAX_LINE_LENGTH).c_str(), 3, mesh.n_nodes(),
                         mesh.n_elements(), static_cast<int64_t>(mesh.blocks.size()),
                         static_cast<int64_t>(mesh.node_sets.size()),
                         static_cast<int64_t>(mesh.side_sets.size())),
             "writing the header");

  const GlobalIndex n_nodes = mesh.n_nodes();
  std::vector<double> x(n_nodes), y(n_nodes), z(n_nodes);
  for (GlobalIndex i = 0; i < n_nodes; ++i) {
    x[i] = mesh.coordinates[3 * i];
    y[i] = mesh.coordinates[3 * i + 1];
    z[i] = mesh.coordinates[3 * i + 2];
  }
  file.check(ex_put_coord(file.id(), x.data(), y.data(), z.data()), "writing coordinates");
  const char* axis_names[3] = {"x", "y", "z"};
  file.check(ex_put_coord_names(file.id(), const_cast<char**>(axis_names)), "writing axes");

  // Ids are renumbered 1..n: readers may give files with clashing ids, Exodus needs unique ones.
  std::vector<std::string> names;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const int per_element = block.n_elements() > 0 ? block.n_element_nodes(0) : 0;
    file.check(ex_put_block(file.id(), EX_ELEM_BLOCK, b + 1, element_type_name(block.type).c_str(),
                            block.n_elements(), per_element, 0, 0, 0),
               "writing block " + block.name);
    std::vector<int64_t> connectivity(block.connectivity.begin(), block.connectivity.end());
    for (auto& node : connectivity)
      node += 1;
    if (!connectivity.empty()) {
      file.check(
          ex_put_conn(file.id(), EX_ELEM_BLOCK, b + 1, connectivity.data(), nullptr, nullptr),
          "writing connectivity of block " + block.name);
    }
    names.push_back(block.name);
  }
  put_names(file, EX_ELEM_BLOCK, names);

  names.clear();
  for (std::size_t s = 0; s < mesh.node_sets.size(); ++s) {
    const auto& set = mesh.node_sets[s];
    file.check(ex_put_set_param(file.id(), EX_NODE_SET, s + 1, set.nodes.size(), 0),
               "writing node set " + set.name);
    std::vector<int64_t> nodes(set.nodes.begin(), set.nodes.end());
    for (auto& node : nodes)
      node += 1;
    if (!nodes.empty()) {
      file.check(ex_put_set(file.id(), EX_NODE_SET, s + 1, nodes.data(), nullptr),
                 "writing node set " + set.name);
    }
    names.push_back(set.name);
  }
  put_names(file, EX_NODE_SET, names);

  names.clear();
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s) {
    const auto& set = mesh.side_sets[s];
    file.check(ex_put_set_param(file.id(), EX_SIDE_SET, s + 1, set.sides.size(), 0),
               "writing side set " + set.name);
    std::vector<int64_t> elements, faces;
    for (const Side& side : set.sides) {
      elements.push_back(side.element + 1);
      faces.push_back(side.face + 1);
    }
    if (!elements.empty()) {
      file.check(ex_put_set(file.id(), EX_SIDE_SET, s + 1, elements.data(), faces.data()),
                 "writing side set " + set.name);
    }
    names.push_back(set.name);
  }
  put_names(file, EX_SIDE_SET, names);

  put_variable_names(file, EX_NODAL, nodal_variables);
  put_variable_names(file, EX_ELEM_BLOCK, element_variables);
}

ExodusWriter::~ExodusWriter() = default;

void ExodusWriter::write_step(double time, const std::vector<std::vector<double>>& nodal,
                              const std::vector<std::vector<double>>& element) {
  if (!file_)
    return;
  if (nodal.size() != n_nodal_ || element.size() != n_element_) {
    throw std::logic_error("railfe: ExodusWriter::write_step got the wrong number of fields");
  }
  const ExodusFile& file = *file_;
  ++step_;
  file.check(ex_put_time(file.id(), step_, &time), "writing time");
  for (std::size_t v = 0; v < n_nodal_; ++v) {
    file.check(ex_put_var(file.id(), step_, EX_NODAL, static_cast<int>(v + 1), 1, mesh_->n_nodes(),
                          nodal[v].data()),
               "writing a nodal variable");
  }
  for (std::size_t v = 0; v < n_element_; ++v) {
    for (std::size_t b = 0; b < mesh_->blocks.size(); ++b) {
      const auto& block = mesh_->blocks[b];
      if (block.n_elements() == 0)
        continue;
      file.check(ex_put_var(file.id(), step_, EX_ELEM_BLOCK, static_cast<int>(v + 1), b + 1,
                            block.n_elements(), element[v].data() + block.first_element),
                 "writing an element variable");
    }
  }
  ex_update(file.id());
}

void ExodusWriter::close() {
  if (file_)
    file_->close();
}

}  // namespace railfe
