#pragma once
/// \file
/// A canonical form for mode shapes. An eigensolver returns each mode up to its sign and each
/// doublet (two modes of one frequency, as every body of revolution has) up to a rotation within
/// its plane; both depend on round-off, so two runs (or 1 and 2 MPI ranks) would write different
/// but equally right shapes. Fixing them makes outputs comparable and reruns reproducible.

#include <vector>

#include "framework/assembly/tpetra_types.hpp"

namespace railfe {

/// The largest relative split of a pair that canonicalize_modes treats as one degenerate
/// eigenvalue (the modal step's default Doublet tolerance): a wider pair is two modes.
inline constexpr double kDegenerateTolerance = 1e-6;

/// Puts the M-orthonormal columns of \p modes into canonical form (collective). The pivot of a
/// vector field is its first DOF (lowest global index) within a relative 1e-6 of its largest
/// magnitude. A single mode is signed so its pivot is positive. A degenerate doublet (two
/// eigenvalues within both \p doublet_tolerance and kDegenerateTolerance, relative) is rotated so
/// that the first mode holds all of the pair's amplitude at the pair's pivot (positive) and the
/// second none, then the second is signed like a single mode; a wider pair is two single modes.
/// The rigid-body modes (eigenvalues below \p rigid_limit) are replaced by the M-orthonormalized
/// projections of \p rigid_basis (the six rigid motions, in order) onto their span, and their
/// eigenvalues by the Rayleigh quotients with \p K; other clusters of three or more are only
/// signed. All of it keeps M-orthonormality.
void canonicalize_modes(std::vector<double>& eigenvalues, TpetraMultiVector& modes,
                        const TpetraMatrix& K, const TpetraMatrix& M,
                        const TpetraMultiVector& rigid_basis, double rigid_limit,
                        double doublet_tolerance);

}  // namespace railfe
