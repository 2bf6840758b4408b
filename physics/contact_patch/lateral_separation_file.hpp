#pragma once
/// \file
/// The "contact patch" step's Separation file: a non-Hertzian patch's undeformed separation across
/// the rolling direction, as a CSV file of y (m) and s (m), and optionally the wheel's rolling
/// radius R (m) at y.

#include <string>

#include "contact/laws/normal_problem.hpp"

namespace railfe {

/// Reads \p path: a header line, then rows "y, s" (m), or "y, s, R" with the wheel's rolling
/// radius R (m), y strictly increasing, every value finite, at least 3 rows. Throws InputError
/// naming \p deck, \p where (the parameter's path), the file and the line at fault.
LateralSeparation read_lateral_separation(const std::string& path, const std::string& deck,
                                          const std::string& where);

}  // namespace railfe
