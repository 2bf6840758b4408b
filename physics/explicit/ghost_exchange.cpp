#include "physics/explicit/ghost_exchange.hpp"

#include <algorithm>

#include "framework/assembly/dof_map.hpp"

namespace railfe {

GhostExchange::GhostExchange(const DofMap& dofs)
    : dofs_(&dofs), active_(dofs.partition().comm().n_ranks() > 1) {
  if (!active_)
    return;
  owned_pair_ = Teuchos::rcp(new TpetraMultiVector(dofs.owned_map(), 2));
  overlap_pair_ = Teuchos::rcp(new TpetraMultiVector(dofs.overlap_map(), 2));
  owned_force_ = Teuchos::rcp(new TpetraVector(dofs.owned_map()));
  overlap_force_ = Teuchos::rcp(new TpetraVector(dofs.overlap_map()));
}

void GhostExchange::update_ghosts(double* u, double* v) {
  if (!active_)
    return;
  const std::size_t n_owned = dofs_->n_owned_dofs();
  const std::size_t n_overlap = dofs_->n_overlap_dofs();
  {
    auto owned_u = owned_pair_->getDataNonConst(0);
    auto owned_v = owned_pair_->getDataNonConst(1);
    std::copy_n(u, n_owned, owned_u.getRawPtr());
    std::copy_n(v, n_owned, owned_v.getRawPtr());
  }
  overlap_pair_->doImport(*owned_pair_, *dofs_->importer(), Tpetra::INSERT);
  const auto ghost_u = overlap_pair_->getData(0);
  const auto ghost_v = overlap_pair_->getData(1);
  std::copy(ghost_u.begin() + n_owned, ghost_u.begin() + n_overlap, u + n_owned);
  std::copy(ghost_v.begin() + n_owned, ghost_v.begin() + n_overlap, v + n_owned);
}

void GhostExchange::sum_into_owners(double* forces) {
  if (!active_)
    return;
  const std::size_t n_owned = dofs_->n_owned_dofs();
  const std::size_t n_overlap = dofs_->n_overlap_dofs();
  {
    auto overlap = overlap_force_->getDataNonConst();
    std::fill_n(overlap.getRawPtr(), n_owned, 0.0);
    std::copy(forces + n_owned, forces + n_overlap, overlap.getRawPtr() + n_owned);
  }
  // Owned entries keep their local sums; only the ghosts' contributions travel.
  owned_force_->putScalar(0.0);
  owned_force_->doExport(*overlap_force_, *dofs_->importer(), Tpetra::ADD);
  const auto received = owned_force_->getData();
  for (std::size_t k = 0; k < n_owned; ++k)
    forces[k] += received[k];
}

}  // namespace railfe
