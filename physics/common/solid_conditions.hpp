#pragma once
/// \file
/// Boundary conditions, loads, ties and probes of solid mechanics as decks write them, shared by
/// the modules that solve for displacements. Each kind has its spec (for a module's valid list),
/// a reader and a check against the mesh.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"

namespace railfe {

/// Prescribed displacement components of a node set.
struct DisplacementCondition {
  std::string name;             ///< its name in the deck
  std::string node_set;         ///< where it applies
  std::vector<int> components;  ///< 0 = x, 1 = y, 2 = z; 3..5 rotations θx, θy, θz
  double value = 0;             ///< prescribed value (m or rad), when no expression is given
  std::string expression;       ///< function of x, y, z (m); overrides value when not empty
};

/// A distributed load on a side set: a traction vector, a pressure, or a total force spread
/// uniformly over the set's area.
struct SurfaceLoad {
  std::string name;                                  ///< its name in the deck
  std::string side_set;                              ///< where it acts
  std::optional<std::array<double, 3>> traction;     ///< Pa
  std::optional<double> pressure;                    ///< Pa, against the outward normal
  std::optional<std::array<double, 3>> total_force;  ///< N
};

/// A force shared equally by the nodes of a node set.
struct NodalForce {
  std::string name;                      ///< its name in the deck
  std::string node_set;                  ///< the nodes
  std::array<double, 3> total_force{};   ///< N, summed over the nodes
  std::array<double, 3> total_moment{};  ///< N m, summed over the nodes (6-DOF nodes only)
};

/// The centrifugal load of a node set spinning about an axis, so that a static step can start an
/// explicit run of a rolling wheel in balance: every node carries m ω² r⊥, with m its lumped
/// (row-sum) mass, as the explicit step lumps it, and r⊥ its distance vector from the axis.
struct CentrifugalLoad {
  std::string name;                          ///< its name in the deck
  std::string node_set;                      ///< the spinning nodes
  std::array<double, 3> angular_velocity{};  ///< rad/s
  std::array<double, 3> axis_point{};        ///< a point on the axis (m)
};

/// Two node sets whose coincident nodes move together (multi-point constraints).
struct Tie {
  std::string name;        ///< its name in the deck
  std::string master_set;  ///< nodes that stay unknowns
  std::string slave_set;   ///< nodes that follow their coincident master
  double tolerance = 0;    ///< largest distance between paired nodes (m)
};

/// A node set whose mean displacement is reported in the step's probes CSV.
struct Probe {
  std::string name;      ///< its name in the deck (and the CSV row)
  std::string node_set;  ///< the nodes averaged
};

/// All the conditions of one step.
struct SolidConditions {
  std::vector<DisplacementCondition> displacements;  ///< Dirichlet conditions
  std::vector<SurfaceLoad> surface_loads;            ///< tractions and pressures
  std::vector<NodalForce> nodal_forces;              ///< point-like forces
  std::vector<CentrifugalLoad> centrifugal_loads;    ///< spinning node sets
  std::array<double, 3> gravity{};                   ///< m/s², body force ρ g on every solid
  std::vector<Tie> ties;                             ///< tied node sets
  std::vector<Probe> probes;                         ///< reported displacements
};

/// Adds Displacements, Surface loads, Nodal forces, Centrifugal loads, Gravity, Ties and Probes to
/// \p spec.
void add_solid_condition_parameters(ParameterSpec& spec);

/// Component indices (0 = x, 1 = y, 2 = z; 3, 4, 5 = the rotations θx, θy, θz written "rx",
/// "ry", "rz") of a deck string such as "xz" or "xyzrx". Throws InputError naming \p deck and
/// \p path for other letters or an empty string.
std::vector<int> parse_components(const std::string& letters, const std::string& deck,
                                  const std::string& path);

/// parse_components() for nodes that carry translations only: rotations are refused too.
std::vector<int> parse_translations(const std::string& letters, const std::string& deck,
                                    const std::string& path);

/// Reads the conditions from a validated step list. Throws InputError (naming \p deck and the
/// step \p path) for combinations the spec cannot express: a surface load with none or several
/// of traction, pressure and total force; bad component letters; invalid expressions.
SolidConditions read_solid_conditions(const Teuchos::ParameterList& step, const std::string& deck,
                                      const std::string& path);

/// Throws InputError naming \p deck and the parameter under \p path when \p conditions prescribe
/// a rotation (rx, ry, rz) or apply a Total moment on a model whose nodes carry translations
/// only (\p model says what it is, for the message).
void refuse_rotations(const SolidConditions& conditions, const std::string& deck,
                      const std::string& path, const std::string& model);

/// Checks that every node set and side set named exists in \p mesh (InputError otherwise).
void check_solid_conditions(const SolidConditions& conditions, const Mesh& mesh,
                            const std::string& deck, const std::string& path);

/// Whether \p name is a statics step listed before \p step under the deck's \p steps (what
/// a dynamic step's Start from may name).
bool is_earlier_statics_step(const Teuchos::ParameterList& steps, const std::string& name,
                             const std::string& step);

}  // namespace railfe
