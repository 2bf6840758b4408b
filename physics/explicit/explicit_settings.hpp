#pragma once
/// \file
/// Everything an explicit step reads from its deck sublist, as plain structs: time stepping,
/// the solid kernel, loads and prescribed motion as functions of time, initial velocities,
/// discrete parts (nodal masses, rigid bodies and point masses, spring–dampers), histories and
/// output. read_explicit_settings() turns the validated list into these and catches what the
/// spec cannot (bad expressions, inconsistent combinations).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"
#include "physics/common/contact_settings.hpp"
#include "physics/explicit/solid_kernel.hpp"

namespace railfe {

/// A load that scales with a function of time f(t) (a deck expression in t).
struct TimedLoad {
  std::string name;                               ///< its name in the deck
  std::string node_set;                           ///< nodal force: the nodes sharing it
  std::string side_set;                           ///< surface load: the faces
  std::optional<std::array<double, 3>> traction;  ///< surface load: traction (Pa)
  std::optional<double> pressure;                 ///< surface load: pressure (Pa)
  std::array<double, 3> total_force{};            ///< nodal force, or total over a side set (N)
  bool surface_total = false;                     ///< side set with a total force
  std::string function = "1";                     ///< f(t)
};

/// Prescribed displacement or velocity components of a node set.
struct PrescribedMotion {
  std::string name;             ///< its name in the deck
  std::string node_set;         ///< the nodes
  std::vector<int> components;  ///< 0 = x, 1 = y, 2 = z
  bool velocity = false;        ///< the function gives a velocity (m/s), else a displacement (m)
  std::string function = "0";   ///< value as a function of x, y, z, t
};

/// An initial velocity field: translation plus rotation about an axis through a point.
struct InitialVelocity {
  std::string name;                          ///< its name in the deck
  std::string node_set;                      ///< the nodes ("" = every node)
  std::array<double, 3> translation{};       ///< m/s
  std::array<double, 3> angular_velocity{};  ///< rad/s
  std::array<double, 3> axis_point{};        ///< a point on the rotation axis (m)
};

/// Mass added to the nodes of a node set (shared equally).
struct NodalMass {
  std::string name;      ///< its name in the deck
  std::string node_set;  ///< the nodes
  double mass = 0;       ///< total (kg)
};

/// A rigid body: a node set moving rigidly with a reference point that carries extra mass and
/// inertia; without a node set and inertia it is a point mass.
struct RigidBodySpec {
  std::string name;                                ///< its name in the deck
  std::string node_set;                            ///< nodes it carries ("" = none)
  std::optional<std::array<double, 3>> reference;  ///< reference point (m); default centroid
  double mass = 0;                                 ///< extra mass at the reference point (kg)
  std::array<double, 3> inertia{};           ///< extra principal inertia, global axes (kg m²)
  std::array<double, 3> velocity{};          ///< initial velocity (m/s)
  std::array<double, 3> angular_velocity{};  ///< initial angular velocity (rad/s)
  std::array<bool, 6> fixed{};               ///< locked translations x y z, rotations x y z
  bool weighs = true;                        ///< gravity acts on its Mass
  /// Prescribed displacement of the reference point along x, y, z: a function of t (m) from
  /// its position at the start, or "" (free).
  std::array<std::string, 3> motion{};
};

/// A linear spring–damper, axis-aligned, between two ends: a rigid body (its reference point),
/// a node set (one spring per node, stiffness shared) or the ground.
struct SpringSpec {
  std::string name;                   ///< its name in the deck
  std::string end_a;                  ///< body or node set name
  std::string end_b;                  ///< body or node set name, or "ground"
  std::array<double, 3> stiffness{};  ///< N/m per global axis (total over a node set)
  std::array<double, 3> damping{};    ///< N s/m per global axis (total over a node set)
};

/// A moment on a rigid body, scaled by a function of time.
struct BodyMoment {
  std::string name;                ///< its name in the deck
  std::string body;                ///< the rigid body
  std::array<double, 3> moment{};  ///< N m
  std::string function = "1";      ///< f(t)
};

/// A history: the mean of one kinematic quantity over a node set, with event measurements.
struct HistorySpec {
  std::string name;             ///< its name in the deck (a CSV column prefix)
  std::string node_set;         ///< the nodes averaged ("" for a body)
  std::string body;             ///< a rigid body's reference point instead ("" for a node set)
  std::string quantity;         ///< displacement, velocity or acceleration
  int component = 0;            ///< 0 = x, 1 = y, 2 = z
  double arrival_level = 0;     ///< |value| that marks the arrival of a wave (0 = none)
  double period_reference = 0;  ///< the value about which periods are counted
};

/// A wave speed measured between the arrivals (or peaks) at two histories.
struct WaveSpeedSpec {
  std::string name;   ///< its name in the deck
  std::string from;   ///< history nearer the source
  std::string to;     ///< history further away
  bool peak = false;  ///< use the peak times instead of the arrival times
};

/// An element whose centre stress is recorded.
struct ElementHistorySpec {
  std::string name;         ///< its name in the deck
  GlobalIndex element = 0;  ///< global element index (0-based; decks give 1-based ids)
};

/// The settings of one explicit step.
struct ExplicitSettings {
  double end_time = 0;               ///< s
  double maximum_steps = 1e8;        ///< step budget (refused before, stopped during)
  double time_step = 0;              ///< fixed step (s); 0 = automatic
  double safety_factor = 0.9;        ///< automatic step = factor × stable step
  bool allow_unstable_step = false;  ///< run a fixed step above the stable limit
  double energy_error_limit = 0.1;   ///< blow-up: |energy error| above it, and...
  double energy_growth_limit = 100;  ///< ...stored + dissipated above this x the put in
  double rayleigh_mass = 0;          ///< α of C = α M (1/s)
  double mass_scaling_step = 0;      ///< elements below this step are made heavier (s); 0 off
  SolidKernelSettings kernel;        ///< hex8 formulation
  std::string start_from;            ///< a previous step whose displacement starts this one
  /// The velocity of the frame in which the preload is steady (convected start); none: off.
  std::optional<std::array<double, 3>> preload_frame;
  std::vector<TimedLoad> loads;                       ///< nodal forces and surface loads
  std::array<double, 3> gravity{};                    ///< m/s²
  std::string gravity_function = "1";                 ///< f(t) scaling gravity
  std::vector<PrescribedMotion> motions;              ///< prescribed kinematics
  std::vector<InitialVelocity> initial_velocities;    ///< initial velocity fields
  std::vector<NodalMass> nodal_masses;                ///< added nodal masses
  std::vector<RigidBodySpec> bodies;                  ///< rigid bodies and point masses
  std::vector<SpringSpec> springs;                    ///< spring–dampers
  std::vector<BodyMoment> moments;                    ///< moments on bodies
  std::vector<ContactPairSpec> contact_pairs;         ///< penalty contact pairs
  std::vector<HistorySpec> histories;                 ///< node-set histories
  std::vector<ElementHistorySpec> element_histories;  ///< element stress histories
  std::vector<WaveSpeedSpec> wave_speeds;             ///< measured wave speeds
  int energy_interval = 100;                          ///< steps between energy.csv rows
  int history_interval = 10;                          ///< steps between history rows
  double exodus_interval = 0;   ///< simulated time between snapshots (s); 0 = first and last
  int checkpoint_interval = 0;  ///< steps between checkpoints (0 = none)
  bool restart = false;         ///< resume from the checkpoint if one exists
  int stop_after_steps = 0;     ///< stop (as if interrupted) after this many steps (0 = no)
};

/// The valid parameters of an explicit step.
ParameterSpec explicit_parameters();

/// Reads a validated explicit step list. Throws InputError naming \p deck and \p path for what
/// the spec cannot express.
ExplicitSettings read_explicit_settings(const Teuchos::ParameterList& step, const std::string& deck,
                                        const std::string& path);

/// Checks every set, block, body and element named against \p mesh (InputError otherwise).
void check_explicit_settings(const ExplicitSettings& settings, const Mesh& mesh,
                             const std::string& deck, const std::string& path);

}  // namespace railfe
