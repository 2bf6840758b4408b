#pragma once
/// \file
/// Index types shared by every layer. They match Debian's Tpetra instantiation (int local,
/// long long global ordinals), so arrays can be handed to Tpetra without conversion.

#include <cstdint>

namespace railfe {

/// Index of a node, element or degree of freedom on this rank.
using LocalIndex = int;
/// Index of a node, element or degree of freedom in the whole model (0-based).
using GlobalIndex = long long;

}  // namespace railfe
