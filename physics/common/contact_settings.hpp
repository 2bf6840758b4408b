#pragma once
/// \file
/// The Contact pairs of an explicit or statics step: which surfaces touch, how stiff the penalty
/// is, which friction law acts, how often the search is refreshed and when the patch is written.

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/enforcement/friction_law.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/mesh/mesh.hpp"

namespace railfe {

/// One contact pair as the deck gives it.
struct ContactPairSpec {
  std::string name;             ///< its name in the deck
  std::string slave_side_set;   ///< slave nodes from a side set ("" if a node set is given)
  std::string slave_node_set;   ///< slave nodes from a node set ("" if a side set is given)
  std::string master_side_set;  ///< the master faces
  bool mass_penalty = false;    ///< k = f m / Δt² (else the bulk-modulus form f K A² / V)
  bool slave_cap = false;       ///< bulk modulus: also cap k at the slave node's own f K A² / V
  double penalty_factor = 0.1;  ///< f
  double damping_fraction = 0;  ///< normal damping, fraction of critical
  /// s: the pair's nodes get mass until its critical step reaches this (0 = none; explicit only)
  double mass_scaling_step = 0;
  FrictionLaw friction;                         ///< friction law
  int search_interval = 10;                     ///< steps between rebuilds of the search
  double search_margin = 0;                     ///< m; 0 = half the mean master face size
  std::array<double, 3> longitudinal{1, 0, 0};  ///< t₁ of the results' frame
  double penetration_limit = 0.1;   ///< deepest start penetration, fraction of the face size
  std::vector<double> patch_times;  ///< times at which patch fields are written (s)
  bool patch_charts = true;         ///< draw each patch as a PNG map
};

/// What to do about a start penetration, for its messages.
extern const char* const kPlacementAdvice;

/// Which kind of step a contact pair belongs to: a static solve has no time step (so no
/// nodal-mass penalty, damping, search interval or patch times) and no friction yet.
enum class ContactUse { explicit_dynamics, statics };

/// The valid parameters of one entry of Contact pairs in a step of kind \p use.
ParameterSpec contact_pair_parameters(ContactUse use);

/// Reads the validated Contact pairs sublist of a step of kind \p use. Throws InputError naming
/// \p deck and the parameter path for what the spec cannot express (μs < μd).
std::vector<ContactPairSpec> read_contact_pairs(const Teuchos::ParameterList& step,
                                                const std::string& deck, const std::string& path,
                                                ContactUse use);

/// Checks the pairs' sets against \p mesh: they exist, are not empty, slave and master share no
/// node, no slave node starts deeper than the pair's Initial penetration limit (reference
/// positions). Throws InputError naming \p deck and the parameter.
void check_contact_pairs(const std::vector<ContactPairSpec>& pairs, const Mesh& mesh,
                         const std::string& deck, const std::string& path);

}  // namespace railfe
