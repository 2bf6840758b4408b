#include "physics/implicit/moving_bridge_model.hpp"

#include <stdexcept>

namespace railfe {

BridgeModel simply_supported_bridge(double span, int n_elements, int n_lines, double spacing,
                                    const BeamMaterial& material, const BeamSection& section,
                                    BeamMass mass_kind) {
  if (n_elements < 2 || n_elements % 2 != 0 || n_lines < 1)
    throw std::invalid_argument("a bridge needs an even number of elements and a line");
  const int stations = n_elements + 1;
  auto node = [stations](int line, int station) { return line * stations + station; };
  auto where = [&](int line, int station) {
    return Eigen::Vector3d(span * station / n_elements, spacing * line, 0.0);
  };
  // Unknown of each DOF, −1 for a support's.
  std::vector<long> unknown(static_cast<std::size_t>(6 * n_lines * stations), 0);
  long count = 0;
  for (int line = 0; line < n_lines; ++line)
    for (int station = 0; station < stations; ++station)
      for (int c = 0; c < 6; ++c) {
        const bool end = station == 0 || station == n_elements;
        const bool fixed = (end && (c == 1 || c == 2 || c == 3)) || (station == 0 && c == 0);
        unknown[6 * node(line, station) + c] = fixed ? -1 : count++;
      }
  BridgeModel model;
  model.n_unknowns = static_cast<std::size_t>(count);
  std::vector<Eigen::Triplet<double>> k, m;
  auto add = [&](int from, int to, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& orientation, bool on_path) {
    const BeamElement beam(a, b, orientation, material, section, false);
    const Matrix12 ke = beam.stiffness(), me = beam.mass(mass_kind);
    std::array<long, 12> dofs;
    for (int c = 0; c < 6; ++c) {
      dofs[c] = unknown[6 * from + c];
      dofs[6 + c] = unknown[6 * to + c];
    }
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        if (dofs[i] >= 0 && dofs[j] >= 0) {
          k.emplace_back(dofs[i], dofs[j], ke(i, j));
          if (me(i, j) != 0)
            m.emplace_back(dofs[i], dofs[j], me(i, j));
        }
    if (on_path)
      model.path.push_back({beam, dofs});
  };
  const Eigen::Vector3d up(0, 0, 1);
  for (int line = 0; line < n_lines; ++line)
    for (int e = 0; e < n_elements; ++e)
      add(node(line, e), node(line, e + 1), where(line, e), where(line, e + 1), up, line == 0);
  for (int line = 0; line + 1 < n_lines; ++line)
    for (int station = 1; station < n_elements; ++station)
      add(node(line, station), node(line + 1, station), where(line, station),
          where(line + 1, station), up, false);
  model.stiffness.resize(count, count);
  model.mass.resize(count, count);
  model.stiffness.setFromTriplets(k.begin(), k.end());
  model.mass.setFromTriplets(m.begin(), m.end());
  model.midspan_vertical = unknown[6 * node(0, n_elements / 2) + 2];
  return model;
}

}  // namespace railfe
