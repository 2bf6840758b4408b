#pragma once
/// \file
/// Steps shared by the sweeps of revolve.cpp and revolve_coarsening.cpp (not for other callers).

#include <array>
#include <utility>
#include <vector>

#include "framework/mesh/revolve.hpp"

namespace railfe {

/// Throws InputError for a section with a node on or across the axis, or fewer than 3 slices.
void check_section(const SectionMesh& section, int n_around);
/// Throws std::logic_error unless \p angles increase within [0, 2π) once round.
void check_angles(const std::vector<double>& angles);
/// The quads counter-clockwise in (r, a): seen from increasing θ, so nodes 0-3 (slice k) and 4-7
/// (slice k + 1) follow the hex8 convention.
std::vector<std::array<GlobalIndex, 4>> oriented_quads(const SectionMesh& section);
/// Boundary edges of the section: (quad, local edge j from corner j to corner j + 1).
std::vector<std::pair<std::size_t, int>> boundary_edges(
    const std::vector<std::array<GlobalIndex, 4>>& quads);

}  // namespace railfe
