#pragma once
/// \file
/// Moves nodal values between ranks each explicit step with Tpetra Import/Export: owners send
/// displacements and velocities to the ranks that hold the node as a ghost, and ghosts' force
/// contributions are added into their owners. On one rank it does nothing.

#include <Teuchos_RCP.hpp>

#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

class DofMap;

/// Ghost exchange over the 3-per-node DOF maps of one partition. Arrays hold 3 values per local
/// node, owned nodes first (the DofMap's overlapping numbering).
class GhostExchange {
 public:
  /// Prepares the exchange for \p dofs (3 DOFs per node), which must outlive it.
  explicit GhostExchange(const DofMap& dofs);
  /// Whether there is anything to exchange (more than one rank).
  bool active() const { return active_; }
  /// Copies the owned entries of \p u and \p v into the ghost entries of the other ranks.
  void update_ghosts(double* u, double* v);
  /// Adds the ghost entries of \p forces into their owners' entries (owned entries become the
  /// full sums; ghost entries are left as they were).
  void sum_into_owners(double* forces);

 private:
  const DofMap* dofs_;
  bool active_;
  Teuchos::RCP<TpetraMultiVector> owned_pair_, overlap_pair_;
  Teuchos::RCP<TpetraVector> owned_force_, overlap_force_;
};

}  // namespace railfe
