#pragma once
/// \file
/// Reading railfe's result files back for comparison: CSV tables and Exodus fields.

#include <array>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// A CSV file: header names and rows of cells (text as written).
struct CsvTable {
  std::vector<std::string> columns;            ///< header names
  std::vector<std::vector<std::string>> rows;  ///< cells, row by row

  /// Index of column \p name; throws std::runtime_error listing the columns if absent.
  std::size_t column(const std::string& name) const;
};

/// Reads \p path; throws std::runtime_error if it is missing or ragged.
CsvTable read_csv(const std::string& path);

/// Parses a cell as a number; false if it is not one.
bool parse_number(const std::string& cell, double& value);

/// One field of an Exodus results file at one output time.
struct ExodusField {
  std::vector<double> values;                 ///< one per node or element (global order)
  std::vector<std::array<double, 3>> points;  ///< node coordinates or element centroids
};

/// What an Exodus results file holds.
struct ExodusContents {
  std::vector<std::string> nodal_variables;    ///< names of nodal variables
  std::vector<std::string> element_variables;  ///< names of element variables
  int n_steps = 0;                             ///< number of output times
};

/// Lists the variables and output times of \p path.
ExodusContents exodus_contents(const std::string& path);

/// Reads variable \p name (nodal when \p nodal, else element) at output time \p step (1-based;
/// 0 or negative counts from the end: 0 = last). Throws std::runtime_error if absent.
ExodusField read_exodus_field(const std::string& path, const std::string& name, bool nodal,
                              int step);
/// The same with the file's mesh already read (read_exodus_mesh), for callers reading many fields.
ExodusField read_exodus_field(const std::string& path, const Mesh& mesh, const std::string& name,
                              bool nodal, int step);

/// Nodes (0-based) of node set \p name in \p path; throws std::runtime_error if absent.
std::vector<long long> read_exodus_node_set(const std::string& path, const std::string& name);

}  // namespace railfe
