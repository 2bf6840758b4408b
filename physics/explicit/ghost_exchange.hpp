#pragma once
/// \file
/// Moves nodal values between ranks each explicit step: owners send displacements and velocities
/// to the ranks that hold the node as a ghost, and ghosts' force contributions are added into
/// their owners. Only the shared entries travel, packed per neighbour rank and sent point to
/// point; on one rank it does nothing.

#include <mpi.h>

#include <vector>

namespace railfe {

class DofMap;

/// Ghost exchange over the 3-per-node DOF maps of one partition. Arrays hold 3 values per local
/// node, owned nodes first (the DofMap's overlapping numbering).
class GhostExchange {
 public:
  /// Prepares the exchange for \p dofs (3 DOFs per node); collective over the partition's ranks.
  explicit GhostExchange(const DofMap& dofs);
  ~GhostExchange();
  GhostExchange(const GhostExchange&) = delete;
  GhostExchange& operator=(const GhostExchange&) = delete;
  /// Whether there is anything to exchange (more than one rank).
  bool active() const { return active_; }
  /// Copies the owned entries of \p u and \p v into the ghost entries of the other ranks.
  void update_ghosts(double* u, double* v);
  /// Adds the ghost entries of \p forces into their owners' entries (owned entries become the
  /// full sums, contributions added in neighbour rank order; ghost entries are left as they were).
  void sum_into_owners(double* forces);

 private:
  /// One neighbour rank: the owned entries it holds as ghosts (sent to it) and this rank's ghost
  /// entries it owns (received from it), both in the order the two ranks agreed at set-up.
  struct Neighbour {
    int rank = 0;
    std::vector<std::size_t> sent, received;
    std::vector<double> send_buffer, receive_buffer;
  };
  bool active_;
  // A private copy of the communicator: its messages cannot meet Tpetra's or anyone else's.
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::vector<Neighbour> neighbours_;
  std::vector<MPI_Request> requests_;
  /// Starts the receives of \p per_entry values per shared entry from every neighbour: its owned
  /// entries this rank holds as ghosts (\p from_owners) or its ghosts of this rank's entries.
  void post_receives(std::size_t per_entry, bool from_owners);
  /// Sends every neighbour its filled send buffer with \p tag and waits for all sends and the
  /// receives post_receives() started.
  void send_and_wait(int tag);
};

}  // namespace railfe
