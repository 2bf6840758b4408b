#include "contact/laws/fastsim.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railfe {

FastsimResult fastsim(const KalkerCoefficients& c, double G, double a, double b, double load,
                      double friction, const Creepages& creep, const FastsimSettings& settings) {
  if (!(a > 0 && b > 0 && load > 0 && friction >= 0 && G > 0 && settings.cells_x > 0 &&
        settings.strips > 0))
    throw std::invalid_argument("FASTSIM needs positive semi-axes, load, modulus and grid");
  // Flexibilities that reproduce the linear theory for small creepages (Kalker 1982).
  const double L1 = 8 * a / (3 * c.C11 * G), L2 = 8 * a / (3 * c.C22 * G);
  const double L3 = M_PI * a * std::sqrt(a / b) / (4 * c.C23 * G);
  const double ab = a * b;
  FastsimResult r;
  const std::size_t n = static_cast<std::size_t>(settings.cells_x) * settings.strips;
  if (settings.fields)
    for (auto* field : {&r.x, &r.y, &r.px, &r.py, &r.bound})
      field->reserve(n);
  double adhesion_area = 0, area = 0;
  const double dy = 2 * b / settings.strips;
  // Loop invariants hoisted by hand: the fields' push_back keeps the compiler from doing it.
  const double rate_x = creep.longitudinal / L1, rate_y = creep.lateral / L2;
  const double spin_rate = creep.spin / L3, inverse_a2 = 1 / (a * a);
  const bool parabolic = settings.bound == TractionBound::parabolic;
  const double peak = friction * (parabolic ? 2 * load / (M_PI * ab) : 3 * load / (2 * M_PI * ab));
  for (int j = 0; j < settings.strips; ++j) {
    const double y = -b + (j + 0.5) * dy;
    const double across = 1 - (y / b) * (y / b);
    const double half = a * std::sqrt(across);  // strip half-length
    const double dx = 2 * half / settings.cells_x;
    const double gain_x = rate_x - spin_rate * y;
    double px = 0, py = 0, fx = 0, fy = 0, mz = 0;
    int adhering = 0;
    for (int i = 0; i < settings.cells_x; ++i) {
      const double x = half - (i + 0.5) * dx;  // leading edge first
      // Deflection gained while rolling to this cell's centre: the rigid slip times the distance
      // (half a cell from the leading edge to the first centre, a cell between centres).
      // The spin's slip grows linearly in x, so it is taken at the interval's midpoint (exact).
      const double step = i == 0 ? 0.5 * dx : dx, middle = x + 0.5 * step;
      px -= gain_x * step;
      py -= (rate_y + spin_rate * middle) * step;
      const double shape = std::max(across - x * x * inverse_a2, 0.0);
      const double limit = peak * (parabolic ? shape : std::sqrt(shape));
      // Squared magnitudes: std::hypot's overflow guard made FASTSIM a quarter slower.
      const double squared = px * px + py * py;
      const bool adheres = squared <= limit * limit;
      if (!adheres) {
        const double scale = limit / std::sqrt(squared);
        px *= scale;
        py *= scale;
      }
      fx += px;
      fy += py;
      mz += x * py - y * px;
      adhering += adheres ? 1 : 0;
      if (settings.fields) {
        r.x.push_back(x);
        r.y.push_back(y);
        r.px.push_back(px);
        r.py.push_back(py);
        r.bound.push_back(limit);
        r.adhesion.push_back(adheres);
      }
    }
    const double cell = dx * dy;
    r.forces.Fx += fx * cell;
    r.forces.Fy += fy * cell;
    r.forces.Mz += mz * cell;
    area += cell * settings.cells_x;
    adhesion_area += cell * adhering;
  }
  r.adhesion_fraction = adhesion_area / area;
  return r;
}

}  // namespace railfe
