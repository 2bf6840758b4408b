#pragma once
/// \file
/// The central-difference time stepper of explicit dynamics: the Newmark(β = 0, γ = ½) member of
/// the integrator family (framework/time/newmark.hpp) with a lumped mass, written as one fused
/// pass over the nodes so that no step copies state. Per step: predict u_{n+1} = u_n + Δt v_n +
/// ½Δt² a_n and the midpoint velocity ṽ = v_n + ½Δt a_n; apply prescribed motion and rigid
/// bodies; exchange ghosts; evaluate element, spring and applied forces at (u_{n+1}, ṽ); solve
/// the diagonal system (1 + ½αΔt) M a_{n+1} = f − αM ṽ (Rayleigh mass damping taken implicitly);
/// correct v_{n+1} = ṽ + ½Δt a_{n+1}. The energy balance is kept with trapezoidal work integrals
/// (docs/theory.md#explicit-dynamics).

#include <memory>
#include <string>
#include <vector>

#include "framework/base/parallel.hpp"
#include "physics/explicit/discrete_parts.hpp"
#include "physics/explicit/explicit_settings.hpp"
#include "physics/explicit/solid_kernel.hpp"

namespace railfe {

class DofMap;
class ContactPairs;
class GhostExchange;
class MaterialTable;
class TimedLoads;
class PrescribedMotions;

/// The energy balance of a run (summed over ranks).
struct EnergyBalance {
  double kinetic = 0;        ///< ½ vᵀ M v of nodes and bodies (J)
  double internal = 0;       ///< strain energy of solids plus spring energy (J)
  double hourglass = 0;      ///< stored (stiffness form) or dissipated (viscous form) (J)
  double contact = 0;        ///< stored in the contact penalty springs (J)
  double friction = 0;       ///< dissipated by contact friction and contact damping (J)
  double damping = 0;        ///< dissipated by Rayleigh damping, bulk viscosity, dampers (J)
  double external_work = 0;  ///< work of loads, gravity and supports since the start (J)
  double error = 0;          ///< (E − E₀ − W) / max(E₀, E, |W|), E = sum of the six above
};

/// Everything that changes during a run, for checkpoints: per rank.
struct SolverState {
  std::vector<double> scalars;   ///< time, step, accumulators
  std::vector<double> arrays;    ///< nodal arrays
  std::vector<double> discrete;  ///< rigid bodies
};

/// The stable step of solids and contact springs together: the smaller of \p solids and
/// \p contact, lowered where the two are close. There a slave node is held by its elements and
/// its penalty springs at nearly one frequency, and the coupled limit is below either (contact
/// stability map, docs/verification.md: limits 3 % apart blew up from 0.85 of the smaller and
/// ran at 0.8; 78 % apart, runs to 0.9 of the smaller were stable). The factor on the smaller is
/// 0.83 when they are equal, rising linearly to 1 where the larger is 1.5 times the smaller, so
/// that the automatic step (Safety factor 0.9) stays at or below 0.75 of the smaller there.
double coupled_stable_step(double solids, double contact);

/// Central-difference integration of one rank's part of the model.
class ExplicitSolver {
 public:
  /// Prepares elements, masses, loads and discrete parts (collective). \p dofs has 3 DOFs per node.
  ExplicitSolver(const ExplicitSettings& settings, const DofMap& dofs,
                 const MaterialTable& materials, const std::string& deck, const std::string& path);
  ~ExplicitSolver();

  /// Sets the initial state: displacements \p start (owned, 3 per node; null = zero), initial
  /// velocities and prescribed motion; finds the initial accelerations (collective).
  void initialise(const double* start);
  /// Before initialise(): take \p calibration as step_calibration() instead of measuring it on
  /// the start state, so that a run resumed from a checkpoint (possibly by a deck that starts
  /// from another state, e.g. without the preload) steps exactly as the run that wrote it.
  void preset_step_calibration(double calibration) { preset_calibration_ = calibration; }
  /// The step calibration a checkpoint's first section carries (0 if it carries none).
  static double checkpointed_step_calibration(const std::vector<double>& scalars);
  /// Advances by \p dt (collective).
  void step(double dt);
  /// Global over element-by-element stable step at the start: the Lanczos estimate of the
  /// mesh's highest frequency, 2/ω_max, over the smallest L/c_P.
  double step_calibration() const { return step_calibration_; }
  /// Stable step at the current state over all ranks, before the safety factor (s): each
  /// element's L/c_P (reduced by bulk viscosity) times step_calibration(), and the springs',
  /// joined with the contact pairs' by coupled_stable_step().
  double stable_step() const { return stable_step_; }
  /// The solids' and springs' stable step alone (s), without contact.
  double solid_stable_step() const { return solid_stable_step_; }
  /// The contact pairs' critical step (s), +inf without contact.
  double contact_stable_step() const;
  /// The contact pairs.
  const ContactPairs& contact() const { return *contact_; }
  /// Where the stable step is smallest, for messages ("element 12 of block 'rail' at (x, y, z)"
  /// or "spring–dampers").
  std::string critical_location() const;
  /// Simulated time (s).
  double time() const { return time_; }
  /// The last step's length (s).
  double last_step() const { return last_step_; }
  /// Steps taken.
  long long n_steps() const { return n_steps_; }
  /// The energy balance at the current state (collective).
  EnergyBalance energy_balance() const;
  /// Mean of component \p component of \p quantity (0 u, 1 v, 2 a) over the owned nodes of
  /// \p nodes, as (sum, count) for a sum over ranks.
  std::pair<double, double> node_sum(const std::vector<LocalIndex>& nodes, int quantity,
                                     int component) const;
  /// Displacements, velocities, accelerations (3 per local node, owned first).
  const std::vector<double>& displacement() const { return u_; }
  /// Velocities.
  const std::vector<double>& velocity() const { return v_; }
  /// Accelerations.
  const std::vector<double>& acceleration() const { return a_; }
  /// The rigid bodies and point masses.
  const std::vector<RigidBody>& bodies() const { return discrete_->bodies(); }
  /// The solid elements.
  const SolidElements& elements() const { return elements_; }
  /// Total mass of the model (kg, summed over ranks).
  double total_mass() const;
  /// What selective mass scaling (Mass scaling step) did, summed over ranks.
  struct MassScaling {
    double added_mass = 0;          ///< kg
    long long scaled_elements = 0;  ///< elements made heavier
  };
  /// The mass scaling applied at set-up.
  const MassScaling& mass_scaling() const { return mass_scaling_; }
  /// Kinetic, internal and hourglass energy at the start (the balance's reference).
  double initial_energy() const { return initial_energy_; }
  /// The state to checkpoint.
  SolverState state() const;
  /// Restores a checkpointed state (throws RunError if it does not fit this partition).
  void restore(const SolverState& state);

 private:
  /// gravity_now_ at \p time.
  void set_gravity(double time);
  /// Zeroes the internal forces and sets the applied ones (gravity, loads) at \p time for
  /// evaluate_forces(); step() does the same inside its predictor pass.
  void prepare_forces(double time);
  /// Internal forces, the residual (applied minus internal, springs, contact) and the stable
  /// step, after prepare_forces(); \p dt is the step just taken (0 at the start).
  void evaluate_forces(double dt);
  void calibrate_stable_step();
  NodalArrays arrays();
  double kinetic_energy_local() const;

  const ExplicitSettings& settings_;
  const DofMap& dofs_;
  const Communicator& comm_;
  std::string deck_;
  LocalIndex n_owned_ = 0;
  std::size_t n_owned_dofs_ = 0;
  std::vector<double> x_, u_, v_, a_, du_, force_, residual_, mass_;
  std::vector<double> applied_;            // applied forces at the end of the step (owned)
  std::vector<double> external_;           // applied forces at the start of the step (owned)
  std::vector<double> previous_reaction_;  // support reaction per prescribed DOF
  // Raises the density of elements whose stable step is below \p target (0: none) and returns
  // each local element's factor (partition order); fills mass_scaling_.
  std::vector<double> scale_small_elements(double target);
  MassScaling mass_scaling_;
  SolidElements elements_;
  std::unique_ptr<GhostExchange> ghosts_;
  std::unique_ptr<TimedLoads> loads_;
  std::unique_ptr<PrescribedMotions> motions_;
  std::unique_ptr<DiscreteParts> discrete_;
  std::unique_ptr<ContactPairs> contact_;
  std::unique_ptr<Expression> gravity_function_;
  std::array<double, 3> gravity_now_{};
  double time_ = 0, last_step_ = 0;
  long long n_steps_ = 0;
  double stable_step_ = 0, solid_stable_step_ = 0;
  double step_calibration_ = 1;    // global (Lanczos) limit over the element estimate at the start
  double preset_calibration_ = 0;  // > 0: taken instead of measuring (a resumed run)
  int critical_rank_ = 0;
  LocalIndex critical_element_ = -1;
  SolidForceTotals totals_;
  double spring_energy_ = 0, damper_power_ = 0;
  double initial_energy_ = 0;
  double external_work_ = 0, damping_work_ = 0, hourglass_work_ = 0;
};

}  // namespace railfe
