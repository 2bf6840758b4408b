#pragma once
/// \file
/// Loads and kinematic conditions on the nodes of an explicit run, as functions of time: each
/// load is assembled once into a sparse list of owned DOFs and scaled by its function every
/// step; prescribed motion is evaluated per node only when its function depends on position.

#include <array>
#include <string>
#include <vector>

#include "framework/base/types.hpp"
#include "framework/deck/expression.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/explicit/explicit_settings.hpp"

namespace railfe {

class DofMap;
class MeshPartition;
class MaterialTable;

/// The applied loads (nodal forces and surface loads; gravity is applied through the masses).
class TimedLoads {
 public:
  /// Assembles each load of \p settings once (collective).
  TimedLoads(const ExplicitSettings& settings, const MaterialTable& materials, const DofMap& dofs,
             const std::string& deck, const std::string& path);
  /// Adds the loads at \p time into \p forces (owned DOFs).
  void add(double time, double* forces) const;

 private:
  struct Load {
    std::vector<LocalIndex> dofs;
    std::vector<double> values;
    Expression function;
  };
  std::vector<Load> loads_;
};

/// One prescribed degree of freedom.
struct PrescribedDof {
  LocalIndex dof = 0;  ///< owned local DOF
  int motion = 0;      ///< index of its condition
};

/// Prescribed displacements and velocities of owned DOFs.
class PrescribedMotions {
 public:
  /// Collects the owned DOFs of each condition of \p settings (later conditions win where two
  /// name the same DOF). \p coordinates are the reference positions of local nodes.
  PrescribedMotions(const ExplicitSettings& settings, LocalIndex n_owned_nodes,
                    const std::vector<std::vector<LocalIndex>>& owned_nodes_of_motion,
                    const double* coordinates, const std::string& deck, const std::string& path);
  /// The prescribed DOFs.
  const std::vector<PrescribedDof>& dofs() const { return dofs_; }
  /// Whether owned DOF \p dof is prescribed.
  bool prescribed(LocalIndex dof) const { return flags_[dof] != 0; }
  /// Sets u (and the step's du), v and a of every prescribed DOF to their values at \p time (the
  /// end of a step of length \p dt; dt = 0 sets the initial state). Velocity and acceleration
  /// are central differences of the function over ±dt, so a rigid motion stays rigid and the
  /// support reactions do no spurious work.
  void apply(double time, double dt, double* u, double* du, double* v, double* a) const;

 private:
  double value(const PrescribedDof& entry, double time) const;
  double value(const PrescribedDof& entry, double time, int motion) const;

  std::vector<PrescribedMotion> motions_;
  std::vector<Expression> functions_;
  std::vector<bool> uniform_;
  std::vector<PrescribedDof> dofs_;
  std::vector<char> flags_;
  // Per condition, its function of time alone at t − h, t, t + h (reused every step).
  mutable std::vector<double> values_at_[3];
  const double* coordinates_;
};

/// Whether the deck expression \p text uses x, y or z (else it is a function of t alone).
bool depends_on_position(const std::string& text);

}  // namespace railfe
