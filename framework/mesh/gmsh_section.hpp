#pragma once
/// \file
/// Meshing a cross-section with the gmsh program, for generators of bodies of revolution (a
/// wheel from its profile) that describe their section as a Gmsh .geo script.

#include <string>

#include "framework/mesh/revolve.hpp"

namespace railfe {

/// Runs `gmsh -2` (found on PATH) on \p geo_script in a fresh private temporary directory, so
/// ranks and concurrent runs never share files, reads the result with read_gmsh_section() and
/// removes the directory. The script must produce quadrangles only in the x-y plane (x = r,
/// y = a). \p source names the origin in messages (e.g. "deck.xml: Mesh/Wheel"). Throws RunError
/// when gmsh is missing or cannot be started, and InputError, with gmsh's own error lines, when
/// it fails on the script or its result is not an all-quadrangle section.
SectionMesh mesh_section_with_gmsh(const std::string& geo_script, const std::string& source);

/// Full path of the gmsh program on PATH, or "" when there is none.
std::string find_gmsh();

}  // namespace railfe
