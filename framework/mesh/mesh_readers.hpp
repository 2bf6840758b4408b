#pragma once
/// \file
/// Mesh file readers. They number from 0 and keep the set and block names of the file.

#include <string>

#include "framework/mesh/mesh.hpp"
#include "framework/mesh/revolve.hpp"

namespace railfe {

/// Reads an Exodus II mesh (HEX8 blocks; BAR2/BEAM2, SPRING2 and SPHERE blocks are read as
/// beam2, spring2 and point_mass). Unnamed blocks and sets are called block_<id>, nodelist_<id>,
/// surface_<id>. Throws InputError for a missing or unreadable file or an element type railfe
/// cannot use.
Mesh read_exodus_mesh(const std::string& path);

/// Reads a Gmsh .msh 4.1 ASCII mesh. Hexahedra form element blocks, one per physical volume
/// (or per volume entity when none is defined); quadrangles of a physical surface become both a
/// side set and a node set of that name; physical curves and points become node sets. A mesh
/// without hexahedra is a line model: each physical curve's 2-node lines (Gmsh type 1) also form
/// a beam2 block of its name (a curve in two physical curves is refused).
/// Throws InputError naming the file and line for anything it cannot use.
Mesh read_gmsh_mesh(const std::string& path);

/// Reads a Gmsh .msh 4.1 ASCII mesh of a cross-section to revolve: quadrangles in the x-y plane,
/// x = r and y = a. Each physical surface (or surface entity when none is defined) is a block;
/// physical curves and points become node sets. Nodes that no quadrangle uses are dropped.
/// Throws InputError naming the file for triangles, volume elements or nodes off the plane.
SectionMesh read_gmsh_section(const std::string& path);

}  // namespace railfe
