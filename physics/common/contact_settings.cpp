#include "physics/common/contact_settings.hpp"

#include <algorithm>

#include <Teuchos_Array.hpp>

#include "framework/base/error.hpp"
#include "physics/common/contact_surfaces.hpp"

namespace railfe {

const char* const kPlacementAdvice =
    "bodies placed apart or touching at the start (move a part, or start from a statics step)";

ParameterSpec contact_pair_parameters(ContactUse use) {
  const bool dynamic = use == ContactUse::explicit_dynamics;
  ParameterSpec spec(
      dynamic ? "A penalty node-to-segment contact pair: the slave nodes may not pass through the "
                "master faces (docs/theory.md#penalty-contact-explicit). Give the slave nodes as "
                "a side set or a node set."
              : "A frictionless penalty node-to-segment contact pair, solved by Newton "
                "iterations on the active set (docs/theory.md#penalty-contact-in-statics); give "
                "an explicit step that starts from this one the same pair. Give the slave nodes "
                "as a side set or a node set.");
  spec.text("Slave side set", "", "Slave nodes: the nodes of these faces (the finer surface).");
  spec.text("Slave node set", "", "Slave nodes given directly (give this or Slave side set).");
  spec.required_text("Master side set", "Master faces (quadrilaterals, outward normals).");
  std::vector<Choice> stiffnesses = {
      {"bulk modulus", "k = f K A^2 / V of the element under the master face"},
      {"bulk modulus, softer side",
       "the smaller of the master face's f K A^2 / V and the slave node's own (a quarter of "
       "f K A^2 / V of each slave face around it), as LS-DYNA's segment-based default: a coarse "
       "master face does not stiffen the fine slave nodes on it, nor shorten the step"}};
  if (dynamic)
    stiffnesses.push_back({"nodal mass",
                           "k = f m / dt^2, m the reduced mass of slave node and face, dt the "
                           "solids' step at the start"});
  spec.choice("Penalty stiffness", "bulk modulus", stiffnesses,
              "How the penalty stiffness is set.");
  spec.real("Penalty factor", 0.1,
            dynamic ? "f of the penalty stiffness."
                    : "f of the penalty stiffness k = f K A^2 / V (bulk-modulus form).",
            "", Range::open_closed(0, 100));
  if (dynamic) {
    spec.real("Mass scaling step", 0.0,
              "Selective mass scaling of the pair (as the solids' Mass scaling step): where its "
              "critical step is below this one, its slave nodes and master-face nodes get the "
              "mass that raises it there (each node to 2 q k of the stiffest spring it can feel, "
              "q = (this / 2)^2, so every node-face pair's reduced mass suffices); 0 = none. The "
              "mass added is reported in the summary, with a warning above 1 % of the total. Not "
              "with Penalty stiffness 'nodal mass', whose springs grow with the masses.",
              "s", Range::non_negative());
    spec.only_when("Penalty stiffness", {"bulk modulus", "bulk modulus, softer side"},
                   {"Mass scaling step"});
    spec.real("Damping fraction", 0.0, "Normal contact damping as a fraction of critical.", "",
              Range::closed(0, 1));
    spec.choice("Friction", "none",
                {{"none", "frictionless"},
                 {"coulomb", "Coulomb, constant Friction coefficient"},
                 {"velocity dependent", "mu = mu_d + (mu_s - mu_d) exp(-c |v_slip|)"}},
                "Friction law.");
    spec.real("Friction coefficient", 0.3, "Coulomb's mu.", "", Range::open_closed(0, 2));
    spec.real("Static coefficient", 0.45, "mu_s.", "", Range::open_closed(0, 2));
    spec.real("Dynamic coefficient", 0.3, "mu_d (at most mu_s).", "", Range::open_closed(0, 2));
    spec.real("Decay", 0.0, "c of the exponential decay with slip speed.", "s/m",
              Range::non_negative());
    spec.only_when("Friction", {"coulomb"}, {"Friction coefficient"});
    spec.only_when("Friction", {"velocity dependent"},
                   {"Static coefficient", "Dynamic coefficient", "Decay"});
    spec.integer("Search interval", 10,
                 "Steps between rebuilds of the bucket search (sooner when the surfaces move "
                 "further than the capture distance allows).",
                 Range::closed(1, 10000));
  }
  spec.real("Search margin", 0.0,
            "Distance beyond the surfaces' motion within which faces are caught (0 = half the "
            "mean master face size).",
            "m", Range::non_negative());
  spec.real_array("Longitudinal direction", {1, 0, 0},
                  "t1 of the frame the results use: projected onto the contact plane; t2 = n x "
                  "t1.",
                  "", 3);
  spec.real("Initial penetration limit", 0.1,
            "The deepest penetration allowed at the start, as a fraction of the master face "
            "size; deeper starts are refused.",
            "", Range::open_closed(0, 1));
  if (dynamic) {
    spec.real_array("Patch times", {},
                    "Times at which the patch fields (pressure, shear, slip) are written.", "s");
    spec.flag("Patch charts", true,
              "Draw each patch as <step>_contact_<pair>_patch_<k>.png: pressure as colour with "
              "shear arrows, and micro-slip arrows over the stick and slip areas (needs python3 "
              "with matplotlib).");
  }
  return spec;
}

std::vector<ContactPairSpec> read_contact_pairs(const Teuchos::ParameterList& step,
                                                const std::string& deck, const std::string& path,
                                                ContactUse use) {
  const bool dynamic = use == ContactUse::explicit_dynamics;
  std::vector<ContactPairSpec> pairs;
  const auto& list = step.sublist("Contact pairs");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it);
    const std::string where = path + "/Contact pairs/" + name;
    const auto& entry = list.sublist(name);
    ContactPairSpec pair;
    pair.name = name;
    pair.slave_side_set = entry.get<std::string>("Slave side set");
    pair.slave_node_set = entry.get<std::string>("Slave node set");
    if (pair.slave_side_set.empty() == pair.slave_node_set.empty())
      throw_input_error(deck, where,
                        pair.slave_side_set.empty() ? "names no slave surface"
                                                    : "names both a Slave side set and a Slave "
                                                      "node set",
                        "exactly one of Slave side set and Slave node set");
    pair.master_side_set = entry.get<std::string>("Master side set");
    pair.penalty_factor = entry.get<double>("Penalty factor");
    const std::string stiffness = entry.get<std::string>("Penalty stiffness");
    pair.mass_penalty = stiffness == "nodal mass";
    pair.slave_cap = stiffness == "bulk modulus, softer side";
    if (dynamic) {
      pair.mass_scaling_step = entry.get<double>("Mass scaling step");
      pair.damping_fraction = entry.get<double>("Damping fraction");
      pair.search_interval = entry.get<int>("Search interval");
    }
    const std::string law = dynamic ? entry.get<std::string>("Friction") : "none";
    if (law == "coulomb") {
      pair.friction.kind = FrictionLaw::Kind::coulomb;
      pair.friction.static_coefficient = entry.get<double>("Friction coefficient");
    } else if (law == "velocity dependent") {
      pair.friction.kind = FrictionLaw::Kind::velocity_dependent;
      pair.friction.static_coefficient = entry.get<double>("Static coefficient");
      pair.friction.dynamic_coefficient = entry.get<double>("Dynamic coefficient");
      pair.friction.decay = entry.get<double>("Decay");
      if (pair.friction.dynamic_coefficient > pair.friction.static_coefficient)
        throw_input_error(deck, where + "/Dynamic coefficient",
                          "is above the Static coefficient (" +
                              std::to_string(pair.friction.static_coefficient) + ")",
                          "mu_d <= mu_s: friction falls with slip speed");
    }
    pair.search_margin = entry.get<double>("Search margin");
    const auto& direction = entry.get<Teuchos::Array<double>>("Longitudinal direction");
    pair.longitudinal = {direction[0], direction[1], direction[2]};
    if (direction[0] == 0 && direction[1] == 0 && direction[2] == 0)
      throw_input_error(deck, where + "/Longitudinal direction", "is the zero vector",
                        "a non-zero direction");
    pair.penetration_limit = entry.get<double>("Initial penetration limit");
    if (dynamic) {
      const auto& times = entry.get<Teuchos::Array<double>>("Patch times");
      pair.patch_times.assign(times.begin(), times.end());
      pair.patch_charts = entry.get<bool>("Patch charts");
      // only_when() takes choices and flags; an empty time list is checked here.
      if (pair.patch_times.empty() && !entry.getEntry("Patch charts").isDefault())
        throw_input_error(deck, where + "/Patch charts",
                          "is used only with Patch times, which are not given, so the value "
                          "would be ignored",
                          "remove 'Patch charts', or give Patch times");
    }
    if (!std::is_sorted(pair.patch_times.begin(), pair.patch_times.end()) ||
        std::any_of(pair.patch_times.begin(), pair.patch_times.end(),
                    [](double t) { return t < 0; }))
      throw_input_error(deck, where + "/Patch times", "are not ascending and non-negative",
                        "ascending times from 0 to the End time");
    pairs.push_back(pair);
  }
  return pairs;
}

void check_contact_pairs(const std::vector<ContactPairSpec>& pairs, const Mesh& mesh,
                         const std::string& deck, const std::string& path) {
  for (const ContactPairSpec& pair : pairs) {
    const std::string where = path + "/Contact pairs/" + pair.name;
    std::vector<GlobalIndex> slave;
    if (!pair.slave_node_set.empty()) {
      slave = mesh.node_set(pair.slave_node_set, deck, where + "/Slave node set").nodes;
    } else {
      const SideSet& sides = mesh.side_set(pair.slave_side_set, deck, where + "/Slave side set");
      if (sides.sides.empty())
        throw_input_error(deck, where + "/Slave side set",
                          "'" + pair.slave_side_set + "' holds no face", "a side set with faces");
    }
    if (!pair.slave_node_set.empty() && slave.empty())
      throw_input_error(deck, where + "/Slave node set",
                        "'" + pair.slave_node_set + "' holds no node", "a node set with nodes");
    const SideSet& master = mesh.side_set(pair.master_side_set, deck, where + "/Master side set");
    if (master.sides.empty())
      throw_input_error(deck, where + "/Master side set",
                        "'" + pair.master_side_set + "' holds no face", "a side set with faces");
    for (const Side& side : master.sides) {
      if (mesh.blocks[mesh.block_of(side.element)].type != ElementType::hex8)
        throw_input_error(deck, where + "/Master side set",
                          "has a face of a " +
                              element_type_name(mesh.blocks[mesh.block_of(side.element)].type) +
                              " element",
                          "quadrilateral faces of hex8 elements");
    }
    const ContactSurfaceNodes surface = contact_surface_nodes(pair, mesh, deck, path);
    const std::string problem = start_penetration_problem(pair, surface, mesh, mesh.coordinates);
    if (!problem.empty())
      throw_input_error(deck, where, problem, kPlacementAdvice);
  }
}

}  // namespace railfe
