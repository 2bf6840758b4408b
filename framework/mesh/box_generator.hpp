#pragma once
/// \file
/// A structured hex8 mesh of a box, for tests, benchmarks and simple scenes.

#include <array>
#include <string>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// What generate_box() builds.
struct BoxSpec {
  std::array<double, 3> origin{0, 0, 0};   ///< corner with the smallest coordinates (m)
  std::array<double, 3> lengths{1, 1, 1};  ///< edge lengths along x, y, z (m)
  std::array<int, 3> elements{1, 1, 1};    ///< elements along x, y, z
  /// Per axis, size of the last element over size of the first (geometric progression);
  /// 1 is uniform, below 1 refines toward the far end.
  std::array<double, 3> grading{1, 1, 1};
  std::string block_name = "block_1";  ///< name of the single element block
};

/// Builds the box: nodes numbered x fastest, then y, then z; elements likewise. Node sets and
/// side sets named xmin, xmax, ymin, ymax, zmin, zmax cover the six faces.
Mesh generate_box(const BoxSpec& spec);

/// Positions of the n+1 nodes along an edge of \p length split into \p n elements whose sizes
/// grow geometrically so that last/first == \p grading.
std::vector<double> graded_positions(double start, double length, int n, double grading);

}  // namespace railfe
