#pragma once
/// \file
/// The Moving contacts of an implicit step as the deck gives them (the direct method, see
/// moving_contact.hpp): a vehicle node tied to the beam beneath it as it travels, with
/// irregularities, separation, and the saddle-point solver that couples them.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "framework/deck/deck.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"

namespace railfe {

/// One vehicle point on a path.
struct MovingContactSpec {
  std::string name;                   ///< its deck name
  std::string node_set;               ///< the vehicle's contact node (a set of one node)
  std::vector<std::string> blocks;    ///< the beam blocks of its path
  double start = 0;                   ///< arc length at t = 0 (m)
  double speed = 0;                   ///< ds/dt (m/s)
  bool lateral = false;               ///< tied laterally (global y) as well as vertically (z)
  std::string vertical_irregularity;  ///< function of s (m), '' = none
  std::string lateral_irregularity;   ///< function of s (m), '' = none
  std::string irregularity_file;      ///< CSV s, vertical, lateral (absolute path), '' = none
  bool separation = true;             ///< whether a pulling force releases the point
};

/// Adds Moving contacts and Constraint solver to an implicit step's spec.
void add_moving_contact_parameters(ParameterSpec& spec);

/// Reads the Moving contacts of a validated step list (the irregularity file resolved by
/// \p deck). Throws InputError naming the deck and the parameter for an irregularity given
/// twice, or a file that cannot be read.
std::vector<MovingContactSpec> read_moving_contacts(const Teuchos::ParameterList& step,
                                                    const Deck& deck, const std::string& path);

/// Checks \p contacts against \p mesh for a run to \p end_time: a contact node set of exactly
/// one node, not on its own path, a path of beams that holds the point from t = 0 to the end
/// (a vehicle that would leave the structure is refused here, before anything runs), and an
/// irregularity file that exists. Throws InputError naming \p deck and the parameter.
void check_moving_contacts(const std::vector<MovingContactSpec>& contacts, const Mesh& mesh,
                           double end_time, const std::string& deck, const std::string& path);

}  // namespace railfe
