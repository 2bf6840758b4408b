#pragma once
/// \file
/// The wheel–rail contact element of implicit dynamics: a rigid wheelset (a 6-DOF node) whose
/// wheels are the profiles of a WheelRailGeometry, and per potential contact point (tread and
/// flange of each wheel) an internal node that stands for the rail's material point under the
/// contact. The element joins the wheelset to each internal node by Hertz's normal force and
/// the creep forces of a rolling-contact theory; the internal nodes are tied to the rail by
/// constraint equations whose multipliers are then the contact forces (the ConstraintSet of the
/// module that uses the element). The contact point is searched online on the profiles at every
/// evaluation, started from the last one found.
///
/// Conventions (docs/theory.md, "The wheel–rail contact element"): track axes x forward,
/// y to the right, z down, as contact/geometry; wheelset unknowns u = (x, y, z, θx, θy, θz), the
/// displacement of its centre and small rotations about the track axes (θx = roll, lowering the
/// right wheel; θz = the WheelRailGeometry's yaw; θy = the spin's departure from the nominal
/// spin Ω = −V / r_nominal). Each internal node carries (x, y, z). The element's forces are
/// returned as internal forces f_int (the negative of the forces acting on the unknowns), so
/// M a + f_int = f_ext. Creep forces are on the wheel, along the rolling direction x and along
/// t = n × x in the contact plane, n the rail's outward normal; spin is ω·n / V.

#include <array>
#include <memory>
#include <string>

#include "contact/geometry/contact_search.hpp"
#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/laws/hertz.hpp"
#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// The rolling-contact theory that gives the creep forces.
enum class CreepTheory {
  table,                ///< the exact solver's creep-force table (CreepTable::shipped())
  linear,               ///< Kalker's linear theory (unbounded)
  shen_hedrick_elkins,  ///< the linear theory saturated by Shen, Hedrick & Elkins
  polach,               ///< Polach's model (k_A = k_S = 1, friction independent of slip)
  fastsim               ///< Kalker's FASTSIM
};

/// Name of \p theory as decks spell it ("table", "linear", ...).
std::string creep_theory_name(CreepTheory theory);
/// The theory named \p name; throws std::invalid_argument for an unknown name.
CreepTheory creep_theory_from_name(const std::string& name);

/// Materials, friction and the theory of the element.
struct WheelRailContactSettings {
  ElasticBody wheel;                         ///< E, ν of the wheel
  ElasticBody rail;                          ///< E, ν of the rail
  double friction = 0.3;                     ///< μ
  CreepTheory theory = CreepTheory::linear;  ///< creep forces
  bool yaw_exact = false;  ///< search on the yawed wheel (else yaw is neglected, as the seed)
  int fastsim_cells = 10;  ///< FASTSIM cells per strip and strips
  /// Where the profiles are nearly conformal (a flange root), Hertz's relative curvatures are
  /// kept to within this ratio of each other by raising the smaller one, so the ellipse stays
  /// within a/b ≈ 1/5..5; 0 refuses such a contact instead (RunError).
  double curvature_ratio_limit = 10;
  bool trust_region = true;  ///< the contact search's trust region (false: plain Newton)
  /// The contact points from the lookup table at the wheelset's lateral shift, not searched
  /// (the gap, normal and curvatures taken there): the offline-table model of programs such as
  /// DIASTARS. Needs use_table(); beyond the table's shifts its last row's points.
  bool offline_table = false;
  /// The creep forces' share of the tangent damping: false, forward differences of the theory
  /// (consistent); true, Kalker's linear damping matrix Jᵀ D J at the current ellipse, as the
  /// seed model does (exact for the linear theory, an approximation for saturating ones).
  bool kalker_damping = false;
};

/// The kinematic state the element sees: the wheelset's and one internal node's.
struct ContactKinematics {
  std::array<double, 6> wheelset_u{};  ///< (x, y, z, θx, θy, θz) of the wheelset centre
  std::array<double, 6> wheelset_v{};  ///< their rates
  std::array<double, 3> node_u{};      ///< the internal node (the rail's material point)
  std::array<double, 3> node_v{};      ///< its velocity
  double speed = 0;  ///< forward speed V (m/s); 0: a static evaluation, no creep forces
  double spin = 0;   ///< nominal spin Ω about the axle (rad/s; −V / r for rolling forward)
};

/// What one potential contact point carries.
struct ContactState {
  ContactPoint point;                ///< the search's result (gap, angle, curvatures, radius)
  bool active = false;               ///< penetrating: the point carries force
  bool conformal = false;            ///< a relative curvature was raised (curvature_ratio_limit)
  HertzContact hertz;                ///< the ellipse and the normal force (zero when not active)
  Creepages creepage;                ///< ξ, η, φ (zero when not active or static)
  CreepForces creep;                 ///< Fx, Fy, Mz on the wheel (contact frame)
  std::array<double, 3> force{};     ///< total force of the rail on the wheel, track axes (N)
  std::array<double, 3> moment{};    ///< its moment about the wheelset centre (N m)
  std::array<double, 3> position{};  ///< wheel contact point relative to the centre (m)
};

/// One potential contact point (a side and a part) of a wheelset.
class WheelRailContact {
 public:
  /// The point on the \p flange part (else the tread) of \p side's wheel of \p geometry
  /// (shared, must outlive nothing: it is kept).
  WheelRailContact(std::shared_ptr<const WheelRailGeometry> geometry, TrackSide side, bool flange,
                   const WheelRailContactSettings& settings);

  /// Searches the contact for \p state (from the last point found, or from a sampled start
  /// the first time and after a failed search) and computes the forces. Throws RunError naming
  /// the point when the search fails or a theory's input leaves its range.
  ContactState evaluate(const ContactKinematics& state);
  /// Internal forces of \p state, evaluated at \p at: \p wheelset (6) and \p node (3) receive
  /// f_int (= −the generalized force on them).
  static void internal_forces(const ContactState& state, const ContactKinematics& at,
                              double* wheelset, double* node);
  /// ∂f_int/∂u and ∂f_int/∂v (9 × 9, row-major, unknowns ordered wheelset then node) at
  /// \p state, by forward differences from the evaluation \p at. Hertz's ellipse is scaled from
  /// the one at \p at (its change of shape is left out): the tangent only steers Newton, the
  /// residual uses exact forces.
  void tangent(const ContactKinematics& state, const ContactState& at, double* stiffness,
               double* damping) const;
  /// Sets the start of the next search (e.g. from the lookup table, or the converged step's).
  void set_start(double s_wheel, double s_rail);
  /// Uses \p table (shared; null: none) to predict jumps: where the table's start for the
  /// relative lateral shift lies more than 1 mm of wheel profile from the last point found,
  /// the part is searched from both and the deeper contact is taken. The part is also searched
  /// only up to 1 mm beyond the table's contacts on its flange-root side (docs/theory.md).
  void use_table(std::shared_ptr<const ContactTable> table);
  /// Evaluations whose contact sat on the edge of the searched stretch, penetrating.
  std::size_t edge_contacts() const { return edge_contacts_; }
  /// Evaluations where the table's start gave the contact (a predicted jump).
  std::size_t table_jumps() const { return table_jumps_; }
  /// Evaluations of a flange the lookup table showed farther than kFarFlangeGap from its rail
  /// (not searched).
  std::size_t far_flanges() const { return far_flanges_; }
  /// Evaluations that took their point from the offline table (WheelRailContactSettings::
  /// offline_table).
  std::size_t offline_points() const { return offline_points_; }
  /// A flange whose rigid-contact gap exceeds this is not searched (m).
  static constexpr double kFarFlangeGap = 2e-3;
  /// "right tread", "left flange", ...
  std::string name() const;
  /// The side.
  TrackSide side() const { return side_; }
  /// Whether this is the flange point.
  bool flange() const { return flange_; }

 private:
  // Whether the offline-table model gives the points (throws std::logic_error without a table).
  bool offline() const;
  // The offline model's point at \p pose: the table's wheel point, the gap taken there.
  ContactPoint offline_point(const WheelsetPose& pose) const;
  /// Pose of the wheelset relative to the node's rail displacement.
  WheelsetPose relative_pose(const ContactKinematics& state) const;
  /// The forces of \p state with the contact point \p point already searched; Hertz's ellipse
  /// computed afresh, or (\p shape given, for the tangent) scaled from \p shape to the approach.
  ContactState forces_at(const ContactKinematics& state, const ContactPoint& point,
                         const HertzContact* shape) const;
  /// J: the rates of the slip numerators (Δv·x, Δv·t, ω·n) per unknown rate (wheelset 6,
  /// node 3) at \p at; the creepages are J v / V plus terms without velocities.
  static void creepage_rates(const ContactKinematics& state, const ContactState& at,
                             double J[3][9]);
  /// Jᵀ D J of Kalker's linear theory at \p at (9 × 9, row-major) into \p damping.
  void kalker_damping_matrix(const ContactKinematics& state, const ContactState& at,
                             double* damping) const;
  /// The creep forces' exact share of ∂f_int/∂v at \p at: −Jᵀ (∂F/∂c) J / V, ∂F/∂c
  /// (F = Fx, Fy, Mz; c the creepages) by forward differences of the creep theory alone.
  void creep_damping_matrix(const ContactKinematics& state, const ContactState& at,
                            double* damping) const;
  /// Creep forces of \p theory for \p hertz and \p creep.
  CreepForces creep_forces(const HertzContact& hertz, const Creepages& creep, double speed) const;

  std::shared_ptr<const WheelRailGeometry> geometry_;
  TrackSide side_;
  bool flange_;
  WheelRailContactSettings settings_;
  double modulus_ = 0, shear_modulus_ = 0, poisson_ = 0;
  std::shared_ptr<const ContactTable> table_;
  std::size_t table_jumps_ = 0, edge_contacts_ = 0, far_flanges_ = 0, offline_points_ = 0;
  SearchSettings search_;  // the stretch searched
  bool started_ = false;
  double s_wheel_ = 0, s_rail_ = 0;
};

}  // namespace railfe
