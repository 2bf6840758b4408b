#pragma once
/// \file
/// The penalty contact of a static solve, linearised about the last evaluation of its pairs
/// (docs/theory.md#penalty-contact-in-statics): per active slave node, with B = n on the slave
/// and −N_a n on the face's nodes, the stiffness k Bᵀ B and the force −k g₀ Bᵀ, g₀ the gap of
/// the reference positions along the current normal, so that the contact force is
/// f_c(u) ≈ f₀ − K_c u for the current active set and projections. No friction.

#include "framework/assembly/dof_map.hpp"

namespace railfe {

class ContactPairs;

/// K_c and f₀ over the owned DOFs of a DofMap.
struct ContactLinearization {
  Teuchos::RCP<TpetraMatrix> stiffness;  ///< K_c, fill-complete over the owned map
  Teuchos::RCP<TpetraVector> force;      ///< f₀ (N)
  long long active = 0;                  ///< active slave nodes over all pairs
};

/// Linearises \p contact about its last add_forces() (collective; every rank holds the same
/// contact and fills the rows it owns).
ContactLinearization linearize_contact(const ContactPairs& contact, const DofMap& dofs);

}  // namespace railfe
