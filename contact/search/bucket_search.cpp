#include "contact/search/bucket_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "framework/base/error.hpp"

namespace railfe {
namespace {

// Above this many (cell, face) entries the capture distance or one face is absurdly large
// against the mean face: refuse rather than exhaust memory.
constexpr std::size_t kMaxEntries = std::size_t(1) << 30;

std::size_t next_power_of_two(std::size_t n) {
  std::size_t p = 16;
  while (p < n)
    p <<= 1;
  return p;
}

}  // namespace

BucketSearch::BucketSearch(std::vector<std::array<int, 4>> faces) : faces_(std::move(faces)) {
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& n = faces_[f];
    const std::string nodes = std::to_string(n[0]) + ", " + std::to_string(n[1]) + ", " +
                              std::to_string(n[2]) + ", " + std::to_string(n[3]);
    for (int a = 0; a < 4; ++a) {
      if (n[a] < 0)
        throw InputError("contact search: master face " + std::to_string(f) + " (nodes " + nodes +
                         ") has a negative node index");
      for (int b = a + 1; b < 4; ++b)
        if (n[a] == n[b])
          throw InputError("contact search: master face " + std::to_string(f) + " (nodes " + nodes +
                           ") repeats node " + std::to_string(n[a]) +
                           "; a master face must be a quadrilateral of four distinct nodes");
    }
  }
  boxes_.resize(faces_.size());
}

std::array<std::int64_t, 3> BucketSearch::cell_of(const double* point) const {
  const double inverse = 1 / cell_size_;
  return {static_cast<std::int64_t>(std::floor((point[0] - bounds_[0]) * inverse)),
          static_cast<std::int64_t>(std::floor((point[1] - bounds_[1]) * inverse)),
          static_cast<std::int64_t>(std::floor((point[2] - bounds_[2]) * inverse))};
}

std::size_t BucketSearch::bucket_of(const std::array<std::int64_t, 3>& cell) const {
  // Teschner et al. (2003) spatial hash: three large primes, XOR.
  const auto h = (static_cast<std::uint64_t>(cell[0]) * 73856093u) ^
                 (static_cast<std::uint64_t>(cell[1]) * 19349663u) ^
                 (static_cast<std::uint64_t>(cell[2]) * 83492791u);
  return static_cast<std::size_t>(h ^ (h >> 29)) & bucket_mask_;
}

template <class Visit>
void BucketSearch::for_each_bucket(int face, Visit&& visit) {
  const Box& box = boxes_[face];
  const auto lower = cell_of(&box[0]), upper = cell_of(&box[3]);
  face_buckets_.clear();
  for (auto i = lower[0]; i <= upper[0]; ++i)
    for (auto j = lower[1]; j <= upper[1]; ++j)
      for (auto k = lower[2]; k <= upper[2]; ++k)
        face_buckets_.push_back(bucket_of({i, j, k}));
  // Two cells of one face may share a bucket; the face is listed there once.
  std::sort(face_buckets_.begin(), face_buckets_.end());
  const auto end = std::unique(face_buckets_.begin(), face_buckets_.end());
  for (auto b = face_buckets_.begin(); b != end; ++b)
    visit(*b);
}

void BucketSearch::rebuild(const double* positions, double capture_distance) {
  if (!(capture_distance >= 0) || !std::isfinite(capture_distance))
    throw std::invalid_argument(
        "contact search: the capture distance must be finite and >= 0, not " +
        std::to_string(capture_distance));
  capture_distance_ = capture_distance;
  const double inf = std::numeric_limits<double>::infinity();
  bounds_ = {inf, inf, inf, -inf, -inf, -inf};
  double size_sum = 0;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    Box box = {inf, inf, inf, -inf, -inf, -inf};
    for (int node : faces_[f]) {
      const double* p = positions + 3 * static_cast<std::size_t>(node);
      for (int d = 0; d < 3; ++d) {
        if (!std::isfinite(p[d]))
          throw RunError("contact search: node " + std::to_string(node) + " of master face " +
                         std::to_string(f) + " has a non-finite position (the run blew up)");
        box[d] = std::min(box[d], p[d]);
        box[3 + d] = std::max(box[3 + d], p[d]);
      }
    }
    size_sum += std::max({box[3] - box[0], box[4] - box[1], box[5] - box[2]});
    for (int d = 0; d < 3; ++d) {
      box[d] -= capture_distance;
      box[3 + d] += capture_distance;
      bounds_[d] = std::min(bounds_[d], box[d]);
      bounds_[3 + d] = std::max(bounds_[3 + d], box[3 + d]);
    }
    boxes_[f] = box;
  }
  const double mean_size = faces_.empty() ? 0 : size_sum / faces_.size();
  cell_size_ = mean_size + 2 * capture_distance;
  if (!(cell_size_ > 0))
    cell_size_ = 1;  // every face a point and no capture: any cell finds them

  // The table: about two buckets per entry, counted from the cells each box spans.
  std::size_t total = 0;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto lower = cell_of(&boxes_[f][0]), upper = cell_of(&boxes_[f][3]);
    total += static_cast<std::size_t>((upper[0] - lower[0] + 1) * (upper[1] - lower[1] + 1) *
                                      (upper[2] - lower[2] + 1));
    if (total > kMaxEntries)
      throw RunError("contact search: master face " + std::to_string(f) +
                     " spans too many search cells (capture distance " +
                     std::to_string(capture_distance) + " m against a mean face size of " +
                     std::to_string(mean_size) + " m)");
  }
  bucket_mask_ = next_power_of_two(2 * total) - 1;
  bucket_start_.assign(bucket_mask_ + 2, 0);
  for (std::size_t f = 0; f < faces_.size(); ++f)
    for_each_bucket(static_cast<int>(f), [&](std::size_t b) { ++bucket_start_[b + 1]; });
  for (std::size_t b = 0; b <= bucket_mask_; ++b)
    bucket_start_[b + 1] += bucket_start_[b];
  bucket_faces_.resize(static_cast<std::size_t>(bucket_start_.back()));
  // Filling in increasing face order leaves every bucket sorted; bucket_start_[b] walks to the
  // end of bucket b and is moved back after.
  for (std::size_t f = 0; f < faces_.size(); ++f)
    for_each_bucket(static_cast<int>(f), [&](std::size_t b) {
      bucket_faces_[bucket_start_[b]++] = static_cast<int>(f);
    });
  for (std::size_t b = bucket_mask_ + 1; b > 0; --b)
    bucket_start_[b] = bucket_start_[b - 1];
  bucket_start_[0] = 0;
}

void BucketSearch::candidates(const double* point, std::vector<int>& out) const {
  out.clear();
  if (bucket_start_.empty())
    return;  // not rebuilt yet
  for (int d = 0; d < 3; ++d)
    if (!(point[d] >= bounds_[d] && point[d] <= bounds_[3 + d]))
      return;  // outside every grown box (or not a number)
  const std::size_t b = bucket_of(cell_of(point));
  for (int i = bucket_start_[b]; i < bucket_start_[b + 1]; ++i) {
    const int f = bucket_faces_[i];
    const Box& box = boxes_[f];
    if (point[0] >= box[0] && point[0] <= box[3] && point[1] >= box[1] && point[1] <= box[4] &&
        point[2] >= box[2] && point[2] <= box[5])
      out.push_back(f);
  }
}

void BucketSearch::faces_overlapping(const std::array<double, 6>& box,
                                     std::vector<int>& out) const {
  out.clear();
  for (std::size_t f = 0; f < boxes_.size(); ++f) {
    const Box& face = boxes_[f];
    bool overlaps = true;
    for (int d = 0; d < 3; ++d)
      overlaps = overlaps && face[d] <= box[3 + d] && box[d] <= face[3 + d];
    if (overlaps)
      out.push_back(static_cast<int>(f));
  }
}

namespace {

QuadProjection project_face(const std::array<int, 4>& nodes, const double* positions,
                            const double* x) {
  return project_onto_quad({positions + 3 * static_cast<std::size_t>(nodes[0]),
                            positions + 3 * static_cast<std::size_t>(nodes[1]),
                            positions + 3 * static_cast<std::size_t>(nodes[2]),
                            positions + 3 * static_cast<std::size_t>(nodes[3])},
                           x);
}

// A lower bound of the distance from \p x to the face: the distance to the box around its
// corners, which holds the whole bilinear face. Cheap against a projection.
double box_distance(const std::array<int, 4>& nodes, const double* positions, const double* x) {
  double squared = 0;
  for (int d = 0; d < 3; ++d) {
    double low = positions[3 * static_cast<std::size_t>(nodes[0]) + d], high = low;
    for (int a = 1; a < 4; ++a) {
      const double value = positions[3 * static_cast<std::size_t>(nodes[a]) + d];
      low = std::min(low, value);
      high = std::max(high, value);
    }
    const double outside = std::max({low - x[d], x[d] - high, 0.0});
    squared += outside * outside;
  }
  return std::sqrt(squared);
}

// Whether a face whose box lies \p bound away can be skipped against the nearest distance so
// far, \p best: it cannot be nearer, nor share the nearest point (a margin for round-off in the
// projection's distance).
bool cannot_compete(double bound, double best) {
  return bound > best + 1e-9 * (best + bound) + 1e-300;
}

}  // namespace

ContactPoint find_contact_point(const BucketSearch& search, const double* positions,
                                const double* x, std::vector<int>& scratch) {
  search.candidates(x, scratch);
  ContactPoint best;
  // Project first onto the face whose box is nearest, then only onto faces that could be
  // nearer: most candidates of a node in a patch are its face's neighbours, a box away.
  int first = -1;
  double first_bound = std::numeric_limits<double>::infinity();
  for (int f : scratch) {
    const double bound = box_distance(search.faces()[f], positions, x);
    if (bound < first_bound) {
      first_bound = bound;
      first = f;
    }
  }
  if (first >= 0)
    best = {first, project_face(search.faces()[first], positions, x), false};
  for (int f : scratch) {
    if (f == first ||
        cannot_compete(box_distance(search.faces()[f], positions, x), best.projection.distance))
      continue;
    const QuadProjection projection = project_face(search.faces()[f], positions, x);
    // Strictly nearer, or as near from a smaller face index (as if taken in order).
    if (projection.distance < best.projection.distance ||
        (projection.distance == best.projection.distance && f < best.face))
      best = {f, projection, false};
  }
  if (best.face < 0 || !best.projection.on_boundary)
    return best;

  // The nearest point is on an edge or corner: which candidate faces share it?
  QuadProjection& chosen = best.projection;
  const auto& corner = search.faces()[best.face];
  const double* c0 = positions + 3 * static_cast<std::size_t>(corner[0]);
  const double* c2 = positions + 3 * static_cast<std::size_t>(corner[2]);
  const double diagonal = std::hypot(c2[0] - c0[0], c2[1] - c0[1], c2[2] - c0[2]);
  const double tolerance = 1e-9 * (diagonal + chosen.distance);
  std::array<double, 3> normal_sum{};
  int sharing = 0;
  for (int f : scratch) {
    if (f != best.face &&
        cannot_compete(box_distance(search.faces()[f], positions, x), chosen.distance))
      continue;
    const QuadProjection other =
        f == best.face ? chosen : project_face(search.faces()[f], positions, x);
    const double separation =
        std::hypot(other.point[0] - chosen.point[0], other.point[1] - chosen.point[1],
                   other.point[2] - chosen.point[2]);
    if (separation > tolerance)
      continue;
    ++sharing;
    for (int d = 0; d < 3; ++d)
      normal_sum[d] += other.normal[d];
  }
  if (sharing < 2) {
    best.beyond_free_edge = true;  // keep the face normal: the gap stays continuous there too
    return best;
  }
  const double side = normal_sum[0] * (x[0] - chosen.point[0]) +
                      normal_sum[1] * (x[1] - chosen.point[1]) +
                      normal_sum[2] * (x[2] - chosen.point[2]);
  if (chosen.distance > 0) {
    const double sign = side >= 0 ? 1 : -1;
    for (int d = 0; d < 3; ++d)
      chosen.normal[d] = sign * (x[d] - chosen.point[d]) / chosen.distance;
    chosen.gap = sign * chosen.distance;
  } else {
    // Exactly on the edge: gap zero, the averaged normal.
    const double length = std::hypot(normal_sum[0], normal_sum[1], normal_sum[2]);
    if (length > 0)
      for (int d = 0; d < 3; ++d)
        chosen.normal[d] = normal_sum[d] / length;
    chosen.gap = 0;
  }
  return best;
}

}  // namespace railfe
