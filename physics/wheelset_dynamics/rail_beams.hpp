#pragma once
/// \file
/// Flexible rails for the wheelset: each rail a line of beam elements along the track (x = s
/// from 0 to the rails' length) on discrete rail seats, each seat a spring–damper to the ground
/// along x, y, z and about x (roll). RailBeams holds the sparse M, C, K of both rails;
/// BeamRails ties every contact point's internal node to the rail beneath it: the node's
/// (x, y, z) equals the beam's translation at s = start + V t, plus the rail's roll θ_x times
/// the contact point's lever about the beam axis, plus the irregularities. The rail profile is
/// carried rigidly (its roll moves the contact point, it does not turn the profile). The same
/// class holds rails on springs: a rigid body per rail that moves with the wheelset, its y, z and
/// roll on springs to the ground, and a structure under the track: a girder continuous over its
/// spans on bearings at the piers, both rails fixed to it (the track beyond the structure
/// rigid). Axes are the track's: x along, y to the right, z down (docs/theory.md, "Rails on
/// beams", "A vehicle on a viaduct").

#include <Eigen/Sparse>

#include <array>
#include <functional>
#include <vector>

#include "framework/time/constraint_set.hpp"
#include "physics/implicit/moving_contact.hpp"
#include "physics/wheelset_dynamics/wheelset_system.hpp"

namespace railfe {

/// The rails' beams and seats.
struct RailBeamLayout {
  BeamMaterial material;      ///< the rail steel
  BeamSection section;        ///< local y = track y (lateral), local z = track z (vertical)
  double length = 0;          ///< each rail's length from s = 0 (m), a whole number of spans
  double seat_spacing = 0.6;  ///< distance between rail seats (m); seats at s = 0, a, 2a, …
  int elements_per_span = 4;  ///< beam elements between two seats
  std::array<double, 4> seat_stiffness{};  ///< per seat along x, y, z (N/m) and roll (N m/rad)
  std::array<double, 4> seat_damping{};    ///< per seat along x, y, z (N s/m), roll (N m s/rad)
  double axis_depth = 0;                   ///< the beam axis below the rail's top (m)
  BeamMass mass = BeamMass::consistent;    ///< how the beams' mass is formed
};

/// Rails on springs: each rail a rigid body under the wheelset that moves with it, displaced
/// along y and z and rolled about its axis, on springs and dampers to the ground.
struct RailSpringLayout {
  double mass = 0;                    ///< each rail's participating mass (kg)
  double roll_inertia = 0;            ///< about its axis (kg m²)
  std::array<double, 3> stiffness{};  ///< along y, z (N/m) and roll (N m/rad), per rail
  std::array<double, 3> damping{};    ///< along y, z (N s/m) and roll (N m s/rad), per rail
  double axis_depth = 0;              ///< the roll axis below the rail's top (m)
};

/// The top of \p side's rail profile in the track's cross-section: {y, z} of its smallest z
/// (where the rails' beam and girder axes are measured from).
std::array<double, 2> rail_top(const WheelRailGeometry& geometry, TrackSide side);

/// A structure under the track: a girder continuous over its spans (the rails run over the piers
/// without a step or kink), on bearings at each pier between two spans, a spring–damper to the
/// ground along x, y, z and about x, its ends held by the abutments along x, y, z and in roll;
/// the rails fixed to it, the track before and after the structure rigid.
struct GirderLayout {
  BeamMaterial material;      ///< the girder's material
  BeamSection section;        ///< local y = track y (lateral), local z = track z (vertical)
  double start = 0;           ///< track position s of the first span's start (m)
  double span = 20;           ///< span length (m)
  int spans = 2;              ///< number of spans
  int elements_per_span = 8;  ///< beam elements in a span
  std::array<double, 4> bearing_stiffness{};  ///< per pier along x, y, z (N/m), roll (N m/rad)
  std::array<double, 4> bearing_damping{};    ///< per pier (N s/m; N m s/rad)
  double axis_depth = 0;                      ///< the girder's axis below the rails' top (m)
  std::array<double, 2> rayleigh{};  ///< C += a_m M + a_k K of the girders: {a_m (1/s), a_k (s)}
};

/// Both rails' matrices and paths (right rail first, its unknowns first).
class RailBeams {
 public:
  /// Rails on springs (see RailSpringLayout): 3 unknowns per rail (y, z, roll). Throws
  /// std::invalid_argument for a stiffness that is not positive or a negative mass.
  RailBeams(const RailSpringLayout& layout, std::array<double, 2> axis_y,
            std::array<double, 2> axis_z);
  /// The rails of \p layout whose axes lie at lateral positions \p axis_y (right, left) and
  /// depths \p axis_z (z of each axis). Throws std::invalid_argument for a length that is not
  /// a whole number of spans, or a seat stiffness that is not positive (a rail free to move).
  RailBeams(const RailBeamLayout& layout, std::array<double, 2> axis_y,
            std::array<double, 2> axis_z);
  /// The girders of \p layout (both sides travel the same path), their axis on the track's
  /// centre line at depth \p axis_z. Throws std::invalid_argument for no span, a span or an
  /// element count that is not positive, or a bearing stiffness that is not positive.
  RailBeams(const GirderLayout& layout, double axis_z);
  /// Number of unknowns (6 per node, both rails).
  std::size_t n_unknowns() const { return n_unknowns_; }
  /// M (consistent or lumped beam mass).
  const Eigen::SparseMatrix<double>& mass() const { return mass_; }
  /// C (the seats' dampers).
  const Eigen::SparseMatrix<double>& damping() const { return damping_; }
  /// K (beams and seats).
  const Eigen::SparseMatrix<double>& stiffness() const { return stiffness_; }
  /// Track position s of the paths' start (0 for rails; the first span's start for girders).
  double origin() const { return origin_; }
  /// Whether the track is rigid where s lies off the paths (girders: before and after the
  /// structure); otherwise s must stay on them.
  bool rigid_beyond() const { return rigid_beyond_; }
  /// Whether the rails are rigid bodies on springs (no paths; point_unknown()).
  bool on_springs() const { return paths_.empty(); }
  /// The beam path of \p side (s = x); beams only.
  const BeamPath& path(TrackSide side) const { return paths_[index(side)]; }
  /// Rails on springs: the unknown of \p side's y (0), z (1) or roll (2).
  long point_unknown(TrackSide side, int component) const { return 3L * index(side) + component; }
  /// The axis of \p side in the cross-section: {y, z}.
  std::array<double, 2> axis(TrackSide side) const {
    return {axis_y_[index(side)], axis_z_[index(side)]};
  }

 private:
  static int index(TrackSide side) { return side == TrackSide::right ? 0 : 1; }
  // M, C and K of n_unknowns_ rows from their entries.
  void set_matrices(const std::vector<Eigen::Triplet<double>>& k,
                    const std::vector<Eigen::Triplet<double>>& m,
                    const std::vector<Eigen::Triplet<double>>& c);
  std::size_t n_unknowns_ = 0;
  Eigen::SparseMatrix<double> mass_, damping_, stiffness_;
  std::vector<BeamPath> paths_;  // right, left
  std::array<double, 2> axis_y_, axis_z_;
  double origin_ = 0;
  bool rigid_beyond_ = false;
};

/// The internal nodes of the wheelset's four contact points tied to the rail beams (see the
/// file comment), for each of a vehicle's wheelsets; the vehicle's unknowns follow the rails' in
/// the coupled system.
class BeamRails : public ConstraintSet {
 public:
  /// Ties for \p rails (not owned) with the vehicle's unknowns from \p vehicle_offset, the
  /// irregularities \p lateral and \p vertical (functions of s, either may be empty: zero; right
  /// and down), the reference point at s = \p start + \p speed t, the rows of \p wheelsets in
  /// turn (their nodes counted from \p vehicle_offset; default: one wheelset at the reference
  /// point, nodes from 6 on).
  BeamRails(const RailBeams& rails, std::size_t vehicle_offset,
            std::function<double(double)> lateral, std::function<double(double)> vertical,
            double start, double speed, std::vector<RailedWheelset> wheelsets = {RailedWheelset{}});
  /// Takes each contact point of wheelset \p wheelset as the lever of the rail's roll for the
  /// rows written from now on (the rows stay fixed within a step: the levers are the last
  /// accepted ones).
  void set_levers(const std::array<ContactState, n_wheelset_contacts>& states, int wheelset = 0);
  /// Three rows per internal node; throws RunError when s leaves rails that have no rigid
  /// track beyond them.
  void rows_at(double time, ConstraintRows& rows) override;
  /// By central differences of the rows over ±1 mm of s (rates_by_differences()).
  void rates(double time, const double* u, const double* v, std::size_t n_rows, double* velocity,
             double* acceleration) override;
  /// Lateral and vertical irregularity at \p time, \p position ahead of the reference point.
  std::array<double, 2> offsets(double time, double position = 0) const;
  /// The rails' displacements (x, y, z) under the first wheelset's four contact points at
  /// \p time for the rails' unknowns \p u, point after point: each internal node's position
  /// less the irregularities.
  std::array<double, 3 * n_wheelset_contacts> rail_displacements(double time, const double* u);

 private:
  const RailBeams& rails_;
  std::size_t offset_;
  std::function<double(double)> lateral_, vertical_;
  double start_, speed_;
  std::vector<RailedWheelset> wheelsets_;
  // {y, z} per point, per wheelset
  std::vector<std::array<std::array<double, 2>, n_wheelset_contacts>> levers_;
};

}  // namespace railfe
