#pragma once
/// \file
/// Exodus II results that ParaView opens: the mesh with its blocks and sets, then nodal and
/// element fields at each output time. Written by rank 0 from fields gathered over all ranks.

#include <memory>
#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"

namespace railfe {

class ExodusFile;

/// An Exodus results file being written.
class ExodusWriter {
 public:
  /// On rank 0 (\p active), creates \p path with the geometry, blocks, node sets and side sets of
  /// \p mesh and declares the variables. Names ending in _x, _y, _z are shown by ParaView as one
  /// vector; a nodal vector whose name starts with "displacement" can warp the mesh.
  ExodusWriter(const std::string& path, const Mesh& mesh, const std::string& title,
               const std::vector<std::string>& nodal_variables,
               const std::vector<std::string>& element_variables, bool active);
  ~ExodusWriter();

  /// Appends one output time. \p nodal[v] holds variable v at every mesh node, \p element[v] at
  /// every mesh element in global order (rank 0 only reads them).
  void write_step(double time, const std::vector<std::vector<double>>& nodal,
                  const std::vector<std::vector<double>>& element);
  /// Closes the file (throws RunError if that fails).
  void close();

 private:
  std::unique_ptr<ExodusFile> file_;
  const Mesh* mesh_;
  std::size_t n_nodal_ = 0;
  std::size_t n_element_ = 0;
  int step_ = 0;
};

}  // namespace railfe
