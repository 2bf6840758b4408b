#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "framework/mesh/mesh_checks.hpp"
#include "framework/mesh/revolve.hpp"
#include "framework/mesh/revolve_detail.hpp"

namespace railfe {

namespace {

[[noreturn]] void broken(const std::string& what) {
  throw std::logic_error("railfe: revolve with coarsening slices: " + what);
}

// Angle indices of every level (level 0: all of them), checked against the rules of revolve().
std::vector<std::vector<std::size_t>> level_slices(
    std::size_t n_angles, const std::vector<std::vector<std::size_t>>& coarser) {
  std::vector<std::vector<std::size_t>> slices(1);
  for (std::size_t k = 0; k < n_angles; ++k)
    slices[0].push_back(k);
  for (const auto& level : coarser) {
    const auto& finer = slices.back();
    if (level.empty() || level.front() != 0)
      broken("a coarser level must start at angle index 0");
    std::size_t at = 0;  // position in finer
    for (std::size_t j = 0; j < level.size(); ++j) {
      const std::size_t end = j + 1 < level.size() ? level[j + 1] : n_angles;
      std::size_t span = 0;
      while (at + span < finer.size() && finer[at + span] < end)
        ++span;
      if (finer[at] != level[j] || (span != 1 && span != 3))
        broken("each coarser slice must span one or three finer slices");
      at += span;
    }
    slices.push_back(level);
  }
  return slices;
}

class CoarseningSweep {
 public:
  CoarseningSweep(const SectionMesh& section, const std::vector<double>& angles,
                  const std::vector<int>& node_level,
                  const std::vector<std::vector<std::size_t>>& coarser)
      : section_(section),
        angles_(angles),
        level_(node_level),
        slices_(level_slices(angles.size(), coarser)) {
    if (level_.size() != static_cast<std::size_t>(section.n_nodes()))
      broken("one level per section node expected");
    position_.assign(slices_.size(), std::vector<long>(angles.size(), -1));
    for (std::size_t l = 0; l < slices_.size(); ++l)
      for (std::size_t j = 0; j < slices_[l].size(); ++j)
        position_[l][slices_[l][j]] = static_cast<long>(j);
    mesh_.source = section.source;
    for (GlobalIndex i = 0; i < section.n_nodes(); ++i) {
      if (level_[i] < 0 || level_[i] >= static_cast<int>(slices_.size()))
        broken("a node level outside the levels given");
      first_node_.push_back(mesh_.n_nodes());
      for (std::size_t k : slices_[level_[i]])
        add_node(section.coordinates[2 * i], section.coordinates[2 * i + 1], k);
    }
    quads_ = oriented_quads(section);
    classify_quads();
  }

  Mesh build() {
    add_elements();
    add_sets();
    return std::move(mesh_);
  }

 private:
  GlobalIndex add_node(double r, double a, std::size_t k) {
    mesh_.coordinates.insert(mesh_.coordinates.end(),
                             {r * std::cos(angles_[k]), a, r * std::sin(angles_[k])});
    return mesh_.n_nodes() - 1;
  }

  GlobalIndex node_at(GlobalIndex i, std::size_t k) const {
    const long j = position_[level_[i]][k];
    if (j < 0)
      broken("a node asked for at an angle its level lacks");
    return first_node_[i] + j;
  }

  // The node half way from \p fine to \p coarse at angle \p k, made on first use.
  GlobalIndex middle_at(GlobalIndex fine, GlobalIndex coarse, std::size_t k) {
    const std::array<GlobalIndex, 3> key = {fine, coarse, static_cast<GlobalIndex>(k)};
    auto it = middles_.find(key);
    if (it != middles_.end())
      return it->second;
    const double* c = section_.coordinates.data();
    const GlobalIndex node = add_node(0.5 * (c[2 * fine] + c[2 * coarse]),
                                      0.5 * (c[2 * fine + 1] + c[2 * coarse + 1]), k);
    middles_.emplace(key, node);
    return node;
  }

  // Each quad's level, and for a transition quad the corner c with c and c + 1 on the finer side.
  void classify_quads() {
    for (const auto& quad : quads_) {
      int low = level_[quad[0]], high = low;
      for (GlobalIndex node : quad) {
        low = std::min(low, level_[node]);
        high = std::max(high, level_[node]);
      }
      int corner = -1;
      if (high == low + 1) {
        for (int c = 0; c < 4; ++c)
          if (level_[quad[c]] == low && level_[quad[(c + 1) % 4]] == low &&
              level_[quad[(c + 2) % 4]] == high && level_[quad[(c + 3) % 4]] == high)
            corner = c;
        if (corner < 0)
          broken("a quad between two levels needs its two finer nodes on one edge");
      } else if (high != low) {
        broken("a quad spans more than two levels");
      }
      quad_level_.push_back(high);
      fine_corner_.push_back(corner);
    }
  }

  // A template's pieces are turned right side out here; a plain slice must already be, as its
  // faces are numbered for the side sets like revolve()'s.
  void add_hex(ElementBlock& block, GlobalIndex nodes[8], bool may_turn) {
    double x[8][3];
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c)
        x[a][c] = mesh_.coordinates[3 * static_cast<std::size_t>(nodes[a]) + c];
    if (hex8_jacobian_quality(x) < 0) {
      if (!may_turn)
        broken("a slice turned inside out");
      for (int a = 0; a < 4; ++a)
        std::swap(nodes[a], nodes[a + 4]);
    }
    block.add_element(nodes, 8);
  }

  // The hexes of quad q in its slice from angle index k to k_next.
  void add_slice(ElementBlock& block, std::size_t q, std::size_t k, std::size_t k_next) {
    const auto& quad = quads_[q];
    const int level = quad_level_[q], c = fine_corner_[q];
    std::vector<std::size_t> fine = {k};  // the finer level's angles from k to k_next
    if (c >= 0) {
      const auto& finer = slices_[level - 1];
      for (std::size_t j = static_cast<std::size_t>(position_[level - 1][k]) + 1;
           j < finer.size() && finer[j] != k_next; ++j)
        fine.push_back(finer[j]);
    }
    fine.push_back(k_next);
    if (fine.size() == 2) {
      GlobalIndex nodes[8];
      for (int j = 0; j < 4; ++j) {
        nodes[j] = node_at(quad[j], k);
        nodes[j + 4] = node_at(quad[j], k_next);
      }
      add_hex(block, nodes, false);
      return;
    }
    // The 3-to-1 template in the plane of (from fine to coarse, around), at each of the two
    // edges joining the levels: fine nodes b0-b3, middles m1 m2, coarse nodes t0 t1.
    GlobalIndex plane[2][4][4];
    for (int side = 0; side < 2; ++side) {
      const GlobalIndex f = quad[(c + side) % 4], g = quad[(c + 3 - side) % 4];
      GlobalIndex b[4];
      for (int j = 0; j < 4; ++j)
        b[j] = node_at(f, fine[j]);
      const GlobalIndex m1 = middle_at(f, g, fine[1]), m2 = middle_at(f, g, fine[2]);
      const GlobalIndex t0 = node_at(g, k), t1 = node_at(g, k_next);
      const GlobalIndex pieces[4][4] = {
          {b[0], b[1], m1, t0}, {b[1], b[2], m2, m1}, {b[2], b[3], t1, m2}, {m1, m2, t1, t0}};
      std::copy(&pieces[0][0], &pieces[0][0] + 16, &plane[side][0][0]);
    }
    for (int piece = 0; piece < 4; ++piece) {
      GlobalIndex nodes[8];
      for (int j = 0; j < 4; ++j) {
        nodes[j] = plane[0][piece][j];
        nodes[j + 4] = plane[1][piece][j];
      }
      add_hex(block, nodes, true);
    }
  }

  void add_elements() {
    quad_elements_.assign(quads_.size(), {});
    for (std::size_t b = 0; b < section_.blocks.size(); ++b) {
      ElementBlock block;
      block.name = section_.blocks[b].name;
      block.id = section_.blocks[b].id;
      const GlobalIndex first = mesh_.n_elements();
      // Slice by slice around, so that neighbours stay close in the numbering.
      for (std::size_t k = 0; k < angles_.size(); ++k) {
        for (std::size_t q = 0; q < quads_.size(); ++q) {
          if (section_.quad_blocks[q] != static_cast<int>(b))
            continue;
          const auto& slices = slices_[quad_level_[q]];
          const long j = position_[quad_level_[q]][k];
          if (j < 0)
            continue;
          const std::size_t k_next = slices[(static_cast<std::size_t>(j) + 1) % slices.size()];
          if (fine_corner_[q] < 0)
            quad_elements_[q].push_back(first + block.n_elements());
          add_slice(block, q, k, k_next);
        }
      }
      if (block.n_elements() > 0)
        mesh_.blocks.push_back(std::move(block));
      mesh_.number_blocks();
    }
  }

  void add_sets() {
    const auto edges = boundary_edges(quads_);
    for (const auto& group : section_.node_sets) {
      NodeSet nodes{group.name, group.id, {}};
      for (GlobalIndex i : group.nodes)
        for (std::size_t k : slices_[level_[i]])
          nodes.nodes.push_back(node_at(i, k));
      std::sort(nodes.nodes.begin(), nodes.nodes.end());
      mesh_.node_sets.push_back(std::move(nodes));

      SideSet sides{group.name, group.id, {}};
      for (const auto& [q, j] : edges) {
        const GlobalIndex p = quads_[q][j], s = quads_[q][(j + 1) % 4];
        if (!std::binary_search(group.nodes.begin(), group.nodes.end(), p) ||
            !std::binary_search(group.nodes.begin(), group.nodes.end(), s))
          continue;
        if (fine_corner_[q] >= 0)
          broken("side set '" + group.name + "' runs along a transition quad");
        for (GlobalIndex element : quad_elements_[q])
          sides.sides.push_back({element, j});
      }
      if (!sides.sides.empty())
        mesh_.side_sets.push_back(std::move(sides));
    }
  }

  const SectionMesh& section_;
  const std::vector<double>& angles_;
  const std::vector<int>& level_;
  std::vector<std::vector<std::size_t>> slices_;
  std::vector<std::vector<long>> position_;  // index of angle k in level l's slices, or −1
  std::vector<GlobalIndex> first_node_;      // of each section node
  std::vector<std::array<GlobalIndex, 4>> quads_;
  std::vector<int> quad_level_, fine_corner_;
  std::vector<std::vector<GlobalIndex>> quad_elements_;  // of each level quad, for side sets
  std::map<std::array<GlobalIndex, 3>, GlobalIndex> middles_;
  Mesh mesh_;
};

}  // namespace

Mesh revolve(const SectionMesh& section, const std::vector<double>& angles,
             const std::vector<int>& node_level,
             const std::vector<std::vector<std::size_t>>& coarser_slices) {
  check_section(section, static_cast<int>(angles.size()));
  check_angles(angles);
  return CoarseningSweep(section, angles, node_level, coarser_slices).build();
}

}  // namespace railfe
