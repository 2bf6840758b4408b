#pragma once
/// \file
/// Closest-point projection onto a bilinear quadrilateral face (node-to-segment contact). A
/// bilinear face with straight edges: the nearest point is either a stationary point of the
/// distance inside the face (Newton on the natural coordinates) or the nearest point of one of
/// the four straight edges (closed form), so the box constraint is handled exactly.

#include <array>

namespace railfe {

/// The point of a bilinear quadrilateral face nearest to a given point.
struct QuadProjection {
  double xi = 0, eta = 0;         ///< natural coordinates of the nearest point, in [-1, 1]^2
  std::array<double, 3> point{};  ///< the nearest point on the face (m)
  /// Unit normal: the face normal at (xi, eta) (right-hand rule on the node order 0-1-2-3, i.e.
  /// outward for Exodus side faces of hex8) when the nearest point is interior; on an edge or
  /// corner, the face normal as well (the caller decides).
  std::array<double, 3> normal{};
  double gap = 0;  ///< (x − point)·normal: negative = the point is behind the face (penetration)
  double distance = 0;       ///< |x − point| (m)
  bool on_boundary = false;  ///< the nearest point lies on an edge or corner of the face
  int iterations = 0;        ///< Newton iterations spent on interior stationary points (all starts)
};

/// Nearest point of the bilinear face with corners c[0..3] (each 3 doubles) to x: Newton on the
/// two natural coordinates with the box constraint handled (edges, corners), bounded iterations.
/// Throws RunError when the face has collapsed to a line or a point (no normal exists).
QuadProjection project_onto_quad(const std::array<const double*, 4>& corners, const double* x);

/// The four bilinear shape functions at (xi, eta), for distributing a force to the face's nodes.
std::array<double, 4> quad_shape_functions(double xi, double eta);

}  // namespace railfe
