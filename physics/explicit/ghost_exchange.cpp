#include "physics/explicit/ghost_exchange.hpp"

#include <algorithm>
#include <map>

#include <Tpetra_Map.hpp>

#include "framework/assembly/dof_map.hpp"
#include "framework/base/error.hpp"

namespace railfe {

namespace {

constexpr int kGhostTag = 1, kForceTag = 2;

void check(int status, const char* what) {
  if (status != MPI_SUCCESS)
    throw RunError(std::string("the explicit ghost exchange failed in ") + what);
}

}  // namespace

GhostExchange::GhostExchange(const DofMap& dofs) : active_(dofs.partition().comm().n_ranks() > 1) {
  if (!active_)
    return;
  const MPI_Comm parent = dofs.partition().comm().mpi();
  check(MPI_Comm_dup(parent, &comm_), "MPI_Comm_dup");
  int n_ranks = 0;
  MPI_Comm_size(comm_, &n_ranks);
  // The owned map's directory knows each ghost's owner; the owners learn which of their entries
  // to send by receiving the ghosts' global indices once, so both sides list them in one order.
  const auto overlap = dofs.overlap_map();
  const auto owned = dofs.owned_map();
  const std::size_t n_owned = dofs.n_owned_dofs(), n_overlap = dofs.n_overlap_dofs();
  std::vector<GlobalIndex> ghost_ids;
  for (std::size_t k = n_owned; k < n_overlap; ++k)
    ghost_ids.push_back(overlap->getGlobalElement(static_cast<LocalIndex>(k)));
  std::vector<int> owners(ghost_ids.size(), -1);
  owned->getRemoteIndexList(Teuchos::ArrayView<const GlobalIndex>(ghost_ids),
                            Teuchos::ArrayView<int>(owners));
  std::map<int, std::vector<long long>> requested;  // owner -> global indices, in ghost order
  std::map<int, std::vector<std::size_t>> ghosts;   // owner -> local overlap entries
  for (std::size_t k = 0; k < ghost_ids.size(); ++k) {
    if (owners[k] < 0)
      throw RunError("the explicit ghost exchange: a ghost entry has no owner");
    requested[owners[k]].push_back(ghost_ids[k]);
    ghosts[owners[k]].push_back(n_owned + k);
  }
  std::vector<int> counts_out(static_cast<std::size_t>(n_ranks), 0), counts_in(counts_out);
  for (const auto& [owner, list] : requested)
    counts_out[static_cast<std::size_t>(owner)] = static_cast<int>(list.size());
  check(MPI_Alltoall(counts_out.data(), 1, MPI_INT, counts_in.data(), 1, MPI_INT, comm_),
        "MPI_Alltoall");
  std::vector<int> displacements_out(counts_out.size(), 0), displacements_in(counts_in.size(), 0);
  std::vector<long long> flat_out;
  for (int p = 0; p < n_ranks; ++p) {
    displacements_out[static_cast<std::size_t>(p)] = static_cast<int>(flat_out.size());
    const auto it = requested.find(p);
    if (it != requested.end())
      flat_out.insert(flat_out.end(), it->second.begin(), it->second.end());
  }
  int total_in = 0;
  for (int p = 0; p < n_ranks; ++p) {
    displacements_in[static_cast<std::size_t>(p)] = total_in;
    total_in += counts_in[static_cast<std::size_t>(p)];
  }
  std::vector<long long> flat_in(static_cast<std::size_t>(total_in));
  check(MPI_Alltoallv(flat_out.data(), counts_out.data(), displacements_out.data(), MPI_LONG_LONG,
                      flat_in.data(), counts_in.data(), displacements_in.data(), MPI_LONG_LONG,
                      comm_),
        "MPI_Alltoallv");
  for (int p = 0; p < n_ranks; ++p) {
    const auto in = static_cast<std::size_t>(counts_in[static_cast<std::size_t>(p)]);
    const auto it = ghosts.find(p);
    if (in == 0 && it == ghosts.end())
      continue;
    Neighbour neighbour;
    neighbour.rank = p;
    const auto begin = flat_in.begin() + displacements_in[static_cast<std::size_t>(p)];
    for (auto g = begin; g != begin + static_cast<std::ptrdiff_t>(in); ++g) {
      const auto local = owned->getLocalElement(*g);
      if (local == Teuchos::OrdinalTraits<LocalIndex>::invalid() || local < 0)
        throw RunError("the explicit ghost exchange: rank " + std::to_string(p) +
                       " asks for an entry this rank does not own");
      neighbour.sent.push_back(static_cast<std::size_t>(local));
    }
    if (it != ghosts.end())
      neighbour.received = it->second;
    neighbours_.push_back(std::move(neighbour));
  }
  requests_.resize(2 * neighbours_.size());
}

GhostExchange::~GhostExchange() {
  if (comm_ != MPI_COMM_NULL)
    MPI_Comm_free(&comm_);
}

void GhostExchange::post_receives(std::size_t per_entry, bool from_owners) {
  for (std::size_t n = 0; n < neighbours_.size(); ++n) {
    Neighbour& neighbour = neighbours_[n];
    const std::size_t count =
        per_entry * (from_owners ? neighbour.received.size() : neighbour.sent.size());
    neighbour.receive_buffer.resize(count);
    check(MPI_Irecv(neighbour.receive_buffer.data(), static_cast<int>(count), MPI_DOUBLE,
                    neighbour.rank, from_owners ? kGhostTag : kForceTag, comm_, &requests_[n]),
          "MPI_Irecv");
  }
}

void GhostExchange::send_and_wait(int tag) {
  const std::size_t n_neighbours = neighbours_.size();
  for (std::size_t n = 0; n < n_neighbours; ++n) {
    std::vector<double>& buffer = neighbours_[n].send_buffer;
    check(MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, neighbours_[n].rank,
                    tag, comm_, &requests_[n_neighbours + n]),
          "MPI_Isend");
  }
  check(MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE),
        "MPI_Waitall");
}

void GhostExchange::update_ghosts(double* u, double* v) {
  if (!active_)
    return;
  post_receives(2, true);
  for (Neighbour& neighbour : neighbours_) {
    neighbour.send_buffer.resize(2 * neighbour.sent.size());
    double* out = neighbour.send_buffer.data();
    for (std::size_t k : neighbour.sent) {
      *out++ = u[k];
      *out++ = v[k];
    }
  }
  send_and_wait(kGhostTag);
  for (const Neighbour& neighbour : neighbours_) {
    const double* in = neighbour.receive_buffer.data();
    for (std::size_t k : neighbour.received) {
      u[k] = *in++;
      v[k] = *in++;
    }
  }
}

void GhostExchange::sum_into_owners(double* forces) {
  if (!active_)
    return;
  post_receives(1, false);
  for (Neighbour& neighbour : neighbours_) {
    neighbour.send_buffer.resize(neighbour.received.size());
    std::transform(neighbour.received.begin(), neighbour.received.end(),
                   neighbour.send_buffer.begin(), [forces](std::size_t k) { return forces[k]; });
  }
  send_and_wait(kForceTag);
  // Owned entries keep their local sums; the ghosts' contributions are added in rank order.
  for (const Neighbour& neighbour : neighbours_) {
    const double* in = neighbour.receive_buffer.data();
    for (std::size_t k : neighbour.sent)
      forces[k] += *in++;
  }
}

}  // namespace railfe
