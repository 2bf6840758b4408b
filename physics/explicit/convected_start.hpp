#pragma once
/// \file
/// The start of an explicit run from a preload that is steady in a moving frame (a wheel rolling
/// on a rail, the static contact deformation travelling with the axle): the deformation is
/// carried by the material's motion through it, so each node starts with its rigid initial
/// velocity v plus the convective rate ∇u (v − c), c the velocity of the frame in which the
/// preload is steady. Without it the rail's nodes under a rolling wheel start at rest while the
/// deformed shape must move along at V, and the contact force swings at the start
/// (docs/verification.md, "Starting quiet").

#include <array>
#include <vector>

#include "physics/explicit/solid_kernel.hpp"

namespace railfe {

class GhostExchange;

/// Adds ∇u (v − \p frame) to the velocities \p v of the owned nodes (the first \p n_owned; 3 per
/// node) whose entry in \p skip is false. ∇u at a node is the volume-weighted mean of the
/// one-point (element centre) gradients of the elements around it, ghosts' shares summed into
/// their owners by \p ghosts (null on one rank); \p u must hold the ghost nodes' values.
/// Exact for a displacement linear in X.
void add_convected_velocity(const SolidElements& elements, const double* u,
                            const std::array<double, 3>& frame, LocalIndex n_owned,
                            GhostExchange* ghosts, const std::vector<bool>& skip, double* v);

}  // namespace railfe
