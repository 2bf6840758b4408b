#pragma once
/// \file
/// The penalty contact pairs of a step (explicit dynamics, or the Newton iterations of statics).
/// Every rank holds every pair's surfaces: each evaluation the owners of the surface nodes share
/// their positions and increments (one sum over ranks of
/// 6 numbers per surface node), every rank evaluates every pair the same way, and each rank adds
/// the forces of the nodes it owns. So no contact force is lost or counted twice at a rank
/// boundary, and the friction history is the same on every rank. The cost is the surface's, not
/// the model's; the exchange grows with the surface and the rank count (docs/theory.md).

#include <array>
#include <string>
#include <vector>

#include "contact/enforcement/penalty_contact_pair.hpp"
#include "framework/base/types.hpp"
#include "physics/common/contact_settings.hpp"
#include "physics/common/contact_surfaces.hpp"

namespace railfe {

class MaterialTable;
class MeshPartition;

/// What selective mass scaling gave one contact pair (ContactPairs::scale_masses()).
struct ContactMassScaling {
  /// the pair's critical step before (s); 0 where the pair has no Mass scaling step
  double step_before = 0;
  double added_mass = 0;  ///< mass added to its nodes, over all ranks (kg)
  long long nodes = 0;    ///< nodes made heavier, over all ranks
};

/// All contact pairs of one step.
class ContactPairs {
 public:
  /// Reads the pairs' surfaces off the mesh (every rank). Throws InputError naming \p deck and
  /// \p path for a node that is both slave and master.
  ContactPairs(const std::vector<ContactPairSpec>& specs, const MeshPartition& partition,
               const MaterialTable& materials, const std::string& deck, const std::string& path);
  ~ContactPairs();

  /// Whether the step has contact pairs.
  bool empty() const { return pairs_.empty(); }
  /// Sets the penalty stiffnesses from \p owned_mass (per owned node; it sets the critical step)
  /// and \p solid_step (the solids' step, for the nodal-mass form; unused by statics), and
  /// refuses a start (reference \p x plus \p u, local arrays) deeper than the pair's limit: a
  /// RunError naming the node and its position, which only a preload can cause, since check time
  /// refuses such reference positions. Collective.
  void initialise(const std::vector<double>& owned_mass, double solid_step, const double* x,
                  const double* u);
  /// Selective mass scaling of every pair whose Mass scaling step T lies above its critical
  /// step: raises \p owned_mass (per owned node) of its slave and master-face nodes to 2 q k̂,
  /// q = (T / 2d)² (d the damper's factor √(1 + ζ²) − ζ), k̂ the stiffest spring the node can
  /// feel in the pair. A node-face pair's reduced mass is at least half the lighter of its nodes,
  /// so each spring then has m_r / k ≥ q and the pair's step is at least T. Call after
  /// initialise(), and initialise() again after it (mass_scaling() keeps what it did).
  /// Returns whether any pair was scaled. Collective.
  bool scale_masses(std::vector<double>& owned_mass);
  /// What scale_masses() did, one entry per pair (empty before it).
  const std::vector<ContactMassScaling>& mass_scaling() const { return mass_scaling_; }
  /// Adds the contact forces at the state (\p x + \p u, step increments \p du of owned nodes,
  /// step \p dt; 0 at the start) to \p residual (owned nodes). Collective.
  void add_forces(const double* x, const double* u, const double* du, double dt, double* residual);
  /// The smallest critical step of the pairs (s), +inf without pairs.
  double stable_step() const;
  /// The pair that sets stable_step(), for messages.
  std::string critical_pair() const;
  /// Energy stored in the penalty springs (J; the same on every rank).
  double stored_energy() const;
  /// Work dissipated by friction and contact damping since the start (J; every rank).
  double dissipated() const;
  /// Wall time spent in add_forces() on this rank since the start (s): exchange, search, forces.
  double seconds() const { return seconds_; }
  /// The pairs.
  const std::vector<PenaltyContactPair>& pairs() const { return pairs_; }
  /// The pairs' specifications.
  const std::vector<ContactPairSpec>& specs() const { return specs_; }
  /// Global node number of surface node \p i.
  GlobalIndex surface_node(int i) const { return surface_[i]; }
  /// Local index of surface node \p i on this rank, −1 where another rank owns it.
  LocalIndex owned_node(int i) const { return owned_[i]; }
  /// Mean shear modulus (Pa) and Poisson's ratio of the elements under pair \p p's master
  /// faces.
  const std::array<double, 2>& master_elastic(std::size_t p) const { return master_elastic_[p]; }
  /// Whether pair \p p has had a node in contact since the start.
  bool ever_touched(std::size_t p) const { return touched_[p]; }
  /// Friction histories and dissipated work, for checkpoints.
  std::vector<double> state() const;
  /// Restores state(); false if it does not fit.
  bool restore(const std::vector<double>& values);

 private:
  // Gives every rank the positions and increments (zero without du) of the surface nodes that
  // subset lists, or of all of them (null), from their owners.
  void share(const double* x, const double* u, const double* du,
             const std::vector<int>* subset = nullptr);

  std::vector<ContactPairSpec> specs_;
  const MeshPartition& partition_;
  const MaterialTable& materials_;
  std::string deck_, path_;
  std::vector<GlobalIndex> surface_;  // global nodes of all pairs, ascending
  std::vector<LocalIndex> owned_;     // local index of each surface node, −1 if not owned
  std::vector<ContactSurfaceNodes> surfaces_;  // per pair, global numbers
  std::vector<PenaltyContactPair> pairs_;
  std::vector<double> exchange_, positions_, increments_, forces_;
  std::vector<int> window_;  // surface nodes any pair reads until its next search, ascending
  std::vector<bool> touched_;
  std::vector<ContactMassScaling> mass_scaling_;
  std::vector<std::array<double, 2>> master_elastic_;  // per pair: G (Pa), nu
  double seconds_ = 0;
};

}  // namespace railfe
