#pragma once
/// \file
/// A vehicle crossing a simply supported bridge by the direct method: the bridge of
/// moving_bridge_model.hpp, a linear vehicle of sprung masses (wheels first, then bodies), the
/// wheels tied to line 0 by MovingContacts, HHT-α with the block or the monolithic saddle-point
/// solver. With one wheel of no mass and one body it is the sprung mass of Yang & Yau (1997);
/// with no bodies and the weight on the wheels, a moving force. Used by railfe-moving-study,
/// the tests, the speed/accuracy study and the benchmark.

#include <string>
#include <vector>

#include "physics/implicit/moving_contact.hpp"

namespace railfe {

/// What to run (SI units).
struct CrossingSettings {
  double span = 25;               ///< bridge span (m)
  int elements = 20;              ///< elements per line (even)
  int lines = 1;                  ///< longitudinal lines (grillage when > 1, 2 m apart)
  double young = 2.87e9;          ///< E (Pa)
  double inertia = 2.9;           ///< I (m⁴), both planes
  double mass_per_length = 2303;  ///< ρA (kg/m)
  bool lumped = false;            ///< lumped (HRZ) instead of consistent mass
  int wheels = 1;                 ///< contact points, 2.5 m apart, the first at s = 0 ... s0
  int vehicle_dofs = 2;           ///< vehicle unknowns (wheels + bodies); = wheels: moving force
  double vehicle_mass = 5750;     ///< body mass per wheel (kg); the weight carried per wheel
  double wheel_mass = 0;          ///< mass of each wheel point (kg)
  double stiffness = 1595e3;      ///< suspension stiffness per wheel (N/m)
  double speed = 100 / 3.6;       ///< m/s
  double bump_height = 0;         ///< height of a (1 − cos) bump on the surface (m)
  double bump_length = 1;         ///< its length (m)
  double bump_start = 12;         ///< where it starts (m)
  double dt = 1e-3;               ///< time step (s)
  double alpha = 0;               ///< HHT α
  std::string solver = "block";   ///< "block" or "monolithic"
  bool moving_force = false;      ///< no constraints: the weight as a moving nodal load
  int steps = 0;                  ///< steps to take (0: until the last wheel reaches the end)
  int every = 1;                  ///< record every this many steps
};

/// What came out.
struct CrossingResult {
  std::vector<double> time, position, midspan_deflection, vehicle_displacement,
      vehicle_acceleration, contact_force;           ///< histories (vehicle: the first body)
  std::vector<ContactEvent> events;                  ///< separations and engagements
  std::size_t unknowns = 0, structure_unknowns = 0;  ///< sizes
  std::size_t steps = 0, iterations = 0;             ///< Newton counters
  std::size_t structure_factorizations = 0;          ///< CHOLMOD factorizations of A_s
  std::size_t restarts = 0;  ///< consistent restarts (landings, NewtonStepSolver::after_step())
  double wall_seconds = 0, cpu_seconds = 0;  ///< the time loop (after set-up)
};

/// Runs the crossing.
CrossingResult run_crossing(const CrossingSettings& settings);

}  // namespace railfe
