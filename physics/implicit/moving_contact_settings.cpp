#include "physics/implicit/moving_contact_settings.hpp"

#include <cmath>
#include <fstream>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "physics/implicit/beam_paths.hpp"

namespace railfe {

void add_moving_contact_parameters(ParameterSpec& spec) {
  ParameterSpec contact(
      "A vehicle node tied to the point of a beam path beneath it, which travels at constant "
      "speed (the direct method: the contact forces are Lagrange multipliers solved with the "
      "displacements; docs/theory.md, \"Constraints in HHT-α\").");
  contact.required_text("Node set", "The vehicle's contact node (a set of exactly one node).");
  contact.required_text_array(
      "Path",
      "Beam2 blocks whose elements form one chain, travelled from its end with the "
      "smallest (x, y, z).");
  contact.real("Start", 0.0, "Arc length along the path at t = 0.", "m");
  contact.required_real("Speed", "Speed along the path.", "m/s");
  contact.choice("Directions", "z",
                 {{"z", "vertical (global z) only"}, {"yz", "lateral (global y) and vertical"}},
                 "Which displacements are tied.");
  contact.text("Vertical irregularity", "",
               "Height of the running surface above the beam as a function of the arc length s "
               "(write it with the variable x) ('' = smooth).");
  contact.text("Lateral irregularity", "",
               "Lateral offset of the running surface as a function of s (variable x) ('' = "
               "none; Directions yz only).");
  contact.text("Irregularity file", "",
               "CSV with a header and columns s (m), vertical (m), lateral (m), s increasing, "
               "relative to the deck's directory (instead of the functions).");
  contact.flag("Separation", true,
               "Whether a vertical force that would pull releases the point (reported with time "
               "and place) until the vehicle reaches the surface again.");
  contact.only_when("Directions", {"yz"}, {"Lateral irregularity"});
  spec.named_sublists("Moving contacts", contact,
                      "Vehicle points tied to beams as they travel (models with beams).");
  spec.choice("Constraint solver", "block",
              {{"block",
                "the model without constraints factored once (CHOLMOD), the contact forces "
                "through the Schur complement of the constraints"},
               {"monolithic", "the whole saddle-point matrix by sparse LU (UMFPACK) every step"}},
              "How the saddle-point systems of Moving contacts are solved (reference: both agree "
              "to round-off).");
}

std::vector<MovingContactSpec> read_moving_contacts(const Teuchos::ParameterList& step,
                                                    const Deck& deck_file,
                                                    const std::string& path) {
  const std::string& deck = deck_file.source;
  std::vector<MovingContactSpec> specs;
  const auto& list = step.sublist("Moving contacts");
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.sublist(list.name(it));
    const std::string where = path + "/Moving contacts/" + list.name(it);
    MovingContactSpec spec;
    spec.name = list.name(it);
    spec.node_set = entry.get<std::string>("Node set");
    for (const auto& block : entry.get<Teuchos::Array<std::string>>("Path"))
      spec.blocks.push_back(block);
    spec.start = entry.get<double>("Start");
    spec.speed = entry.get<double>("Speed");
    spec.lateral = entry.get<std::string>("Directions") == "yz";
    spec.vertical_irregularity = entry.get<std::string>("Vertical irregularity");
    spec.lateral_irregularity = entry.get<std::string>("Lateral irregularity");
    const std::string file = entry.get<std::string>("Irregularity file");
    spec.separation = entry.get<bool>("Separation");
    for (const std::string* text : {&spec.vertical_irregularity, &spec.lateral_irregularity})
      if (!text->empty())
        Expression(*text, deck, where + "/Irregularity");
    if (!file.empty()) {
      if (!spec.vertical_irregularity.empty() || !spec.lateral_irregularity.empty())
        throw_input_error(deck, where + "/Irregularity file",
                          "is given with an irregularity function, which it would replace",
                          "either the file or the functions");
      spec.irregularity_file = deck_file.resolve(file);
      if (!std::ifstream(spec.irregularity_file))
        throw_input_error(deck, where + "/Irregularity file",
                          "'" + spec.irregularity_file + "' cannot be read",
                          "a CSV file relative to the deck's directory");
    }
    specs.push_back(spec);
  }
  return specs;
}

void check_moving_contacts(const std::vector<MovingContactSpec>& contacts, const Mesh& mesh,
                           double end_time, const std::string& deck, const std::string& path) {
  for (const MovingContactSpec& contact : contacts) {
    const std::string where = path + "/Moving contacts/" + contact.name;
    const auto& nodes = mesh.node_set(contact.node_set, deck, where + "/Node set").nodes;
    if (nodes.size() != 1)
      throw_input_error(
          deck, where + "/Node set",
          "'" + contact.node_set + "' holds " + std::to_string(nodes.size()) + " nodes",
          "a node set of exactly one node (the vehicle's contact point)");
    const auto chain = chain_of_blocks(mesh, contact.blocks, deck, where + "/Path");
    double length = 0;
    for (const PathLink& link : chain) {
      if (link.a == nodes.front() || link.b == nodes.front())
        throw_input_error(deck, where + "/Node set",
                          "is a node of its own path: the contact node belongs to the vehicle",
                          "a vehicle node apart from the beams it runs on");
      const double* a = &mesh.coordinates[3 * link.a];
      const double* b = &mesh.coordinates[3 * link.b];
      length += std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    }
    const double finish = contact.start + contact.speed * end_time;
    if (contact.start < 0 || contact.start > length)
      throw_input_error(deck, where + "/Start",
                        "puts the point at s = " + std::to_string(contact.start) +
                            " m, off its path of " + std::to_string(length) + " m",
                        "a start within [0, path length]");
    if (finish < -1e-9 * length || finish > length * (1 + 1e-9))
      throw_input_error(deck, where + "/Speed",
                        "takes the point to s = " + std::to_string(finish) +
                            " m at the End time, off its path of " + std::to_string(length) +
                            " m: the vehicle would leave the structure",
                        "a Speed and End time that keep the point on the path");
  }
}

}  // namespace railfe
