#include "physics/modal/mode_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>

namespace railfe {
namespace {

using Vector3 = std::array<double, 3>;

constexpr double kPi = 3.14159265358979323846;

// Cylindrical component indices; the family names follow the same order.
constexpr int kRadial = 0;
constexpr int kCircumferential = 1;
constexpr int kAxial = 2;
constexpr const char* kFamilyNames[3] = {"radial", "circumferential", "axial"};
constexpr const char* kAmbiguous = "ambiguous";

// A mode of a cyclic-symmetric body is separable, so every ring sees the harmonic with the same
// phase (up to sign) and |Σ c²| / Σ |c|² is 1; below this the rings disagree on where the
// maximum is, and no single radial line represents the mode.
constexpr double kMinimumPhaseCoherence = 0.5;

// The rim counts as still when its largest displacement is below this share of the body's.
constexpr double kStillRim = 1e-12;

void require(bool condition, const std::string& message) {
  if (!condition)
    throw std::invalid_argument("classify_mode: " + message);
}

double dot(const Vector3& a, const Vector3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vector3 scaled(const Vector3& a, double factor) {
  return {a[0] * factor, a[1] * factor, a[2] * factor};
}

Vector3 difference(const Vector3& a, const Vector3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f %%", 100 * share);
  return text;
}

void append_note(std::string& note, const std::string& addition) {
  note += note.empty() ? addition : "; " + addition;
}

// Right-handed (first, second, axis) with the axis normalised.
struct CylindricalBasis {
  Vector3 axis;
  Vector3 first;
  Vector3 second;
};

CylindricalBasis make_basis(const Vector3& axis) {
  const double length = std::sqrt(dot(axis, axis));
  require(length > 0 && std::isfinite(length), "the axis of revolution is zero or not finite");
  CylindricalBasis basis;
  basis.axis = scaled(axis, 1 / length);
  int least_aligned = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(basis.axis[i]) < std::abs(basis.axis[least_aligned]))
      least_aligned = i;
  }
  Vector3 reference{0, 0, 0};
  reference[least_aligned] = 1;
  const Vector3 projected = difference(reference, scaled(basis.axis, dot(reference, basis.axis)));
  basis.first = scaled(projected, 1 / std::sqrt(dot(projected, projected)));
  basis.second = cross(basis.axis, basis.first);
  return basis;
}

// A node in cylindrical coordinates; displacement holds (u_r, u_θ, u_a).
struct CylindricalNode {
  double radius = 0;
  double angle = 0;  // in [0, 2π)
  double axial = 0;
  Vector3 displacement{0, 0, 0};
};

CylindricalNode to_cylindrical(const Vector3& point, const Vector3& displacement,
                               const Vector3& origin, const CylindricalBasis& basis) {
  const Vector3 relative = difference(point, origin);
  const double x = dot(relative, basis.first);
  const double y = dot(relative, basis.second);
  CylindricalNode node;
  node.radius = std::hypot(x, y);
  node.angle = std::atan2(y, x);
  if (node.angle < 0)
    node.angle += 2 * kPi;
  node.axial = dot(relative, basis.axis);
  const double cosine = std::cos(node.angle);
  const double sine = std::sin(node.angle);
  const double along_first = dot(displacement, basis.first);
  const double along_second = dot(displacement, basis.second);
  node.displacement[kRadial] = along_first * cosine + along_second * sine;
  node.displacement[kCircumferential] = -along_first * sine + along_second * cosine;
  node.displacement[kAxial] = dot(displacement, basis.axis);
  return node;
}

// Nodes of equal radius and axial position, sorted by angle. Each node is weighted by its
// angular share (half the gaps to its neighbours) so that sums approximate integrals over θ
// even where the spacing is uneven, and rings of different node counts weigh alike.
struct Ring {
  double radius = 0;
  double axial = 0;
  std::vector<std::size_t> nodes;
  std::vector<double> weights;
};

// Sorts indices by key and splits them where consecutive keys differ by more than tolerance.
template <typename Key>
std::vector<std::vector<std::size_t>> split_at_gaps(std::vector<std::size_t> indices, Key key,
                                                    double tolerance) {
  std::sort(indices.begin(), indices.end(),
            [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t k = 0; k < indices.size(); ++k) {
    if (k == 0 || key(indices[k]) - key(indices[k - 1]) > tolerance)
      groups.emplace_back();
    groups.back().push_back(indices[k]);
  }
  return groups;
}

Ring make_ring(std::vector<std::size_t> members, const std::vector<CylindricalNode>& nodes) {
  std::sort(members.begin(), members.end(),
            [&](std::size_t a, std::size_t b) { return nodes[a].angle < nodes[b].angle; });
  Ring ring;
  const std::size_t count = members.size();
  for (std::size_t index : members) {
    ring.radius += nodes[index].radius / count;
    ring.axial += nodes[index].axial / count;
  }
  ring.weights.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t next = (k + 1) % count;
    double gap = nodes[members[next]].angle - nodes[members[k]].angle;
    if (next == 0)
      gap += 2 * kPi;
    ring.weights[k] += gap / 2;
    ring.weights[next] += gap / 2;
  }
  ring.nodes = std::move(members);
  return ring;
}

// Rings of 3 or more nodes off the axis; the count of smaller rings goes to skipped.
std::vector<Ring> group_rings(const std::vector<CylindricalNode>& nodes, double tolerance,
                              int& skipped) {
  std::vector<std::size_t> off_axis;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].radius > tolerance)
      off_axis.push_back(i);
  }
  std::vector<Ring> rings;
  skipped = 0;
  const auto axial = [&](std::size_t i) { return nodes[i].axial; };
  const auto radius = [&](std::size_t i) { return nodes[i].radius; };
  for (auto& layer : split_at_gaps(std::move(off_axis), axial, tolerance)) {
    for (auto& members : split_at_gaps(std::move(layer), radius, tolerance)) {
      if (members.size() < 3) {
        ++skipped;
      } else {
        rings.push_back(make_ring(std::move(members), nodes));
      }
    }
  }
  return rings;
}

// Power of each harmonic and component over the rim: power[n][c] is Σ over rings of
// ∫ (harmonic n of u_c)² dθ, so that for evenly spaced rings Σ_n power[n][c] = energy[c]
// (Parseval) when every harmonic up to the Nyquist limit is examined. Complex coefficients are
// never summed across rings (rings moving in opposite senses would cancel); their squares are,
// only to find the phase.
struct RimSpectrum {
  std::vector<Vector3> power;
  std::vector<std::array<std::complex<double>, 3>> squared_coefficients;
  std::vector<Vector3> coefficient_magnitudes;  // Σ |c|², the bound on |Σ c²|
  Vector3 energy{0, 0, 0};                      // Σ over rings of ∫ u_c² dθ
  double largest_displacement = 0;
  int rings = 0;
};

void add_ring_energy(const Ring& ring, const std::vector<CylindricalNode>& nodes,
                     RimSpectrum& spectrum) {
  for (std::size_t k = 0; k < ring.nodes.size(); ++k) {
    const Vector3& u = nodes[ring.nodes[k]].displacement;
    for (int c = 0; c < 3; ++c)
      spectrum.energy[c] += u[c] * u[c] * ring.weights[k];
    spectrum.largest_displacement = std::max(spectrum.largest_displacement, std::sqrt(dot(u, u)));
  }
}

void add_ring_harmonics(const Ring& ring, const std::vector<CylindricalNode>& nodes,
                        RimSpectrum& spectrum) {
  const int count = static_cast<int>(ring.nodes.size());
  const int highest = std::min(static_cast<int>(spectrum.power.size()) - 1, count / 2);
  for (int n = 0; n <= highest; ++n) {
    std::array<std::complex<double>, 3> coefficient{};
    for (std::size_t k = 0; k < ring.nodes.size(); ++k) {
      const CylindricalNode& node = nodes[ring.nodes[k]];
      const std::complex<double> kernel = std::polar(ring.weights[k], -n * node.angle);
      for (int c = 0; c < 3; ++c)
        coefficient[c] += node.displacement[c] * kernel;
    }
    // The one-sided spectrum counts ±n together except at n = 0 and the Nyquist harmonic.
    const double factor = (n == 0 || 2 * n == count) ? 1 : 2;
    for (int c = 0; c < 3; ++c) {
      spectrum.power[n][c] += factor * std::norm(coefficient[c]) / (2 * kPi);
      spectrum.squared_coefficients[n][c] += coefficient[c] * coefficient[c];
      spectrum.coefficient_magnitudes[n][c] += std::norm(coefficient[c]);
    }
  }
}

// Harmonics up to max_diameters, or the Nyquist limit of the finest rim ring if lower.
RimSpectrum rim_spectrum(const std::vector<Ring>& rings, const std::vector<CylindricalNode>& nodes,
                         double rim_radius, int max_diameters) {
  std::size_t highest = 0;
  for (const Ring& ring : rings) {
    if (ring.radius >= rim_radius)
      highest = std::max(highest, ring.nodes.size() / 2);
  }
  highest = std::min(highest, static_cast<std::size_t>(max_diameters));
  RimSpectrum spectrum;
  spectrum.power.assign(highest + 1, Vector3{0, 0, 0});
  spectrum.squared_coefficients.resize(highest + 1);
  spectrum.coefficient_magnitudes.assign(highest + 1, Vector3{0, 0, 0});
  for (const Ring& ring : rings) {
    if (ring.radius < rim_radius)
      continue;
    add_ring_energy(ring, nodes, spectrum);
    add_ring_harmonics(ring, nodes, spectrum);
    ++spectrum.rings;
  }
  return spectrum;
}

double total(const Vector3& values) {
  return values[0] + values[1] + values[2];
}

// The family's component, or -1 (with a note) when no component dominates.
int choose_family(const Vector3& energy, double threshold, std::string& note) {
  const double all = total(energy);
  const double in_plane = energy[kRadial] + energy[kCircumferential];
  if (energy[kAxial] >= threshold * all)
    return kAxial;
  if (in_plane < threshold * all) {
    append_note(note, "energy split between out of plane (" + percent(energy[kAxial] / all) +
                          ") and in plane (" + percent(in_plane / all) + ")");
    return -1;
  }
  if (energy[kRadial] >= threshold * in_plane)
    return kRadial;
  if (energy[kCircumferential] >= threshold * in_plane)
    return kCircumferential;
  append_note(note, "in-plane energy split between radial (" + percent(energy[kRadial] / in_plane) +
                        ") and circumferential (" + percent(energy[kCircumferential] / in_plane) +
                        ")");
  return -1;
}

// The harmonic of largest power (the lowest on ties) and its share of the rim's energy.
std::pair<int, double> dominant_harmonic(const RimSpectrum& spectrum) {
  int best = 0;
  for (std::size_t n = 1; n < spectrum.power.size(); ++n) {
    if (total(spectrum.power[n]) > total(spectrum.power[best]))
      best = static_cast<int>(n);
  }
  return {best, total(spectrum.power[best]) / total(spectrum.energy)};
}

int strongest_component(const Vector3& power) {
  return static_cast<int>(std::max_element(power.begin(), power.end()) - power.begin());
}

// One angle in [0, π/n) where u_c is largest in magnitude: with c_n = A π e^{−inθ₀} on each
// ring, Σ c_n² has argument −2nθ₀ whatever the signs A of the rings. Negative when the rings
// disagree on the phase.
double maximum_angle(const RimSpectrum& spectrum, int n, int component) {
  if (n == 0)
    return 0;
  const std::complex<double> sum = spectrum.squared_coefficients[n][component];
  if (std::abs(sum) < kMinimumPhaseCoherence * spectrum.coefficient_magnitudes[n][component]) {
    return -1;
  }
  const double period = kPi / n;
  double angle = std::fmod(-std::arg(sum) / (2 * n), period);
  if (angle < 0)
    angle += period;
  return angle < period ? angle : 0;  // −ε + period rounds to period
}

double angular_distance(double a, double b) {
  const double distance = std::fmod(std::abs(a - b), 2 * kPi);
  return std::min(distance, 2 * kPi - distance);
}

// The node of the ring nearest to angle, if within half the mean spacing, and (for n ≥ 1)
// within π/(4n) of it, where cos(nΔθ) ≥ 0.7 keeps the sign of the value it samples.
const CylindricalNode* node_near(const Ring& ring, const std::vector<CylindricalNode>& nodes,
                                 double angle, int n) {
  const CylindricalNode* nearest = nullptr;
  double nearest_distance = 0;
  for (std::size_t index : ring.nodes) {
    const double distance = angular_distance(nodes[index].angle, angle);
    if (nearest == nullptr || distance < nearest_distance) {
      nearest = &nodes[index];
      nearest_distance = distance;
    }
  }
  double limit = kPi / ring.nodes.size();
  if (n > 0)
    limit = std::min(limit, kPi / (4 * n));
  return nearest_distance <= limit * (1 + 1e-9) ? nearest : nullptr;
}

// Radial bins of the nodal-circle line. Nodes through the thickness of an unstructured section
// rarely share a radius exactly, and bending makes u_r change sign through the thickness, so
// values are averaged over bins of this share of the line's length: fine enough for a handful of
// nodal circles, coarse enough to span the web's thickness.
constexpr int kRadialBins = 25;

// (radius, value of u_c) along the radial line at angle, averaged over nodes in each radial bin
// (through the thickness, where bending makes u_r change sign), sorted by radius.
std::vector<std::pair<double, double>> radial_profile(const std::vector<Ring>& rings,
                                                      const std::vector<CylindricalNode>& nodes,
                                                      double angle, int n, int component,
                                                      double inner, double outer,
                                                      double tolerance) {
  std::vector<std::pair<double, double>> samples;
  for (const Ring& ring : rings) {
    if (ring.radius < inner - tolerance || ring.radius > outer + tolerance)
      continue;
    if (const CylindricalNode* node = node_near(ring, nodes, angle, n)) {
      samples.emplace_back(ring.radius, node->displacement[component]);
    }
  }
  std::sort(samples.begin(), samples.end());
  const double bin = std::max(tolerance, (outer - inner) / kRadialBins);
  std::vector<std::pair<double, double>> profile;
  for (std::size_t first = 0; first < samples.size();) {
    std::size_t last = first;
    double sum = 0;
    while (last < samples.size() && samples[last].first - samples[first].first <= bin) {
      sum += samples[last++].second;
    }
    profile.emplace_back(samples[first].first, sum / (last - first));
    first = last;
  }
  return profile;
}

// Sign changes along the profile, values within noise_fraction of its largest magnitude taken
// as zero; -1 when the profile does not move.
int count_sign_changes(const std::vector<std::pair<double, double>>& profile,
                       double noise_fraction) {
  double largest = 0;
  for (const auto& sample : profile)
    largest = std::max(largest, std::abs(sample.second));
  if (!(largest > 0))
    return -1;
  int changes = 0;
  int previous_sign = 0;
  for (const auto& sample : profile) {
    if (std::abs(sample.second) <= noise_fraction * largest)
      continue;
    const int sign = sample.second > 0 ? 1 : -1;
    if (previous_sign != 0 && sign != previous_sign)
      ++changes;
    previous_sign = sign;
  }
  return changes;
}

void check_settings(const ClassifierSettings& settings) {
  require(settings.rim_fraction > 0 && settings.rim_fraction <= 1, "rim_fraction not in (0, 1]");
  require(settings.dominance > 0 && settings.dominance <= 1, "dominance not in (0, 1]");
  require(settings.family_dominance > 0.5 && settings.family_dominance <= 1,
          "family_dominance not in (0.5, 1]");
  require(settings.noise_fraction >= 0 && settings.noise_fraction < 1,
          "noise_fraction not in [0, 1)");
  require(settings.relative_tolerance > 0 && settings.relative_tolerance < 1,
          "relative_tolerance not in (0, 1)");
  require(settings.max_diameters >= 0, "max_diameters negative");
  require(settings.web_inner_radius >= 0 && std::isfinite(settings.web_inner_radius),
          "web_inner_radius negative or not finite");
  require(settings.web_outer_radius >= 0 && std::isfinite(settings.web_outer_radius),
          "web_outer_radius negative or not finite");
}

void check_inputs(const std::vector<Vector3>& points, const std::vector<Vector3>& displacements,
                  const AxisymmetricFrame& frame) {
  require(points.size() == displacements.size(), std::to_string(points.size()) + " points but " +
                                                     std::to_string(displacements.size()) +
                                                     " displacements");
  const auto finite = [](const Vector3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
  };
  require(std::all_of(points.begin(), points.end(), finite) &&
              std::all_of(displacements.begin(), displacements.end(), finite) &&
              finite(frame.origin),
          "a coordinate or displacement is not finite");
}

// Radial and axial extents of the body.
struct Extent {
  double inner = 0;
  double outer = 0;
  double axial_low = 0;
  double axial_high = 0;
};

Extent body_extent(const std::vector<CylindricalNode>& nodes) {
  Extent extent{nodes[0].radius, nodes[0].radius, nodes[0].axial, nodes[0].axial};
  for (const CylindricalNode& node : nodes) {
    extent.inner = std::min(extent.inner, node.radius);
    extent.outer = std::max(extent.outer, node.radius);
    extent.axial_low = std::min(extent.axial_low, node.axial);
    extent.axial_high = std::max(extent.axial_high, node.axial);
  }
  return extent;
}

double largest_displacement(const std::vector<Vector3>& displacements) {
  double largest = 0;
  for (const Vector3& u : displacements)
    largest = std::max(largest, std::sqrt(dot(u, u)));
  return largest;
}

// Family and energy shares from the rim; the family's component, or -1.
int classify_family(const RimSpectrum& spectrum, const ClassifierSettings& settings,
                    ModeClass& result) {
  const double all = total(spectrum.energy);
  result.radial_share = spectrum.energy[kRadial] / all;
  result.circumferential_share = spectrum.energy[kCircumferential] / all;
  result.axial_share = spectrum.energy[kAxial] / all;
  const int component = choose_family(spectrum.energy, settings.family_dominance, result.note);
  result.family = component < 0 ? kAmbiguous : kFamilyNames[component];
  return component;
}

// n and its share; false (with a note) when no harmonic dominates.
bool classify_diameters(const RimSpectrum& spectrum, const ClassifierSettings& settings,
                        ModeClass& result) {
  const auto [n, share] = dominant_harmonic(spectrum);
  result.diameter_share = share;
  if (share >= settings.dominance) {
    result.nodal_diameters = n;
    return true;
  }
  append_note(result.note, "no harmonic dominates: n = " + std::to_string(n) + " carries " +
                               percent(share) + " of the rim's power (harmonics up to " +
                               std::to_string(spectrum.power.size() - 1) + " examined)");
  return false;
}

void classify_circles(const std::vector<Ring>& rings, const std::vector<CylindricalNode>& nodes,
                      const Extent& extent, double angle, int component, double tolerance,
                      const ClassifierSettings& settings, ModeClass& result) {
  const double inner = settings.web_inner_radius > 0 ? settings.web_inner_radius : extent.inner;
  const double outer = settings.web_outer_radius > 0 ? settings.web_outer_radius : extent.outer;
  const auto profile = radial_profile(rings, nodes, angle, result.nodal_diameters, component, inner,
                                      outer, tolerance);
  result.nodal_circles = count_sign_changes(profile, settings.noise_fraction);
  if (result.nodal_circles < 0) {
    append_note(result.note, profile.empty() ? "no web node on the line of maximum amplitude"
                                             : "the web does not move on the line of maximum "
                                               "amplitude");
  }
}

}  // namespace

ModeClass classify_mode(const std::vector<std::array<double, 3>>& points,
                        const std::vector<std::array<double, 3>>& displacements,
                        const AxisymmetricFrame& frame, const ClassifierSettings& settings) {
  check_inputs(points, displacements, frame);
  check_settings(settings);
  const CylindricalBasis basis = make_basis(frame.axis);
  ModeClass result;
  const double body_motion = largest_displacement(displacements);
  if (!(body_motion > 0)) {
    result.note = "zero mode shape";
    return result;
  }
  std::vector<CylindricalNode> nodes;
  nodes.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    nodes.push_back(to_cylindrical(points[i], displacements[i], frame.origin, basis));
  const Extent extent = body_extent(nodes);
  const double size = std::max(extent.outer, extent.axial_high - extent.axial_low);
  const double tolerance = settings.relative_tolerance * size;
  int skipped = 0;
  const std::vector<Ring> rings = group_rings(nodes, tolerance, skipped);
  if (skipped > 0) {
    append_note(result.note, std::to_string(skipped) + " ring(s) with fewer than 3 nodes skipped");
  }
  const double rim_radius =
      extent.outer - settings.rim_fraction * (extent.outer - extent.inner) - tolerance;
  const RimSpectrum spectrum = rim_spectrum(rings, nodes, rim_radius, settings.max_diameters);
  if (spectrum.rings == 0) {
    append_note(result.note, "no rim ring with 3 or more nodes");
    return result;
  }
  if (spectrum.largest_displacement <= kStillRim * body_motion) {
    append_note(result.note, "the rim does not move");
    return result;
  }
  const int component = classify_family(spectrum, settings, result);
  if (!classify_diameters(spectrum, settings, result))
    return result;
  const int n = result.nodal_diameters;
  const int phase_component = component >= 0 ? component : strongest_component(spectrum.power[n]);
  const double angle = maximum_angle(spectrum, n, phase_component);
  if (angle < 0) {
    append_note(result.note, "rim rings disagree on the angle of maximum amplitude");
    return result;
  }
  result.phase_angle = angle;
  if (component < 0)
    return result;
  classify_circles(rings, nodes, extent, angle, component, tolerance, settings, result);
  return result;
}

}  // namespace railfe
