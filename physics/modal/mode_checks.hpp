#pragma once
/// \file
/// Independent checks of returned eigenpairs, recomputed from K and M (not taken from the
/// eigensolver), and the modal quantities engineers read: effective masses and doublet partners.

#include <array>
#include <vector>

#include "framework/assembly/dof_map.hpp"
#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

/// Checks and modal quantities of one mode φ (mass-normalized) with eigenvalue λ.
struct ModeCheck {
  /// Normwise backward error ||Kφ − λMφ||∞ / ((||K||∞ + |λ| ||M||∞) ||φ||∞): the relative size of
  /// the smallest perturbation of K and M for which (λ, φ) is exact.
  double backward_error = 0;
  /// max over the other returned modes ψ of |φᵀMψ| (0 for perfectly M-orthogonal modes).
  double orthogonality = 0;
  /// |φᵀMφ − 1|.
  double normalization_error = 0;
  /// Mass of the mode scaled to a largest displacement component of 1 (kg): 1 / max|φ|².
  double modal_mass = 0;
  /// Effective mass along x, y, z (kg): (φᵀ M r_d)² for the unit rigid translation r_d.
  std::array<double, 3> effective_mass{};
  /// Index of the doublet partner (another mode with the same frequency within the doublet
  /// tolerance), or −1.
  int partner = -1;
};

/// Checks every column of \p modes (collective). \p translations holds the unit rigid
/// translations r_x, r_y, r_z over the DOFs (rigid_translations()). Two modes are a doublet when
/// their eigenvalues differ by less than \p doublet_tolerance relative to the larger (frequencies
/// by half that).
std::vector<ModeCheck> check_modes(const TpetraMatrix& K, const TpetraMatrix& M,
                                   const std::vector<double>& eigenvalues,
                                   const TpetraMultiVector& modes,
                                   const TpetraMultiVector& translations, double doublet_tolerance);

/// The unit rigid translations r_x, r_y, r_z (three columns) over the owned DOFs of \p dofs:
/// 1 at each node's component d, 0 at the other components and the rotations.
TpetraMultiVector rigid_translations(const DofMap& dofs);

}  // namespace railfe
