#pragma once
/// \file
/// The direct method's moving constraints (Neves, Azevedo & Calçada 2012; Montenegro et al.
/// 2015): a vehicle unknown tied to the point of a beam beneath it, which travels along a chain
/// of beam elements at constant speed, s(t) = s0 + v t. Each row reads
///   u_vehicle − e_dᵀ N(ξ(s)) u_element = r_d(s)   (d = vertical z or lateral y, global axes),
/// N from beam_translation_interpolation() and r_d the irregularity of the running surface. The
/// rows switch element as the point travels. A vertical constraint whose force would pull
/// releases (with its lateral row) and engages again when the vehicle point reaches the
/// surface; both are recorded with time and place. A point that leaves the path is an error.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "framework/time/constraint_set.hpp"
#include "physics/elements/beam_element.hpp"

namespace railfe {

/// One element of a path: the beam and the unknown of each of its 12 global DOFs (−1: fixed).
struct PathElement {
  BeamElement beam;               ///< the element
  std::array<long, 12> unknowns;  ///< unknown index of each DOF, or −1 for a fixed one
};

/// Beam elements end to end, travelled by arc length s ∈ [0, length()].
class BeamPath {
 public:
  /// The chain \p elements in travel order (the element ends are taken to meet).
  explicit BeamPath(std::vector<PathElement> elements);
  /// Total length (m).
  double length() const { return starts_.back(); }
  /// Number of elements.
  std::size_t size() const { return elements_.size(); }
  /// Element \p index.
  const PathElement& element(std::size_t index) const { return elements_[index]; }
  /// The element that holds \p s and ξ there; false when s lies outside [0, length()].
  bool locate(double s, std::size_t& index, double& xi) const;

 private:
  std::vector<PathElement> elements_;
  std::vector<double> starts_;  // s at each element's start, then the total length
};

/// Offsets of the running surface against s: vertical (up, m) and lateral (m).
class Irregularity {
 public:
  /// A smooth surface (both offsets zero).
  Irregularity() = default;
  /// The offsets given as functions of s (either may be empty: zero).
  Irregularity(std::function<double(double)> vertical, std::function<double(double)> lateral);
  /// From a CSV file with a header line and columns s (m), vertical (m), lateral (m), s strictly
  /// increasing; linear between rows. Throws RunError naming the file for a bad file, and
  /// later for an s outside the table.
  static Irregularity from_csv(const std::string& path);
  /// Vertical offset at \p s.
  double vertical(double s) const { return vertical_ ? vertical_(s) : 0.0; }
  /// Lateral offset at \p s.
  double lateral(double s) const { return lateral_ ? lateral_(s) : 0.0; }

 private:
  std::function<double(double)> vertical_, lateral_;
};

/// One vehicle point on the path.
struct MovingContactPoint {
  std::string name;            ///< for messages and events, e.g. "wheel 1"
  long vertical_unknown = -1;  ///< the vehicle unknown tied vertically (global z)
  long lateral_unknown = -1;   ///< the vehicle unknown tied laterally (global y), or −1
  double start = 0;            ///< s at t = 0 (m)
  double speed = 0;            ///< ds/dt (m/s)
  Irregularity irregularity;   ///< the running surface under this point
  bool may_separate = true;    ///< whether a pulling vertical force releases the point
};

/// A release (separation) or an engagement of a contact point.
struct ContactEvent {
  std::string contact;     ///< the point's name
  double time = 0;         ///< t_{n+1} of the step (s)
  double position = 0;     ///< s there (m)
  bool separation = true;  ///< true: released; false: engaged again
};

/// The constraints of moving contact points on one beam path.
class MovingContacts : public ConstraintSet {
 public:
  /// Points \p points travelling \p path (every point starts in contact).
  MovingContacts(BeamPath path, std::vector<MovingContactPoint> points);
  /// The rows of the engaged points at \p time; throws RunError when a point lies off the path.
  void rows_at(double time, ConstraintRows& rows) override;
  /// Releases points whose vertical force pulls (λ > 0), engages released points the vehicle
  /// reaches; records each change; true when anything changed.
  bool accept(double time, const double* u, const double* lambda) override;
  /// True when a point engaged at \p time: the landing's velocity jump is taken as a plastic
  /// impact (NewtonStepSolver::after_step()), which keeps the contact from chattering. Under a
  /// scheme without numerical damping (\p spectral_radius 1, α = 0) also true when a point's
  /// contact force has alternated step to step and grown for 10 steps to 0.1 % of itself: the
  /// multipliers' undamped mode, driven by the moving rows, which the restart sets at rest.
  bool needs_restart(double time, double spectral_radius) override;
  /// ġ − Ċ u = ṡ d(r + surface)/ds and g̈ − C̈ u − 2 Ċ v = ṡ² d²(r + surface)/ds² +
  /// 2 ṡ d(surface of v)/ds of each row, by central differences over ±1 cm of s.
  void rates(double time, const double* u, const double* v, std::size_t n_rows, double* velocity,
             double* acceleration) override;

  /// Vertical contact force (N, compression positive) of each point for the multipliers
  /// \p lambda of the rows last written at \p time (0 for a released point).
  std::vector<double> contact_forces(const double* lambda) const;
  /// The releases and engagements so far.
  const std::vector<ContactEvent>& events() const { return events_; }
  /// Position s of point \p index at \p time.
  double position(std::size_t index, double time) const;
  /// Adds the consistent nodal load of a vertical force \p force (N, up) at s to \p f.
  void add_point_load(double s, double force, double* f) const;

 private:
  /// Displacement of the surface at s along global axis \p axis (1: y, 2: z) for \p u.
  double surface(double s, int axis, const double* u) const;
  /// Appends the row of \p unknown against the surface along \p axis at s.
  void add_row(long unknown, double s, int axis, double offset, ConstraintRows& rows) const;
  /// Locates s or throws RunError for point \p index.
  void locate(std::size_t index, double time, double s, std::size_t& element, double& xi) const;

  BeamPath path_;
  std::vector<MovingContactPoint> points_;
  std::vector<bool> engaged_;
  std::vector<long> vertical_row_;  // row of each point's vertical constraint, or −1
  std::vector<double> changed_at_;  // time of each point's last release or engagement
  /// The step-to-step mode of one point's contact force F: its second differences.
  struct Alternation {
    double force[2] = {0, 0};     // F at the last two accepted steps
    int seen = 0;                 // accepted steps since the last reset (up to 3)
    double last = 0, before = 0;  // the last two second differences
    int run = 0;  // steps in a row whose second difference alternates in sign and grows
  };
  std::vector<Alternation> alternation_;
  bool restart_ = false;  // a point's force alternated: restart after this step
  std::vector<ContactEvent> events_;
};

}  // namespace railfe
