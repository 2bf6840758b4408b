#pragma once
/// \file
/// Saturation laws that vehicle-dynamics codes put on top of Kalker's linear theory so that the
/// creep force cannot exceed μN. Shen, Hedrick & Elkins (1983): with β = |F_linear| / (μN), the
/// resultant becomes μN (β − β²/3 + β³/27) for β < 3 and μN beyond, both components and the spin
/// moment scaled alike.

#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// The Shen-Hedrick-Elkins saturation of the linear forces \p linear under normal force \p load
/// (N > 0) and friction coefficient \p friction.
CreepForces shen_hedrick_elkins(const CreepForces& linear, double load, double friction);

}  // namespace railfe
