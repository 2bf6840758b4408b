#include "physics/common/solid_conditions.hpp"

#include <Teuchos_Array.hpp>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"

namespace railfe {

void add_solid_condition_parameters(ParameterSpec& spec) {
  ParameterSpec displacement("Prescribed displacements of a node set.");
  displacement.required_text("Node set", "The nodes it applies to.");
  displacement.text("Components", "xyz",
                    "Which components are prescribed: letters of 'xyz', and on the 6-DOF nodes of "
                    "beams, springs and point masses the rotations 'rx', 'ry', 'rz' (e.g. "
                    "'xyzrxryrz' clamps a beam's end).");
  displacement.real("Value", 0.0,
                    "The prescribed value of each listed component (m; rad for rotations).", "m");
  displacement.text("Expression", "",
                    "Instead of Value: a function of x, y, z in m (muParser syntax), evaluated at "
                    "each node, e.g. '1e-3*(2*x+y+z)/2'.");
  spec.named_sublists("Displacements", displacement, "Prescribed displacements (Dirichlet).");

  ParameterSpec surface(
      "A load on a side set: give exactly one of Traction, Pressure and Total "
      "force.");
  surface.required_text("Side set", "The element faces it acts on.");
  surface.real_array("Traction", {}, "Uniform traction vector.", "Pa", 3);
  surface.real_array("Pressure", {}, "Pressure against the outward normal (one number).", "Pa", 1);
  surface.real_array("Total force", {}, "Force vector spread uniformly over the set's area.", "N",
                     3);
  spec.named_sublists("Surface loads", surface, "Tractions and pressures on side sets.");

  ParameterSpec nodal("A force shared equally by the nodes of a node set.");
  nodal.required_text("Node set", "The nodes.");
  nodal.required_real_array("Total force", "Force vector summed over the nodes.", "N", 3);
  nodal.real_array("Total moment", {0, 0, 0},
                   "Moment vector summed over the nodes (6-DOF nodes of beams, springs and point "
                   "masses only).",
                   "N m", 3);
  spec.named_sublists("Nodal forces", nodal, "Forces at nodes.");

  ParameterSpec spin(
      "The centrifugal load of nodes spinning about an axis: each carries m omega^2 r, its lumped "
      "mass times omega squared times its distance from the axis. Give it the Angular velocity "
      "and Axis point of the explicit step's Initial velocity that follows, so that a rolling "
      "wheel starts in balance.");
  spin.required_text("Node set", "The spinning nodes.");
  spin.required_real_array("Angular velocity", "Angular velocity vector.", "rad/s", 3);
  spin.real_array("Axis point", {0, 0, 0}, "A point on the axis.", "m", 3);
  spec.named_sublists("Centrifugal loads", spin, "Centrifugal loads of spinning node sets.");

  spec.real_array("Gravity", {0, 0, 0},
                  "Gravitational acceleration; every solid carries density × gravity.", "m/s^2", 3,
                  Range::closed(-1e6, 1e6));

  ParameterSpec tie("Ties two node sets: each slave node follows the master node at its place.");
  tie.required_text("Master node set", "Nodes that remain unknowns.");
  tie.required_text("Slave node set", "Nodes eliminated by multi-point constraints.");
  tie.real("Tolerance", 1e-8, "Largest distance between paired nodes.", "m", Range::positive());
  spec.named_sublists("Ties", tie, "Tied node sets (multi-point constraints).");

  ParameterSpec probe(
      "Reports the mean displacement and the mean stress of a node set (the stress at each node: "
      "the Gauss-point stresses of the elements around it extrapolated to the node and averaged).");
  probe.required_text("Node set", "The nodes averaged.");
  spec.named_sublists("Probes", probe, "Displacements and stresses written to <step>_probes.csv.");
}

std::vector<int> parse_components(const std::string& letters, const std::string& deck,
                                  const std::string& path) {
  std::vector<int> components;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const bool rotation = letters[i] == 'r' && i + 1 < letters.size();
    const char letter = letters[i + rotation];
    const int c = letter == 'x' ? 0 : letter == 'y' ? 1 : letter == 'z' ? 2 : -1;
    if (c < 0) {
      throw_input_error(deck, path, "'" + letters + "' contains '" + std::string(1, letter) + "'",
                        "the letters x, y and z, e.g. 'xz', and the rotations rx, ry, rz");
    }
    components.push_back(c + 3 * rotation);
    i += rotation;
  }
  if (components.empty())
    throw_input_error(deck, path, "is empty", "the letters x, y and z");
  return components;
}

std::vector<int> parse_translations(const std::string& letters, const std::string& deck,
                                    const std::string& path) {
  std::vector<int> components = parse_components(letters, deck, path);
  for (int c : components)
    if (c >= 3)
      throw_input_error(deck, path, "'" + letters + "' names a rotation, and these nodes have none",
                        "the letters x, y and z, e.g. 'xz'");
  return components;
}

namespace {

std::array<double, 3> vector3(const Teuchos::Array<double>& values) {
  return {values[0], values[1], values[2]};
}

template <typename Body>
void for_each_sublist(const Teuchos::ParameterList& list, Body body) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    body(list.name(it), list.sublist(list.name(it)));
  }
}

}  // namespace

SolidConditions read_solid_conditions(const Teuchos::ParameterList& step, const std::string& deck,
                                      const std::string& path) {
  SolidConditions conditions;
  for_each_sublist(step.sublist("Displacements"), [&](const std::string& name, const auto& list) {
    const std::string where = path + "/Displacements/" + name;
    DisplacementCondition condition;
    condition.name = name;
    condition.node_set = list.template get<std::string>("Node set");
    condition.components =
        parse_components(list.template get<std::string>("Components"), deck, where + "/Components");
    condition.value = list.template get<double>("Value");
    condition.expression = list.template get<std::string>("Expression");
    if (!condition.expression.empty())
      Expression(condition.expression, deck, where + "/Expression");
    conditions.displacements.push_back(condition);
  });
  for_each_sublist(step.sublist("Surface loads"), [&](const std::string& name, const auto& list) {
    SurfaceLoad load;
    load.name = name;
    load.side_set = list.template get<std::string>("Side set");
    const auto& traction = list.template get<Teuchos::Array<double>>("Traction");
    const auto& pressure = list.template get<Teuchos::Array<double>>("Pressure");
    const auto& total = list.template get<Teuchos::Array<double>>("Total force");
    if (!traction.empty())
      load.traction = vector3(traction);
    if (!pressure.empty())
      load.pressure = pressure[0];
    if (!total.empty())
      load.total_force = vector3(total);
    const int given =
        load.traction.has_value() + load.pressure.has_value() + load.total_force.has_value();
    if (given != 1) {
      throw_input_error(deck, path + "/Surface loads/" + name,
                        "gives " + std::to_string(given) + " of Traction, Pressure, Total force",
                        "exactly one of them");
    }
    conditions.surface_loads.push_back(load);
  });
  for_each_sublist(step.sublist("Nodal forces"), [&](const std::string& name, const auto& list) {
    conditions.nodal_forces.push_back(
        {name, list.template get<std::string>("Node set"),
         vector3(list.template get<Teuchos::Array<double>>("Total force")),
         vector3(list.template get<Teuchos::Array<double>>("Total moment"))});
  });
  for_each_sublist(step.sublist("Centrifugal loads"),
                   [&](const std::string& name, const auto& list) {
                     conditions.centrifugal_loads.push_back(
                         {name, list.template get<std::string>("Node set"),
                          vector3(list.template get<Teuchos::Array<double>>("Angular velocity")),
                          vector3(list.template get<Teuchos::Array<double>>("Axis point"))});
                   });
  conditions.gravity = vector3(step.get<Teuchos::Array<double>>("Gravity"));
  for_each_sublist(step.sublist("Ties"), [&](const std::string& name, const auto& list) {
    conditions.ties.push_back({name, list.template get<std::string>("Master node set"),
                               list.template get<std::string>("Slave node set"),
                               list.template get<double>("Tolerance")});
  });
  for_each_sublist(step.sublist("Probes"), [&](const std::string& name, const auto& list) {
    conditions.probes.push_back({name, list.template get<std::string>("Node set")});
  });
  return conditions;
}

void refuse_rotations(const SolidConditions& conditions, const std::string& deck,
                      const std::string& path, const std::string& model) {
  for (const auto& condition : conditions.displacements)
    for (int c : condition.components)
      if (c >= 3)
        throw_input_error(deck, path + "/Displacements/" + condition.name + "/Components",
                          "prescribes a rotation, and " + model + " has translations only",
                          "the letters x, y and z (rx, ry, rz on beam, spring and point-mass "
                          "nodes)");
  for (const auto& force : conditions.nodal_forces) {
    const auto& m = force.total_moment;
    if (m[0] != 0 || m[1] != 0 || m[2] != 0)
      throw_input_error(deck, path + "/Nodal forces/" + force.name + "/Total moment",
                        "is not zero, and " + model + " has translations only",
                        "a Total moment on beam, spring and point-mass nodes only");
  }
}

void check_solid_conditions(const SolidConditions& conditions, const Mesh& mesh,
                            const std::string& deck, const std::string& path) {
  for (const auto& condition : conditions.displacements) {
    mesh.node_set(condition.node_set, deck,
                  path + "/Displacements/" + condition.name + "/Node set");
  }
  for (const auto& load : conditions.surface_loads) {
    mesh.side_set(load.side_set, deck, path + "/Surface loads/" + load.name + "/Side set");
  }
  for (const auto& force : conditions.nodal_forces) {
    mesh.node_set(force.node_set, deck, path + "/Nodal forces/" + force.name + "/Node set");
  }
  for (const auto& load : conditions.centrifugal_loads) {
    mesh.node_set(load.node_set, deck, path + "/Centrifugal loads/" + load.name + "/Node set");
    const auto& w = load.angular_velocity;
    if (w[0] == 0 && w[1] == 0 && w[2] == 0)
      throw_input_error(deck, path + "/Centrifugal loads/" + load.name + "/Angular velocity",
                        "is zero (no load)", "a non-zero angular velocity");
  }
  for (const auto& tie : conditions.ties) {
    mesh.node_set(tie.master_set, deck, path + "/Ties/" + tie.name + "/Master node set");
    mesh.node_set(tie.slave_set, deck, path + "/Ties/" + tie.name + "/Slave node set");
  }
  for (const auto& probe : conditions.probes) {
    mesh.node_set(probe.node_set, deck, path + "/Probes/" + probe.name + "/Node set");
  }
}

bool is_earlier_statics_step(const Teuchos::ParameterList& steps, const std::string& name,
                             const std::string& step) {
  for (auto it = steps.begin(); it != steps.end(); ++it) {
    if (steps.name(it) == step)
      return false;
    if (steps.name(it) == name)
      return steps.sublist(name).get<std::string>("Module") == "statics";
  }
  return false;
}

}  // namespace railfe
