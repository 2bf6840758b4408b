#pragma once
/// \file
/// The nodes and faces of a contact pair, read off the mesh: slave nodes with their tributary
/// areas, master faces with the elements beneath them. Every rank builds the same lists.

#include <array>
#include <string>
#include <vector>

#include "framework/base/types.hpp"
#include "framework/mesh/mesh.hpp"
#include "physics/common/contact_settings.hpp"

namespace railfe {

/// The surfaces of one pair, in global node numbers.
struct ContactSurfaceNodes {
  std::vector<GlobalIndex> slave_nodes;                  ///< ascending, unique
  std::vector<double> slave_area;                        ///< tributary area of each (m²)
  std::vector<std::array<GlobalIndex, 4>> master_faces;  ///< outward node order
  std::vector<GlobalIndex> master_elements;              ///< the hex8 under each face
  std::vector<std::array<GlobalIndex, 4>> slave_faces;   ///< the faces that give the areas
  std::vector<GlobalIndex> slave_elements;               ///< the hex8 under each slave face
};

/// The surfaces of \p pair on \p mesh (reference coordinates). A slave node's area is a quarter
/// of each slave face around it; for a node set, of each exterior face around it whose nodes
/// all belong to the set. Throws InputError naming \p deck and \p path when a node is both slave
/// and master (self-contact is not supported).
ContactSurfaceNodes contact_surface_nodes(const ContactPairSpec& pair, const Mesh& mesh,
                                          const std::string& deck, const std::string& path);

/// What is wrong with the start of \p pair at \p positions (3 per global node): the first slave
/// node of \p surface deeper inside the master surface than Initial penetration limit x the face
/// size, with its number, position and depth; "" if none. Face sizes come from the reference
/// coordinates of \p mesh.
std::string start_penetration_problem(const ContactPairSpec& pair,
                                      const ContactSurfaceNodes& surface, const Mesh& mesh,
                                      const std::vector<double>& positions);

/// Area of the face \p face of \p mesh in the reference coordinates (quad_area).
double face_area(const Mesh& mesh, const std::array<GlobalIndex, 4>& face);

/// Area of the quadrilateral through \p a, \p b, \p c, \p d: half the cross product of its
/// diagonals (exact for a plane face).
double quad_area(const double* a, const double* b, const double* c, const double* d);

}  // namespace railfe
