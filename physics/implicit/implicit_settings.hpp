#pragma once
/// \file
/// What an implicit step reads from its deck list: the HHT-α (or Newmark) scheme, Rayleigh
/// damping, the Newton tolerances and cut-back, the time line, the initial state and what is
/// recorded. See implicit_module.hpp.

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/parameter_spec.hpp"
#include "framework/time/hht_integrator.hpp"

namespace railfe {

/// One recorded quantity: the mean of a kinematic component over a node set.
struct ImplicitHistory {
  std::string name;             ///< its deck name (the CSV column stem)
  std::string node_set;         ///< the nodes averaged
  int quantity = 0;             ///< 0 displacement, 1 velocity, 2 acceleration
  int component = 0;            ///< 0..2 translations x, y, z; 3..5 rotations about x, y, z
  double period_reference = 0;  ///< value about which upward crossings time a period
};

/// An initial velocity field v = V on a node set (every node when empty).
struct ImplicitInitialVelocity {
  std::string node_set;                 ///< the nodes ('' = every node)
  std::array<double, 3> translation{};  ///< V (m/s)
};

/// The validated settings of one implicit step.
struct ImplicitSettings {
  double end_time = 0;              ///< simulated duration (s)
  double time_step = 0;             ///< Δt (s)
  NewmarkScheme scheme;             ///< β, γ, α
  RayleighDamping rayleigh;         ///< a_R, b_R
  NewtonSettings newton;            ///< tolerances and iteration limit
  CutBackSettings cut_back;         ///< halvings allowed
  bool lumped_mass = false;         ///< row-sum mass instead of the consistent one
  std::string start_from;           ///< a statics step whose displacements start this one
  std::string load_function = "1";  ///< scale of every load as a function of t
  std::vector<ImplicitInitialVelocity> initial_velocities;  ///< applied in order
  std::vector<ImplicitHistory> histories;                   ///< recorded every History interval
  int history_interval = 1;    ///< steps between rows of <step>_histories.csv
  int energy_interval = 10;    ///< steps between rows of <step>_energy.csv
  double exodus_interval = 0;  ///< simulated time between Exodus snapshots (0: ends)
};

/// The valid parameters of an implicit step, less the solid conditions (added by the module).
void add_implicit_parameters(ParameterSpec& spec);

/// Reads the settings of a validated step list; throws InputError naming \p deck and the
/// parameter under \p path for what the spec cannot express (a scheme outside its range, a
/// History interval that does not divide the steps, ...).
ImplicitSettings read_implicit_settings(const Teuchos::ParameterList& step, const std::string& deck,
                                        const std::string& path);

}  // namespace railfe
