#pragma once
/// \file
/// Element lengths graded away from a finely meshed zone, for generators that refine where the
/// contact passes (the rail's solution zone, the wheel's arc).

#include <vector>

namespace railfe {

/// Lengths that cover \p distance from the edge of a zone meshed at \p first: each the previous
/// times \p growth (the first one \p first × growth), capped at \p largest, then all scaled by
/// one factor so they add up to \p distance exactly (the last, partial length is dropped or
/// kept, whichever leaves the factor nearer 1). Empty for a distance of 0.
std::vector<double> graded_lengths(double distance, double first, double largest, double growth);

}  // namespace railfe
