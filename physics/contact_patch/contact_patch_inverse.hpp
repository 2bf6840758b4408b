#pragma once
/// \file
/// The "contact patch" step's inverse cases (Prescribe forces): the creepages that carry each
/// case's prescribed tangential forces on the exact solver's patch (inverse_creepage.hpp), and
/// the table <step>_inverse.csv of forces prescribed and creepages found.

#include <array>
#include <vector>

#include "contact/laws/inverse_creepage.hpp"
#include "contact/laws/normal_problem.hpp"
#include "framework/app/module.hpp"

namespace railfe {

/// For each case of \p cases (spin given), finds the longitudinal and lateral creepages whose
/// exact steady-rolling solution on \p patch (its leading edge used, as the forward solve does)
/// carries the forces \p forces (Fx, Fy on body 1, N) to \p tolerance × μs N, sets them in
/// \p cases and writes <step>_inverse.csv: FN, Fx, Fy, φ prescribed, ξ, η found, the forces met,
/// the miss over μs N, Newton iterations and the adhesion share. Throws RunError naming the case
/// where no creepage carries the forces (the traction bound reached on the discrete patch, or no
/// convergence).
void find_creepages(StepContext& context, const HertzPatch& patch, const FrictionLaw& friction,
                    double tolerance, const std::vector<std::array<double, 2>>& forces,
                    std::vector<Creepages>& cases);

}  // namespace railfe
