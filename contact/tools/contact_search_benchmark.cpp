// railfe-contact-search-benchmark: the cost of node-to-segment contact search against the size of
// the master surface (issue 15, "Benchmark": the search cost must grow linearly with the surface).
//
//   railfe-contact-search-benchmark OUT.csv [FACES ...]     (default 1000 10000 100000)
//
// For each size, a tread-like master patch (a piece of a wheel's surface of revolution, radius
// 0.46 m, lateral profile radius 0.3 m) of about FACES bilinear faces of 1 mm, nodes jittered
// radially by 5 % of a face so that faces are warped, and one slave point per face: above the
// face's centre by up to ±0.2 mm (in and out of contact) and shifted tangentially by up to half a
// face, as a slave surface of the same density would be. Timed: BucketSearch::rebuild with the
// pair's default capture distance (half a face), in ns per face, and find_contact_point (the
// candidates and the closest-point projections of one slave node), in ns per query; the median
// of 7 repetitions of a batch that takes at least 50 ms each. Writes one row per size to OUT.csv.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "contact/search/bucket_search.hpp"

namespace {

constexpr double kFace = 1e-3;          // m, face size
constexpr double kWheelRadius = 0.46;   // m
constexpr double kProfileRadius = 0.3;  // m, the tread's lateral curvature
constexpr int kRepetitions = 7;         // batches per timing; the median is kept
constexpr double kBatchSeconds = 0.05;  // the least time of one batch

struct Patch {
  std::vector<double> positions;  // x, y, z per node
  std::vector<std::array<int, 4>> faces;
  std::vector<double> queries;  // x, y, z per slave point
};

// A patch of nu x nv faces of about kFace on the tread, with one query point per face.
Patch tread_patch(int nu, int nv) {
  Patch patch;
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto surface = [](double s, double y, double lift, double* out) {
    const double angle = s / kWheelRadius;
    const double radius =
        kWheelRadius - kProfileRadius + std::sqrt(kProfileRadius * kProfileRadius - y * y) + lift;
    out[0] = radius * std::sin(angle);
    out[1] = y;
    out[2] = -radius * std::cos(angle);  // the wheel's bottom: outward normal points down
  };
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      double p[3];
      surface((i - 0.5 * nu) * kFace, (j - 0.5 * nv) * kFace, 0.05 * kFace * unit(random), p);
      patch.positions.insert(patch.positions.end(), p, p + 3);
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int a = i * (nv + 1) + j;
      patch.faces.push_back({a, a + nv + 1, a + nv + 2, a + 1});
      double p[3];
      surface((i + 0.5 + 0.5 * unit(random) - 0.5 * nu) * kFace,
              (j + 0.5 + 0.5 * unit(random) - 0.5 * nv) * kFace, 0.2 * kFace * unit(random), p);
      patch.queries.insert(patch.queries.end(), p, p + 3);
    }
  return patch;
}

// The median over kRepetitions of the seconds per call of \p work (called in batches).
template <class Work>
double median_seconds_per_call(Work&& work) {
  int calls = 1;
  for (;;) {  // batch size: at least kBatchSeconds
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < calls; ++c)
      work();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds >= kBatchSeconds)
      break;
    calls *= 2;
  }
  std::vector<double> times;
  for (int r = 0; r < kRepetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < calls; ++c)
      work();
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / calls);
  }
  std::nth_element(times.begin(), times.begin() + kRepetitions / 2, times.end());
  return times[kRepetitions / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: railfe-contact-search-benchmark OUT.csv [FACES ...]\n";
    return 2;
  }
  std::vector<long> sizes;
  for (int a = 2; a < argc; ++a)
    sizes.push_back(std::atol(argv[a]));
  if (sizes.empty())
    sizes = {1000, 10000, 100000};
  std::ofstream out(argv[1]);
  out << "faces,nodes,queries,capture_distance_m,cell_size_m,entries,rebuild_ns_per_face,"
         "query_ns,candidates_per_query,contacts_found\n";
  for (long target : sizes) {
    // A strip twice as long as wide, as a rail head or a tread band.
    const int nv = std::max(1, static_cast<int>(std::lround(std::sqrt(target / 2.0))));
    const int nu = std::max(1, static_cast<int>(std::lround(static_cast<double>(target) / nv)));
    const Patch patch = tread_patch(nu, nv);
    railfe::BucketSearch search(patch.faces);
    const double capture = 0.5 * kFace;
    search.rebuild(patch.positions.data(), capture);  // warm-up: the tables reach their size
    const double rebuild =
        median_seconds_per_call([&] { search.rebuild(patch.positions.data(), capture); });
    std::vector<int> scratch;
    const std::size_t n_queries = patch.queries.size() / 3;
    long candidates = 0, found = 0;
    for (std::size_t q = 0; q < n_queries; ++q) {
      search.candidates(&patch.queries[3 * q], scratch);
      candidates += static_cast<long>(scratch.size());
      found +=
          railfe::find_contact_point(search, patch.positions.data(), &patch.queries[3 * q], scratch)
                      .face >= 0
              ? 1
              : 0;
    }
    volatile double sink = 0;
    const double query = median_seconds_per_call([&] {
      for (std::size_t q = 0; q < n_queries; ++q)
        sink = sink + railfe::find_contact_point(search, patch.positions.data(),
                                                 &patch.queries[3 * q], scratch)
                          .projection.gap;
    });
    const std::size_t n_faces = patch.faces.size();
    out << n_faces << ',' << patch.positions.size() / 3 << ',' << n_queries << ',' << capture << ','
        << search.cell_size() << ',' << search.entries() << ','
        << 1e9 * rebuild / static_cast<double>(n_faces) << ','
        << 1e9 * query / static_cast<double>(n_queries) << ','
        << static_cast<double>(candidates) / static_cast<double>(n_queries) << ',' << found << '\n';
    std::cout << n_faces << " faces: rebuild " << 1e9 * rebuild / static_cast<double>(n_faces)
              << " ns/face, query " << 1e9 * query / static_cast<double>(n_queries) << " ns, "
              << static_cast<double>(candidates) / static_cast<double>(n_queries)
              << " candidates per query\n";
  }
  return 0;
}
