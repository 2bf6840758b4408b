#pragma once
/// \file
/// Mathematical constants (C++17 has no std::numbers).

namespace railfe {

/// π to double precision.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace railfe
