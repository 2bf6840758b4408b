#pragma once
/// \file
/// Mesh file readers. Both return a Mesh numbered from 0, with set and block names from the file.

#include <string>

#include "framework/mesh/mesh.hpp"

namespace railfe {

/// Reads an Exodus II mesh (HEX8 blocks; BAR2/BEAM2 and SPHERE blocks are read as beam2 and
/// point_mass). Unnamed blocks and sets are called block_<id>, nodelist_<id>, surface_<id>.
/// Throws InputError for a missing or unreadable file or an element type railfe cannot use.
Mesh read_exodus_mesh(const std::string& path);

/// Reads a Gmsh .msh 4.1 ASCII mesh. Hexahedra form element blocks, one per physical volume
/// (or per volume entity when none is defined); quadrangles of a physical surface become both a
/// side set and a node set of that name; physical curves and points become node sets.
/// Throws InputError naming the file and line for anything it cannot use.
Mesh read_gmsh_mesh(const std::string& path);

}  // namespace railfe
