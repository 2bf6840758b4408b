#pragma once
/// \file
/// The spatial search of node-to-segment contact: master faces sorted into a uniform grid of
/// cells, stored as a hash table so that only cells the surface crosses cost memory (a rail head
/// is long and thin; a dense grid over its bounding box would not be linear in the faces), and
/// the choice of a slave node's master face with a gap that is continuous across edges.

#include <array>
#include <cstdint>
#include <vector>

#include "contact/search/quad_projection.hpp"

namespace railfe {

/// Master faces sorted into a uniform grid of cells (buckets) for candidate lookup; cost linear in
/// the number of faces; no allocation per query once warmed up.
class BucketSearch {
 public:
  /// \p faces: per master face, four indices into the position arrays later passed to rebuild().
  /// Throws InputError for a negative index or a face that repeats a node (not a quadrilateral).
  explicit BucketSearch(std::vector<std::array<int, 4>> faces);
  /// Sorts the faces into cells by their bounding boxes grown by \p capture_distance (m);
  /// \p positions holds x, y, z of node i at 3i..3i+2 (current coordinates). Cell size from the
  /// mean face size. O(faces). Throws RunError for a non-finite node position (a run that blew
  /// up) and std::invalid_argument for a negative or non-finite capture distance.
  void rebuild(const double* positions, double capture_distance);
  /// Appends to \p out (cleared first) the faces whose grown bounding box may contain \p point,
  /// each once, in increasing order.
  void candidates(const double* point, std::vector<int>& out) const;
  /// Appends to \p out (cleared first) every face whose grown bounding box overlaps \p box
  /// (lower x, y, z, upper x, y, z), in increasing order: the faces candidates() can return for
  /// any point in \p box. O(faces).
  void faces_overlapping(const std::array<double, 6>& box, std::vector<int>& out) const;
  /// The faces.
  const std::vector<std::array<int, 4>>& faces() const { return faces_; }
  /// The capture distance of the last rebuild (m).
  double capture_distance() const { return capture_distance_; }
  /// The edge length of the cells of the last rebuild (m): the mean face size plus twice the
  /// capture distance, so that a grown face box spans at most two cells per direction on average.
  double cell_size() const { return cell_size_; }
  /// The number of (cell, face) entries of the last rebuild: a measure of its memory.
  std::size_t entries() const { return bucket_faces_.size(); }

 private:
  using Box = std::array<double, 6>;  // lower x, y, z, upper x, y, z

  std::array<std::int64_t, 3> cell_of(const double* point) const;
  std::size_t bucket_of(const std::array<std::int64_t, 3>& cell) const;
  // Calls visit(bucket) once per distinct bucket the grown box of face f touches.
  template <class Visit>
  void for_each_bucket(int face, Visit&& visit);

  std::vector<std::array<int, 4>> faces_;
  std::vector<Box> boxes_;  // grown by the capture distance
  Box bounds_{};            // of all grown boxes
  double capture_distance_ = 0;
  double cell_size_ = 1;
  std::size_t bucket_mask_ = 0;            // the table has bucket_mask_ + 1 buckets
  std::vector<int> bucket_start_;          // compressed rows: the faces of bucket b are
  std::vector<int> bucket_faces_;          // bucket_faces_[bucket_start_[b] .. start_[b + 1])
  std::vector<std::size_t> face_buckets_;  // per face, its distinct buckets (rebuild only)
};

/// The contact point of a slave node: the face and projection chosen among the candidates.
struct ContactPoint {
  int face = -1;              ///< index into faces(), −1 = no candidate face
  QuadProjection projection;  ///< the projection on that face; its normal is the contact normal
  /// The nearest point lies on an edge or corner that no other candidate face shares: \p x lies
  /// beyond the boundary of the master surface (the gap is then measured along the face normal;
  /// the caller may prefer to ignore such a node).
  bool beyond_free_edge = false;
};

/// Chooses the master face for slave point \p x among the candidate faces of \p search:
/// the face with the nearest point (the smallest face index among exact ties). When the nearest
/// point is on an edge or corner shared by several candidate faces, the gap is the signed distance
/// |x − point| and the normal its gradient ±(x − point)/|x − point|, the sign from the sum of the
/// sharing faces' normals (outside: +, penetrated: −); so the gap is the signed distance to the
/// surface everywhere and continuous across edges and corners, convex or concave (see
/// docs/theory.md, "Node-to-segment search"). \p scratch is reused storage for candidates.
ContactPoint find_contact_point(const BucketSearch& search, const double* positions,
                                const double* x, std::vector<int>& scratch);

}  // namespace railfe
