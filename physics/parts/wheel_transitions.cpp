#include "physics/parts/wheel_transitions.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "framework/base/constants.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

const char* const kParameter = "Mesh/Wheel/Transition radii";

std::string mm(double metres) {
  std::ostringstream text;
  text << std::setprecision(4) << metres * 1000 << " mm";
  return text.str();
}

// Inserts the points where r = radius crosses the rim, web and hub lines; returns the cut.
WheelCut insert_cut(WheelSection& section, double radius, const std::string& source) {
  auto& wheel = section.wheel;
  std::vector<std::size_t> crossings;
  for (std::size_t s = 0; s < wheel.size(); ++s) {
    const double r0 = wheel[s][0], r1 = wheel[(s + 1) % wheel.size()][0];
    if (std::abs(r0 - radius) < 1e-9)
      throw_input_error(source, kParameter,
                        "the cut at r = " + mm(radius) + " passes through a corner of the section",
                        "radii that cut the web or the hub away from their corners");
    if ((r0 - radius) * (r1 - radius) < 0) {
      if (s + 1 < section.tread_points)
        throw_input_error(source, kParameter, "the cut at r = " + mm(radius) + " crosses the tread",
                          "radii below the rim");
      crossings.push_back(s);
    }
  }
  if (crossings.size() != 2)
    throw_input_error(source, kParameter,
                      "the cut at r = " + mm(radius) + " crosses the section's outline " +
                          std::to_string(crossings.size()) + " times",
                      "radii that cut across the web or the hub (twice)");
  WheelCut cut;
  cut.radius = radius;
  for (auto it = crossings.rbegin(); it != crossings.rend(); ++it) {
    const auto& p = wheel[*it];
    const auto& q = wheel[(*it + 1) % wheel.size()];
    const double t = (radius - p[0]) / (q[0] - p[0]);
    wheel.insert(wheel.begin() + static_cast<std::ptrdiff_t>(*it + 1),
                 {radius, p[1] + t * (q[1] - p[1])});
    if (*it + 1 <= section.bore_start)
      ++section.bore_start;
  }
  return cut;
}

}  // namespace

std::vector<double> largest_wheel_slices(const WheelDimensions& dimensions) {
  std::vector<double> largest;
  // Never coarser than the wheel's own slices, whose chords the rest of the body already has.
  const double coarsest = 2 * kPi / wheel_elements_around(dimensions);
  for (double radius : dimensions.transition_radii)
    largest.push_back(std::min(coarsest, dimensions.element_size / radius));
  return largest;
}

double transition_width(const WheelDimensions& dimensions) {
  return 4 * dimensions.arc_element_size;
}

std::vector<WheelCut> cut_wheel_section(WheelSection& section, const std::vector<double>& radii,
                                        double width, double spacing, const std::string& source) {
  std::vector<WheelCut> cuts;
  for (double radius : radii)
    for (double r : {radius, radius - width})
      cuts.push_back(insert_cut(section, r, source));
  // The cut points' indices once every point is in.
  for (WheelCut& cut : cuts) {
    std::vector<std::size_t> at;
    for (std::size_t i = section.tread_points; i < section.wheel.size(); ++i)
      if (section.wheel[i][0] == cut.radius)
        at.push_back(i);
    cut.first = at.front();
    cut.second = at.back();
    const double length = std::abs(section.wheel[cut.second][1] - section.wheel[cut.first][1]);
    // Even: the full-quad recombination halves every curve's count before it splits each quad.
    // About the section's own size, so the parts beside the cut are not refined around it.
    cut.segments = 2 * std::max(1, static_cast<int>(std::lround(length / spacing)));
  }
  bool nested = section.bore_start >= cuts.back().first && section.bore_start < cuts.back().second;
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j)
    nested = nested && cuts[j].first < cuts[j + 1].first && cuts[j + 1].second < cuts[j].second;
  if (!nested) {
    std::ostringstream radii_text;
    for (double r : radii)
      radii_text << (radii_text.tellp() > 0 ? ", " : "") << mm(r);
    throw_input_error(source, kParameter,
                      "the strips below " + radii_text.str() + " (each " + mm(width) +
                          " deep) do not lie one inside the other across the web or hub, above "
                          "the bore",
                      "decreasing radii between the bore and the rim, more than the strip's "
                      "depth (4 x Arc element size) apart, each cutting across the web or hub");
  }
  for (std::size_t p = 0; p + 1 < cuts.size(); p += 2)
    cuts[p + 1].segments = cuts[p].segments;
  return cuts;
}

bool strip_side(const std::vector<WheelCut>& cuts, std::size_t s) {
  for (std::size_t p = 0; p + 1 < cuts.size(); p += 2) {
    if ((s >= cuts[p].first && s < cuts[p + 1].first) ||
        (s >= cuts[p + 1].second && s < cuts[p].second))
      return true;
  }
  return false;
}

int outline_line_tag(const WheelSection& section, std::size_t s) {
  return 3 + static_cast<int>(s - (section.tread_points - 1));
}

std::string cut_surfaces_geo(const WheelSection& section, const std::vector<WheelCut>& cuts,
                             int first_tag) {
  std::ostringstream geo;
  for (std::size_t j = 0; j < cuts.size(); ++j) {
    geo << "Line(" << first_tag + static_cast<int>(j) << ") = {" << cuts[j].first + 1 << ", "
        << cuts[j].second + 1 << "};\n";
    geo << "Transfinite Curve {" << first_tag + static_cast<int>(j)
        << "} = " << cuts[j].segments + 1 << ";\n";
  }
  auto path = [&](std::ostringstream& loop, std::size_t from, std::size_t to) {
    for (std::size_t s = from; s < to; ++s)
      loop << ", " << outline_line_tag(section, s);
  };
  auto cut_line = [&](std::size_t j, bool reversed) {
    return (reversed ? ", -" : ", ") + std::to_string(first_tag + static_cast<int>(j));
  };
  std::vector<std::string> loops;
  {  // above the first cut: from its second point round through the tread to its first
    std::ostringstream loop;
    path(loop, cuts[0].second, section.wheel.size());
    loop << ", 1, 2";
    path(loop, section.tread_points - 1, cuts[0].first);
    loop << cut_line(0, false);
    loops.push_back(loop.str());
  }
  for (std::size_t j = 1; j + 1 < cuts.size(); j += 2) {  // between two strips
    std::ostringstream loop;
    path(loop, cuts[j].first, cuts[j + 1].first);
    loop << cut_line(j + 1, false);
    path(loop, cuts[j + 1].second, cuts[j].second);
    loop << cut_line(j, true);
    loops.push_back(loop.str());
  }
  {  // below the last cut
    std::ostringstream loop;
    path(loop, cuts.back().first, cuts.back().second);
    loop << cut_line(cuts.size() - 1, true);
    loops.push_back(loop.str());
  }
  std::ostringstream surfaces;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const int tag = i == 0 ? 1 : 100 + static_cast<int>(i);
    geo << "Curve Loop(" << tag << ") = {" << loops[i].substr(2) << "};\n";
    geo << "Plane Surface(" << tag << ") = {" << tag << "};\n";
    surfaces << (i > 0 ? ", " : "") << tag;
  }
  geo << "Physical Surface(\"wheel\", 1) = {" << surfaces.str() << "};\n";
  return geo.str();
}

std::vector<int> add_transition_strips(SectionMesh& mesh, const std::vector<WheelCut>& cuts,
                                       const WheelSection& section) {
  int block = -1;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    if (mesh.blocks[b].name == "wheel")
      block = static_cast<int>(b);
  if (block < 0)
    throw std::logic_error("railfe: wheel transitions: the section has no block 'wheel'");
  // The section's nodes on each cut, along it.
  std::vector<std::vector<GlobalIndex>> on_cut(cuts.size());
  for (std::size_t j = 0; j < cuts.size(); ++j) {
    const double a0 = section.wheel[cuts[j].first][1], a1 = section.wheel[cuts[j].second][1];
    for (GlobalIndex i = 0; i < mesh.n_nodes(); ++i) {
      const double r = mesh.coordinates[2 * i], a = mesh.coordinates[2 * i + 1];
      if (std::abs(r - cuts[j].radius) < 1e-9 && a >= std::min(a0, a1) - 1e-9 &&
          a <= std::max(a0, a1) + 1e-9)
        on_cut[j].push_back(i);
    }
    std::sort(on_cut[j].begin(), on_cut[j].end(), [&](GlobalIndex p, GlobalIndex q) {
      return mesh.coordinates[2 * p + 1] < mesh.coordinates[2 * q + 1];
    });
  }
  for (std::size_t p = 0; p + 1 < cuts.size(); p += 2) {
    const auto &top = on_cut[p], &bottom = on_cut[p + 1];
    if (top.size() != bottom.size() || top.size() < 2)
      throw RunError(mesh.source + ": gmsh put " + std::to_string(top.size()) + " and " +
                     std::to_string(bottom.size()) +
                     " points on the cuts at r = " + mm(cuts[p].radius) + " and " +
                     mm(cuts[p + 1].radius) + " (the same number expected)");
    for (std::size_t k = 0; k + 1 < top.size(); ++k) {
      mesh.quads.push_back({top[k], top[k + 1], bottom[k + 1], bottom[k]});
      mesh.quad_blocks.push_back(block);
    }
  }
  std::vector<int> level(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (GlobalIndex i = 0; i < mesh.n_nodes(); ++i)
    for (std::size_t p = 1; p < cuts.size(); p += 2)
      level[i] += mesh.coordinates[2 * i] < cuts[p].radius + 1e-9 ? 1 : 0;
  return level;
}

std::vector<std::vector<std::size_t>> coarser_wheel_slices(const std::vector<double>& angles,
                                                           const std::vector<double>& largest) {
  std::vector<std::vector<std::size_t>> result;
  std::vector<std::size_t> finer(angles.size());
  for (std::size_t k = 0; k < angles.size(); ++k)
    finer[k] = k;
  for (std::size_t level = 0; level < largest.size(); ++level) {
    auto angle = [&](std::size_t j) {
      return j < finer.size() ? angles[finer[j]] : angles[0] + 2 * kPi;
    };
    auto merges = [&](std::size_t j) {
      return angle(j + 3) - angle(j) <= largest[level] * (1 + 1e-9);
    };
    // Forward over the first half, backward over the second, so that the fine slices on both
    // sides of the arc (it starts at index 0 and ends the list) merge from the arc outwards.
    const std::size_t half = finer.size() / 2;
    std::vector<std::size_t> coarser;
    for (std::size_t j = 0; j < half;) {
      coarser.push_back(finer[j]);
      j += j + 3 <= half && merges(j) ? 3 : 1;
    }
    std::vector<std::size_t> tail;
    for (std::size_t end = finer.size(); end > half;) {
      const bool three = end >= half + 3 && merges(end - 3);
      end -= three ? 3 : 1;
      tail.push_back(finer[end]);
    }
    coarser.insert(coarser.end(), tail.rbegin(), tail.rend());
    result.push_back(coarser);
    finer = coarser;
  }
  return result;
}

}  // namespace railfe
