#include "regression/compare/result_files.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "framework/mesh/exodus_file.hpp"
#include "framework/mesh/mesh_readers.hpp"
#include "framework/output/csv_writer.hpp"

namespace railfe {

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name)
      return i;
  }
  std::string known;
  for (const auto& column : columns)
    known += " " + column;
  throw std::runtime_error("no column '" + name + "'; columns:" + known);
}

CsvTable read_csv(const std::string& path) {
  std::ifstream file(path);
  if (!file)
    throw std::runtime_error("cannot read '" + path + "'");
  CsvTable table;
  std::string line;
  if (!std::getline(file, line))
    throw std::runtime_error("'" + path + "' is empty");
  table.columns = CsvWriter::cells(line);
  while (std::getline(file, line)) {
    if (line.empty())
      continue;
    auto cells = CsvWriter::cells(line);
    if (cells.size() != table.columns.size()) {
      throw std::runtime_error("'" + path + "' has a row of " + std::to_string(cells.size()) +
                               " cells under " + std::to_string(table.columns.size()) + " columns");
    }
    table.rows.push_back(std::move(cells));
  }
  return table;
}

bool parse_number(const std::string& cell, double& value) {
  if (cell.empty())
    return false;
  char* end = nullptr;
  value = std::strtod(cell.c_str(), &end);
  return end != cell.c_str() && *end == '\0';
}

namespace {

std::vector<std::string> variable_names(const ExodusFile& file, ex_entity_type type) {
  int count = 0;
  ex_get_variable_param(file.id(), type, &count);
  std::vector<std::string> names;
  for (int i = 1; i <= count; ++i) {
    char name[MAX_STR_LENGTH + 1] = {0};
    file.check(ex_get_variable_name(file.id(), type, i, name), "reading variable names");
    names.emplace_back(name);
  }
  return names;
}

}  // namespace

ExodusContents exodus_contents(const std::string& path) {
  ExodusFile file(path, ExodusMode::read);
  ExodusContents contents;
  contents.nodal_variables = variable_names(file, EX_NODAL);
  contents.element_variables = variable_names(file, EX_ELEM_BLOCK);
  contents.n_steps = static_cast<int>(ex_inquire_int(file.id(), EX_INQ_TIME));
  return contents;
}

ExodusField read_exodus_field(const std::string& path, const std::string& name, bool nodal,
                              int step) {
  return read_exodus_field(path, read_exodus_mesh(path), name, nodal, step);
}

ExodusField read_exodus_field(const std::string& path, const Mesh& mesh, const std::string& name,
                              bool nodal, int step) {
  ExodusFile file(path, ExodusMode::read);
  const auto names = variable_names(file, nodal ? EX_NODAL : EX_ELEM_BLOCK);
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) {
    std::string known;
    for (const auto& n : names)
      known += " " + n;
    throw std::runtime_error("'" + path + "' has no " + (nodal ? "nodal" : "element") +
                             " variable '" + name + "'; it has:" + known);
  }
  const int index = static_cast<int>(found - names.begin()) + 1;
  const int n_steps = static_cast<int>(ex_inquire_int(file.id(), EX_INQ_TIME));
  const int time_step = step > 0 ? step : n_steps + step;
  if (time_step < 1 || time_step > n_steps) {
    throw std::runtime_error("'" + path + "' has no output time " + std::to_string(step) +
                             " (it has " + std::to_string(n_steps) + ")");
  }
  ExodusField field;
  if (nodal) {
    field.values.resize(mesh.n_nodes());
    file.check(
        ex_get_var(file.id(), time_step, EX_NODAL, index, 1, mesh.n_nodes(), field.values.data()),
        "reading " + name);
    for (GlobalIndex n = 0; n < mesh.n_nodes(); ++n)
      field.points.push_back(mesh.node(n));
    return field;
  }
  std::vector<int64_t> block_ids(mesh.blocks.size());
  file.check(ex_get_ids(file.id(), EX_ELEM_BLOCK, block_ids.data()), "reading block ids");
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    std::vector<double> values(block.n_elements());
    if (!values.empty()) {
      file.check(ex_get_var(file.id(), time_step, EX_ELEM_BLOCK, index, block_ids[b],
                            block.n_elements(), values.data()),
                 "reading " + name);
    }
    field.values.insert(field.values.end(), values.begin(), values.end());
    for (GlobalIndex e = 0; e < block.n_elements(); ++e) {
      std::array<double, 3> centre{0, 0, 0};
      const int count = block.n_element_nodes(e);
      for (int a = 0; a < count; ++a) {
        const auto node = mesh.node(block.element_nodes(e)[a]);
        for (int d = 0; d < 3; ++d)
          centre[d] += node[d] / count;
      }
      field.points.push_back(centre);
    }
  }
  return field;
}

std::vector<long long> read_exodus_node_set(const std::string& path, const std::string& name) {
  const Mesh mesh = read_exodus_mesh(path);
  if (!mesh.has_node_set(name)) {
    throw std::runtime_error("'" + path + "' has no node set '" + name + "'");
  }
  const auto& nodes = mesh.node_set(name, "", "").nodes;
  return {nodes.begin(), nodes.end()};
}

}  // namespace railfe
