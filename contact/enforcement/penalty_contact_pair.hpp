#pragma once
/// \file
/// Penalty node-to-segment contact between a slave node set and a master surface of bilinear
/// quadrilaterals, with Coulomb or velocity-dependent friction by return mapping on the
/// incremental slip (docs/theory.md#penalty-contact). The pair sees plain arrays of its own
/// surface nodes (positions, step increments, forces); the time scheme that owns the nodes
/// (explicit dynamics) gathers and scatters them. One evaluate() per step; no allocation per step
/// once the search has warmed up.

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact/enforcement/friction_law.hpp"

namespace railfe {

class BucketSearch;

/// What a pair is made of, numbered within its surface: node i of the surface has its
/// coordinates at 3i .. 3i+2 of every array passed to the pair.
struct PenaltyPairGeometry {
  std::vector<int> slave_nodes;                  ///< surface indices of the slave nodes
  std::vector<double> slave_area;                ///< tributary area of each slave node (m²)
  std::vector<std::array<int, 4>> master_faces;  ///< surface indices, outward node order
  std::vector<double> face_stiffness;            ///< penalty stiffness k of each face (N/m)
  /// Cap on the stiffness of each slave node (N/m; LS-DYNA's smaller of segment and node):
  /// a node on a face gets the smaller of the two. Empty: no cap.
  std::vector<double> slave_stiffness;
  std::vector<double> mass;  ///< lumped mass of every surface node (kg)
  int n_surface_nodes = 0;   ///< size of the surface
};

/// The factor √(1 + ζ²) − ζ by which a viscous damper of fraction \p zeta lowers a spring's
/// central-difference limit 2/ω (ω Δt ≤ 2 (√(1 + ζ²) − ζ)).
inline double damped_step_factor(double zeta) {
  return std::sqrt(1 + zeta * zeta) - zeta;
}

/// The choices of a pair besides its geometry.
struct PenaltyPairSettings {
  std::string name;             ///< its deck name, for messages and files
  double damping_fraction = 0;  ///< normal damping as a fraction of critical, c = 2ζ√(k m)
  FrictionLaw friction;         ///< friction law
  int search_interval = 10;     ///< steps between rebuilds of the bucket search
  double search_margin = 0;     ///< distance beyond the motion at which faces are caught (m)
  std::array<double, 3> longitudinal{1, 0, 0};  ///< first tangent direction of the results (t₁)
};

/// The state of one slave node after the last evaluate().
struct SlaveContact {
  int face = -1;                             ///< master face in contact, −1 = none
  double xi = 0, eta = 0;                    ///< its natural coordinates on the face
  double gap = 0;                            ///< signed normal distance (m), < 0 = penetration
  double normal_force = 0;                   ///< ≥ 0 (N), on the slave along the normal
  std::array<double, 3> normal{};            ///< unit contact normal (master towards slave)
  std::array<double, 3> point{};             ///< projection on the master surface (m)
  std::array<double, 3> tangential_force{};  ///< friction force on the slave (N)
  std::array<double, 3> slip_velocity{};     ///< slave relative to master, slip part (m/s)
  double coefficient = 0;                    ///< μ used in the step
  bool slipping = false;                     ///< the friction bound was reached
};

/// Sums over the pair after the last evaluate(): forces on the slave side.
struct PenaltyPairTotals {
  std::array<double, 3> force{};   ///< total contact force on the slave side (N)
  std::array<double, 3> normal{};  ///< force-weighted mean contact normal (unit; 0 if no contact)
  double normal_force = 0;         ///< sum of normal forces (N)
  double friction_bound = 0;       ///< sum of μ·N over active nodes (N)
  double area = 0;                 ///< tributary area of the active slave nodes (m²)
  int active = 0;                  ///< slave nodes in contact
  int slipping = 0;                ///< of which slipping
  double max_penetration = 0;      ///< largest −gap (m)
  double stored_energy = 0;        ///< ½ k g² + |f_t|²/2k over active nodes (J)
  double dissipated = 0;           ///< frictional plus damping work since the start (J)
  double frictional_work = 0;      ///< frictional part of dissipated (J)
};

/// One penalty contact pair.
class PenaltyContactPair {
 public:
  /// A pair over \p geometry. Throws std::invalid_argument for inconsistent sizes.
  PenaltyContactPair(PenaltyPairGeometry geometry, PenaltyPairSettings settings);
  ~PenaltyContactPair();
  PenaltyContactPair(PenaltyContactPair&&) noexcept;
  PenaltyContactPair& operator=(PenaltyContactPair&&) noexcept;

  /// Critical step of the contact springs: the smallest 2√(m/k) over the faces, m the reduced
  /// mass of the lightest slave node and the face's mean nodal mass, times √(1 + ζ²) − ζ for
  /// the normal damping fraction ζ (s). With slave caps, k = min(k_s, k_f) and m the reduced
  /// mass of the node and the face, over every slave node on every face. Springs whose mass and
  /// stiffness agree to 0.1 % count once, with the group's smallest mass and largest
  /// stiffness: the step is exact for a lone spring and at most 0.1 % below the exact one.
  double stable_step() const { return stable_step_; }
  /// Penalty stiffness of slave \p slave (index into slaves()) on master face \p face (N/m).
  double stiffness(std::size_t slave, int face) const {
    const double k = geometry_.face_stiffness[face];
    return geometry_.slave_stiffness.empty() ? k : std::min(k, geometry_.slave_stiffness[slave]);
  }
  /// Finds the contact points at positions \p x (3 per surface node) without forces, for the
  /// checks at the start; fills slaves().
  void locate(const double* x);
  /// One step: contact points at \p x, increments \p du of the step (3 per surface node),
  /// step \p dt (s; 0 at the start: no friction increment), largest surface speed \p max_speed
  /// (m/s, for the search). Adds the contact forces to \p force (3 per surface node).
  /// Between searches only the window's slaves are evaluated: the others cannot reach a master
  /// face before the next search (see window_nodes()).
  void evaluate(const double* x, const double* du, double dt, double max_speed, double* force);
  /// Whether evaluate() with these arguments reads only window_nodes(): not when it rebuilds the
  /// search first (the first call, every Search interval steps, or sooner when the surfaces move
  /// further than the capture allows), nor without a step (\p dt 0: statics and the start, where
  /// the motion since the search is unknown).
  bool window_suffices(double dt, double max_speed) const;
  /// The surface nodes whose positions and increments the evaluations until the next search read:
  /// the slaves that were within twice the reach (the most any node can move until the next
  /// search) of the master surface at the last search, and the nodes of every master face they
  /// can reach, ascending. Every other slave stays out of contact until then, so its contact
  /// state (none) is already known.
  const std::vector<int>& window_nodes() const { return window_nodes_; }
  /// Per slave node, in the order of the geometry's slave_nodes.
  const std::vector<SlaveContact>& slaves() const { return slaves_; }
  /// Sums of the last evaluate().
  const PenaltyPairTotals& totals() const { return totals_; }
  /// The geometry.
  const PenaltyPairGeometry& geometry() const { return geometry_; }
  /// The settings.
  const PenaltyPairSettings& settings() const { return settings_; }
  /// Everything that changes between steps, for checkpoints.
  std::vector<double> state() const;
  /// Restores state(); false if the size does not fit.
  bool restore(const std::vector<double>& values);

 private:
  void search(const double* x, double dt, double max_speed);
  // Sets slaves_[slave]'s contact point at \p x; returns the signed distance to the nearest
  // candidate face (+inf without one).
  double contact_point(int slave, const double* x);
  bool search_due(double dt, double max_speed) const;
  // After a search: adds \p slave to the window if its distance \p gap can close before the
  // next search; close_window() then adds the master nodes the window's slaves can reach.
  void add_to_window(int slave, double gap);
  void close_window(const double* x);
  // Contact point, friction and forces of slave \p s for evaluate(); returns contact_point()'s gap.
  double evaluate_slave(std::size_t s, const double* x, const double* du, double dt,
                        std::array<double, 3>& weighted_normal, double* force);

  PenaltyPairGeometry geometry_;
  PenaltyPairSettings settings_;
  std::unique_ptr<BucketSearch> search_;
  std::vector<int> scratch_;
  std::vector<SlaveContact> slaves_;
  std::vector<int> window_slaves_;  // slaves evaluated between searches, ascending
  std::vector<int> window_nodes_;   // see window_nodes()
  double window_reach_ = 0;         // bound on any node's motion until the next search (m)
  bool window_valid_ = false;       // the window covers the motion since the last search
  PenaltyPairTotals totals_;
  double stable_step_ = 1e300;
  long long calls_ = 0;
  int steps_since_search_ = 0;
  double capture_left_ = 0;  // relative motion the last rebuild still covers (m)
};

}  // namespace railfe
