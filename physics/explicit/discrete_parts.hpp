#pragma once
/// \file
/// Rigid bodies (and point masses) and spring–dampers of an explicit run. A body's state is
/// replicated on every rank; the nodes it carries are moved with it, and their forces are summed
/// over ranks each step (one reduction for all bodies). Springs to node sets act on the owned
/// nodes of each rank; springs between bodies and to the ground are evaluated on every rank.
/// A spring between two node sets ties each node of End A to the nearest node of End B
/// (framework/mesh/nearest_nodes.hpp); the motion of those nodes is gathered over ranks each
/// step (one reduction for all such springs), since the two ends need not share a rank.
/// Time stepping is the same central difference as the nodes: translation exactly, rotation as
/// kick–drift–kick on the spatial angular momentum with an energy- and momentum-conserving free
/// rotation between the kicks (rigid_rotation.hpp).

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "framework/base/parallel.hpp"
#include "framework/base/types.hpp"
#include "framework/deck/expression.hpp"
#include "physics/elements/spring_damper.hpp"
#include "physics/explicit/explicit_settings.hpp"
#include "physics/explicit/rigid_rotation.hpp"

namespace railfe {

class MeshPartition;

/// The nodal arrays of a rank (3 entries per local node, owned nodes first).
struct NodalArrays {
  LocalIndex n_owned = 0;        ///< owned nodes
  const double* x = nullptr;     ///< reference coordinates
  const double* mass = nullptr;  ///< lumped mass per owned node (1 per node)
  double* u = nullptr;           ///< displacement
  double* v = nullptr;           ///< velocity (the midpoint prediction between the two phases)
  double* a = nullptr;           ///< acceleration
  double* du = nullptr;          ///< displacement increment of the step (owned)
  double* residual = nullptr;    ///< f_ext − f_int − f_spring on owned nodes
};

/// One rigid body.
struct RigidBody {
  std::string name;                      ///< its deck name
  std::vector<LocalIndex> nodes;         ///< owned nodes it carries
  std::vector<Eigen::Vector3d> offsets;  ///< their reference positions − reference point
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();     ///< reference point (m)
  double mass = 0;                                         ///< total mass incl. nodes (kg)
  double extra_mass = 0;                                   ///< mass at the reference point (kg)
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();       ///< reference inertia about the point
  bool rotates = true;                                     ///< false for a point mass
  bool weighs = true;                                      ///< gravity acts on its extra mass
  std::array<bool, 6> fixed{};                             ///< locked translations and rotations
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();  ///< U (m)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      ///< V (m/s)
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< A (m/s²)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();      ///< ω (rad/s)
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  ///< ω̇
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();      ///< L = R I Rᵀ ω (N m s)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();                 ///< force of the step (N)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();                ///< moment about the point (N m)
  double work = 0;  ///< work of the body-level loads (J), prescribed motion's included
  std::array<int, 3> motion{-1, -1, -1};  ///< index of the prescribed-motion function, per axis
  Eigen::Vector3d motion_origin = Eigen::Vector3d::Zero();    ///< U when the motion starts (m)
  Eigen::Vector3d motion_reaction = Eigen::Vector3d::Zero();  ///< force driving it, last step (N)
};

/// The discrete parts of a run.
class DiscreteParts {
 public:
  /// Builds the parts of \p settings on \p partition; \p nodal_mass (owned nodes) gives each
  /// carried node's mass. Throws InputError (naming \p deck and \p path) for a node carried by
  /// two bodies. Collective.
  DiscreteParts(const ExplicitSettings& settings, const MeshPartition& partition,
                const std::vector<double>& nodal_mass, const std::string& deck,
                const std::string& path);

  /// Whether owned node \p node is carried by a body (its motion is the body's).
  bool carried(LocalIndex node) const { return body_of_node_[node] >= 0; }
  /// The bodies.
  const std::vector<RigidBody>& bodies() const { return bodies_; }
  /// Smallest critical step the springs allow (s), +inf without springs.
  double stable_step() const { return stable_step_; }
  /// Places the bodies for a run that starts from a statics step's displacement (already in
  /// \p nodes.u): a body carrying nodes at their mean displacement (its rotation is not
  /// fitted), a point body at rest where its springs and \p gravity balance (springs to node
  /// sets pull towards the nodes' mean), so that the run starts in equilibrium. Locked
  /// translations stay at zero. Collective. Without it (a fresh start) every body starts at zero.
  void start_from_preload(const NodalArrays& nodes, const std::array<double, 3>& gravity,
                          const Communicator& comm);
  /// Gives carried nodes the initial velocity of their bodies. The run then calls
  /// add_spring_forces() and correct() with dt = 0 to find the initial accelerations.
  void initialise_nodes(NodalArrays& nodes) const;
  /// First half of a step: advances the bodies to t + dt and moves their nodes (u, du, and the
  /// midpoint velocity in v).
  void predict(double dt, NodalArrays& nodes);
  /// Spring forces at the predicted state: adds them to the residual of owned nodes and to the
  /// bodies' forces; returns the damper power (W) and adds the spring energy to \p energy.
  double add_spring_forces(const NodalArrays& nodes, double& energy);
  /// Second half: sums the carried nodes' residuals and the body loads at \p time over ranks,
  /// then solves each body's accelerations and sets its nodes' v and a (collective).
  void correct(double time, double dt, const std::array<double, 3>& gravity, NodalArrays& nodes,
               const Communicator& comm);
  /// Energy stored in springs between bodies or to the ground in the last correct() (J; rank 0
  /// only, so that sums over ranks count it once).
  double body_spring_energy() const { return spring_energy_; }
  /// Power of their dampers in the last correct() (W; rank 0 only).
  double body_spring_power() const { return spring_power_; }
  /// Kinetic energy of the bodies (J).
  double kinetic_energy() const;
  /// Work done so far by the loads on the bodies themselves (gravity on extra mass, moments).
  double external_work() const;
  /// Everything that changes in time, for checkpoints.
  std::vector<double> state() const;
  /// Restores what state() saved; also a checkpoint of railfe before the momentum scheme (without
  /// L and M, which it rebuilds from ω, ω̇ and R). Throws RunError for a state of another model.
  void restore(const std::vector<double>& values);

 private:
  struct SpringEnd {
    int body = -1;                  // index into bodies_, or −1
    std::vector<LocalIndex> nodes;  // owned nodes of a node-set end
    double share = 0;               // 1 / global node count of a node-set end
  };
  struct Spring {
    std::string name;
    SpringEnd a, b;        // b with body −1 and no nodes = ground
    SpringDamper element;  // along the global axes; per node for a node-set end (shared)
    // Between two node sets: each A node and its partner (global), and their slots in
    // gathered_nodes_.
    std::vector<std::pair<GlobalIndex, GlobalIndex>> pairs;
    std::vector<std::array<int, 2>> pair_slots;
  };
  // Numbers the nodes of springs between node sets and sets their pair_slots.
  void number_gathered_nodes(const MeshPartition& partition);
  // Gathers u and v of gathered_nodes_ over ranks into gathered_ (6 per node).
  void gather_paired_motion(const NodalArrays& nodes);
  double add_paired_spring_forces(const Spring& spring, const NodalArrays& nodes, double& energy);
  void add_body_force(const Spring& spring, const Eigen::Vector3d& force_on_a, bool to_b);

  std::vector<RigidBody> bodies_;
  std::vector<RigidRotation> rotations_;  // per body
  std::vector<Spring> springs_;
  Communicator comm_;
  std::vector<GlobalIndex> gathered_nodes_;  // nodes of springs between node sets, sorted
  std::vector<LocalIndex> gathered_owned_;   // each one's owned local index here, or −1
  std::vector<double> gathered_;             // their u and v, summed over ranks
  std::vector<int> body_of_node_;
  std::vector<BodyMoment> moments_;
  std::vector<Expression> moment_functions_;
  std::vector<Expression> motion_functions_;  // prescribed translations of bodies
  std::vector<double> motion_start_;          // each one's value at t = 0
  double time_ = 0;                           // time of the last correct()
  // Displacement, velocity and acceleration of prescribed function \p f at time \p t.
  std::array<double, 3> motion_at(int f, double t, double dt) const;
  double stable_step_ = 1e300;
  double spring_energy_ = 0, spring_power_ = 0;
  std::vector<double> body_sums_;  // force and moment of every body, summed over ranks
  // Per body: the loads on the body itself at the last step, and this step's ΔU (for their work).
  std::vector<Eigen::Vector3d> previous_own_force_, previous_own_moment_, body_step_;
};

}  // namespace railfe
