#include "physics/explicit/convected_start.hpp"

#include "physics/explicit/ghost_exchange.hpp"

namespace railfe {

void add_convected_velocity(const SolidElements& elements, const double* u,
                            const std::array<double, 3>& frame, LocalIndex n_owned,
                            GhostExchange* ghosts, const std::vector<bool>& skip, double* v) {
  const std::size_t n_values = 3 * static_cast<std::size_t>(elements.n_nodes);
  // column[j][3 node + i]: Σ V_e ∂u_i/∂X_j over the node's elements; weight[3 node]: Σ V_e.
  std::array<std::vector<double>, 3> column;
  for (auto& c : column)
    c.assign(n_values, 0.0);
  std::vector<double> weight(n_values, 0.0);
  const int n_points = elements.n_points;
  for (LocalIndex e = 0; e < elements.n_elements; ++e) {
    // The mean of the element's point gradients: its centre gradient for one point.
    double gradient[3][3] = {};
    for (int q = 0; q < n_points; ++q) {
      const double* g = &elements.gradients[24 * (static_cast<std::size_t>(e) * n_points + q)];
      for (int a = 0; a < 8; ++a) {
        const std::size_t node = elements.nodes[8 * static_cast<std::size_t>(e) + a];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            gradient[i][j] += u[3 * node + i] * g[j * 8 + a] / n_points;
      }
    }
    const double volume = elements.volume[e];
    for (int a = 0; a < 8; ++a) {
      const std::size_t node = elements.nodes[8 * static_cast<std::size_t>(e) + a];
      weight[3 * node] += volume;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          column[j][3 * node + i] += volume * gradient[i][j];
    }
  }
  if (ghosts) {
    ghosts->sum_into_owners(weight.data());
    for (auto& c : column)
      ghosts->sum_into_owners(c.data());
  }
  for (LocalIndex node = 0; node < n_owned; ++node) {
    const std::size_t k = 3 * static_cast<std::size_t>(node);
    if (skip[node] || !(weight[k] > 0))
      continue;
    const double w[3] = {v[k] - frame[0], v[k + 1] - frame[1], v[k + 2] - frame[2]};
    for (int i = 0; i < 3; ++i) {
      double rate = 0;
      for (int j = 0; j < 3; ++j)
        rate += column[j][k + i] * w[j];
      v[k + i] += rate / weight[k];
    }
  }
}

}  // namespace railfe
