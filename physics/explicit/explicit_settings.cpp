#include "physics/explicit/explicit_settings.hpp"

#include <set>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"
#include "framework/mesh/nearest_nodes.hpp"
#include "physics/common/solid_conditions.hpp"

namespace railfe {

namespace {

ParameterSpec time_function_spec(ParameterSpec spec) {
  spec.text("Function", "1",
            "Scale factor as a function of time t (s), e.g. 'min(t/1e-3, 1)' for a ramp.");
  return spec;
}

ParameterSpec discrete_parameters() {
  ParameterSpec spec("Masses, rigid bodies and spring–dampers in the same scene as the solids.");
  ParameterSpec nodal("Mass added to a node set, shared equally by its nodes.");
  nodal.required_text("Node set", "The nodes.");
  nodal.required_real("Mass", "Total added mass.", "kg", Range::positive());
  spec.named_sublists("Nodal masses", nodal, "Added nodal masses.");

  ParameterSpec body(
      "A rigid body: the nodes of a node set move rigidly with a reference point that carries "
      "extra mass and inertia (axle ends, a sprung mass). Without a node set and with no "
      "inertia it is a point mass that only translates.");
  body.text("Node set", "", "Nodes carried by the body ('' = none).");
  body.real_array("Reference point", {}, "Reference point (default: centroid of the nodes).", "m",
                  3);
  body.real("Mass", 0.0, "Mass at the reference point, added to the nodes' mass.", "kg",
            Range::non_negative());
  body.real_array("Inertia", {0, 0, 0},
                  "Principal moments of inertia about the reference point along x, y, z, added "
                  "to the nodes' inertia.",
                  "kg m^2", 3, Range::non_negative());
  body.real_array("Velocity", {0, 0, 0}, "Initial velocity of the reference point.", "m/s", 3);
  body.real_array("Angular velocity", {0, 0, 0}, "Initial angular velocity.", "rad/s", 3);
  body.text("Fixed translations", "", "Translations held at zero: letters of 'xyz'.");
  body.text("Fixed rotations", "", "Rotations held at zero: letters of 'xyz'.");
  body.flag("Weight", true,
            "Gravity acts on the body's Mass. false leaves its weight out: exact for a point "
            "mass on linear springs to the ground (a sleeper on ballast), whose weight only "
            "shifts their rest length, so a statics preload without it starts in balance. "
            "Only for a body without a Node set, in a step with Gravity.");
  for (const char* axis : {"x", "y", "z"}) {
    body.text(std::string("Motion ") + axis, "",
              std::string("Prescribed displacement of the reference point along ") + axis +
                  " from its start: a function of t (m), e.g. '1e-3*sin(2*pi*50*t)' ('' = "
                  "free). The force that drives it does work counted in the energy balance.");
  }
  spec.named_sublists("Rigid bodies", body, "Rigid bodies and point masses.");

  ParameterSpec spring(
      "A linear spring–damper acting along the global axes between two ends. An end is a rigid "
      "body (its reference point), a node set (one spring per node, stiffness and damping "
      "shared equally) or, for End B only, 'ground'. Between two node sets, each node of End A "
      "is tied to the nearest node of End B (a rail seat on the pad over a sleeper's top).");
  spring.required_text("End A", "A rigid body or node set.");
  spring.text("End B", "ground", "A rigid body, a node set or 'ground'.");
  spring.real_array("Stiffness", {0, 0, 0}, "Stiffness along x, y, z.", "N/m", 3,
                    Range::non_negative());
  spring.real_array("Damping", {0, 0, 0}, "Viscous damping along x, y, z.", "N s/m", 3,
                    Range::non_negative());
  spec.named_sublists("Springs", spring, "Spring–dampers.");

  ParameterSpec moment = time_function_spec(ParameterSpec("A moment on a rigid body."));
  moment.required_text("Body", "The rigid body.");
  moment.required_real_array("Moment", "Moment vector.", "N m", 3);
  spec.named_sublists("Moments", moment, "Applied moments (e.g. a driving torque).");
  return spec;
}

ParameterSpec load_parameters(ParameterSpec& spec) {
  spec.real_array("Gravity", {0, 0, 0}, "Gravitational acceleration on every mass.", "m/s^2", 3);
  spec.text("Gravity function", "1", "Scale factor of gravity as a function of time t.");
  ParameterSpec nodal = time_function_spec(ParameterSpec("A force shared by a node set."));
  nodal.required_text("Node set", "The nodes.");
  nodal.required_real_array("Total force", "Force summed over the nodes.", "N", 3);
  spec.named_sublists("Nodal forces", nodal, "Forces on node sets.");
  ParameterSpec surface =
      time_function_spec(ParameterSpec("A dead load on a side set (reference configuration)."));
  surface.required_text("Side set", "The faces.");
  surface.real_array("Traction", {}, "Traction vector.", "Pa", 3);
  surface.real_array("Pressure", {}, "Pressure against the outward normal (one number).", "Pa", 1);
  surface.real_array("Total force", {}, "Total force spread uniformly over the area.", "N", 3);
  spec.named_sublists("Surface loads", surface,
                      "Tractions, pressures or total forces on side sets; exactly one of them.");
  ParameterSpec motion(
      "Prescribed displacement or velocity components of a node set, as a function of x, y, z "
      "(reference position, m) and t (s).");
  motion.required_text("Node set", "The nodes.");
  motion.text("Components", "xyz", "Letters of 'xyz'.");
  motion.choice("Kind", "velocity",
                {{"velocity", "the function gives the velocity (m/s)"},
                 {"displacement", "the function gives the displacement (m)"}},
                "What the function prescribes.");
  motion.text("Function", "0", "The value.");
  spec.named_sublists("Prescribed motion", motion, "Kinematic conditions (fixed supports too).");
  ParameterSpec initial("Initial velocity v = V + omega x (X - point).");
  initial.text("Node set", "", "The nodes ('' = every node).");
  initial.real_array("Translation", {0, 0, 0}, "V.", "m/s", 3);
  initial.real_array("Angular velocity", {0, 0, 0}, "omega.", "rad/s", 3);
  initial.real_array("Axis point", {0, 0, 0}, "A point on the rotation axis.", "m", 3);
  spec.named_sublists("Initial velocity", initial,
                      "Initial velocity fields (applied in order; later ones win).");
  return spec;
}

ParameterSpec output_parameters() {
  ParameterSpec spec("What the step writes.");
  spec.integer("Energy interval", 100, "Steps between rows of <step>_energy.csv.",
               Range::at_least(1));
  spec.integer("History interval", 10, "Steps between rows of <step>_histories.csv.",
               Range::at_least(1));
  spec.real("Exodus interval", 0.0,
            "Simulated time between Exodus snapshots (0 = only the first and last).", "s",
            Range::non_negative());
  ParameterSpec history(
      "The mean of one kinematic quantity over a node set, or of a rigid body's reference point, "
      "every step.");
  history.text("Node set", "", "The nodes averaged (give this or Body).");
  history.text("Body", "", "A rigid body or point mass (give this or Node set).");
  history.choice("Quantity", "displacement",
                 {{"displacement", "m"},
                  {"velocity", "m/s"},
                  {"acceleration", "m/s^2"},
                  {"angular velocity", "rad/s, spatial (Body only)"},
                  {"body angular velocity", "rad/s, in the body's axes R^T omega (Body only)"},
                  {"angular momentum", "N m s, spatial, about the reference point (Body only)"}},
                 "What is recorded.");
  history.choice("Component", "x", {{"x", "x"}, {"y", "y"}, {"z", "z"}}, "Which component.");
  history.real("Arrival level", 0.0,
               "|value| marking the arrival of a wave (0 = do not measure arrivals).", "",
               Range::non_negative());
  history.real("Period reference", 0.0,
               "Value about which the period of an oscillation is measured (upward crossings).");
  spec.named_sublists("Histories", history,
                      "Node-set histories; events (arrival, peak, period) are measured from every "
                      "step into <step>_measurements.csv.");
  ParameterSpec element("Centre Cauchy stress of one element.");
  element.required_real("Element", "1-based element id, as ParaView shows it.", "",
                        Range::at_least(1));
  spec.named_sublists("Element histories", element, "Element stress histories.");
  ParameterSpec wave("Speed of a wave between two histories: distance / delay.");
  wave.required_text("From", "History nearer the source.");
  wave.required_text("To", "History further away.");
  wave.choice("Event", "arrival",
              {{"arrival", "first time |value| reaches the Arrival level"},
               {"peak", "time of the largest |value|"}},
              "Which event is timed.");
  spec.named_sublists("Wave speeds", wave, "Measured wave speeds (<step>_wave_speeds.csv).");
  return spec;
}

}  // namespace

ParameterSpec explicit_parameters() {
  ParameterSpec spec(
      "Explicit dynamics of hex8 solids and discrete parts: central difference "
      "(Newmark beta = 0, gamma = 1/2) with a lumped mass.");
  spec.required_real("End time", "Simulated duration.", "s", Range::positive());
  spec.real("Maximum steps", 1e8,
            "Step budget: a run whose End time needs more steps (estimated from the smallest "
            "element before it starts) is refused, and one that reaches it stops.",
            "", Range::at_least(1));
  spec.real("Time step", 0.0,
            "Fixed step; 0 = automatic (Safety factor x the stable step, recomputed as the mesh "
            "deforms). A fixed step above the stable limit is refused unless Allow unstable step.",
            "s", Range::non_negative());
  spec.real("Safety factor", 0.9, "Automatic step as a fraction of the stable step.", "",
            Range::open(0.0, 1.0 + 1e-12));
  spec.flag("Allow unstable step", false,
            "Run a fixed Time step above the stable limit (to study instability); the run stops "
            "when the energy balance fails.");
  spec.real("Energy error limit", 0.1,
            "Blow-up detection, first condition: |energy_error| above this. A stable central "
            "difference step oscillates the measured energy (by up to 1 / (1 - (omega dt / 2)^2)), "
            "so the error alone never stops a run.",
            "", Range::positive());
  spec.real("Energy growth limit", 100,
            "Blow-up detection, second condition: the stored energy (kinetic, strain, hourglass, "
            "contact) plus the energy dissipated (damping, friction) above this multiple of the "
            "energy put in (initial energy plus the largest work of "
            "the loads so far). A run stops only when both conditions hold.",
            "", Range::open(1, 1e300));
  spec.real("Rayleigh mass damping", 0.0, "alpha of C = alpha M.", "1/s", Range::non_negative());
  spec.real("Mass scaling step", 0.0,
            "Selective mass scaling (LS-DYNA's DT2MS): every element whose stable step is below "
            "this one gets its density raised by (this / its step)^2, so that its step reaches "
            "it (0 = none). The mass added is reported in the summary, with a warning above 1 % "
            "of the total; it slows the scaled elements' waves by the square root of the factor.",
            "s", Range::non_negative());
  spec.text("Start from", "",
            "A previous statics step whose displacements start this one (preload), or ''.");
  spec.real_array("Preload frame velocity", {},
                  "With Start from: the velocity of the frame in which the preload is steady "
                  "(a rolling wheel's axle, {V, 0, 0}); every node then starts with its initial "
                  "velocity v plus grad(u) (v - this), the preload's deformation carried by the "
                  "material through it. Empty: the preload starts with the initial velocities "
                  "alone.",
                  "m/s");
  ParameterSpec solid("The hex8 formulation (total-Lagrangian St. Venant-Kirchhoff).");
  solid.choice("Integration", "one point",
               {{"one point", "one point with hourglass control (fast)"},
                {"full", "2x2x2 Gauss points (8x the cost; locks in thin bending)"}},
               "Integration rule.");
  solid.choice("Hourglass control", "stiffness",
               {{"stiffness", "Flanagan-Belytschko stiffness form (elastic, stored energy)"},
                {"viscous", "Flanagan-Belytschko viscous form (dissipative)"},
                {"none", "none (hourglass modes are free: for demonstrations only)"}},
               "Hourglass resistance of one-point elements.");
  solid.real("Hourglass coefficient", 0.03, "kappa of the hourglass form.", "",
             Range::closed(0.0, 1.0));
  solid.real("Bulk viscosity linear", 0.06, "Linear bulk viscosity coefficient (0 = off).", "",
             Range::non_negative());
  solid.real("Bulk viscosity quadratic", 1.5, "Quadratic bulk viscosity coefficient (0 = off).", "",
             Range::non_negative());
  solid.choice(
      "Kernel", "batched",
      {{"batched",
        "8 elements per SIMD batch where the CPU has AVX-512, 4 where it has AVX2 and "
        "FMA, else scalar"},
       {"scalar", "one element at a time (the reference the batched kernel is tested on)"}},
      "How one-point elements are evaluated; both give the same forces to round-off.");
  solid.only_when("Integration", {"one point"},
                  {"Hourglass control", "Hourglass coefficient", "Kernel"});
  spec.sublist("Solid", solid, "Hex8 formulation.");
  load_parameters(spec);
  spec.sublist("Discrete parts", discrete_parameters(), "Masses, rigid bodies, springs.");
  spec.named_sublists("Contact pairs", contact_pair_parameters(ContactUse::explicit_dynamics),
                      "Penalty node-to-segment contact between deformable bodies.");
  spec.sublist("Output", output_parameters(), "Energy, histories and snapshots.");
  ParameterSpec checkpoint("Checkpoint and restart.");
  checkpoint.integer("Interval", 0, "Steps between checkpoints (0 = none).", Range::at_least(0));
  checkpoint.flag("Restart", false,
                  "Resume from the checkpoint in the results directory if there is one.");
  checkpoint.integer("Stop after steps", 0,
                     "Stop after this many steps as if interrupted (tests restart); 0 = run on.",
                     Range::at_least(0));
  spec.sublist("Checkpoint", checkpoint, "Checkpoint files <step>.checkpoint.<rank>.");
  return spec;
}

namespace {

std::array<double, 3> array3(const Teuchos::ParameterList& list, const std::string& name) {
  const auto& values = list.get<Teuchos::Array<double>>(name);
  return {values[0], values[1], values[2]};
}

void check_expression(const std::string& text, const std::string& deck, const std::string& path) {
  Expression expression(text, deck, path);
}

template <class F>
void for_each_sublist(const Teuchos::ParameterList& parent, const std::string& name, F&& f) {
  const auto& list = parent.sublist(name);
  for (auto it = list.begin(); it != list.end(); ++it)
    f(list.name(it), list.sublist(list.name(it)));
}

void read_loads(const Teuchos::ParameterList& step, const std::string& deck,
                const std::string& path, ExplicitSettings& settings) {
  settings.gravity = array3(step, "Gravity");
  settings.gravity_function = step.get<std::string>("Gravity function");
  check_expression(settings.gravity_function, deck, path + "/Gravity function");
  for_each_sublist(step, "Nodal forces", [&](const std::string& name, const auto& entry) {
    TimedLoad load;
    load.name = name;
    load.node_set = entry.template get<std::string>("Node set");
    load.total_force = array3(entry, "Total force");
    load.function = entry.template get<std::string>("Function");
    check_expression(load.function, deck, path + "/Nodal forces/" + name + "/Function");
    settings.loads.push_back(load);
  });
  for_each_sublist(step, "Surface loads", [&](const std::string& name, const auto& entry) {
    const std::string where = path + "/Surface loads/" + name;
    TimedLoad load;
    load.name = name;
    load.side_set = entry.template get<std::string>("Side set");
    load.function = entry.template get<std::string>("Function");
    check_expression(load.function, deck, where + "/Function");
    int given = 0;
    if (!entry.template get<Teuchos::Array<double>>("Traction").empty()) {
      load.traction = array3(entry, "Traction");
      ++given;
    }
    if (!entry.template get<Teuchos::Array<double>>("Pressure").empty()) {
      load.pressure = entry.template get<Teuchos::Array<double>>("Pressure")[0];
      ++given;
    }
    if (!entry.template get<Teuchos::Array<double>>("Total force").empty()) {
      load.total_force = array3(entry, "Total force");
      load.surface_total = true;
      ++given;
    }
    if (given != 1)
      throw_input_error(deck, where, "gives " + std::to_string(given) + " kinds of load",
                        "exactly one of Traction, Pressure and Total force");
    settings.loads.push_back(load);
  });
  for_each_sublist(step, "Prescribed motion", [&](const std::string& name, const auto& entry) {
    const std::string where = path + "/Prescribed motion/" + name;
    PrescribedMotion motion;
    motion.name = name;
    motion.node_set = entry.template get<std::string>("Node set");
    motion.components = parse_translations(entry.template get<std::string>("Components"), deck,
                                           where + "/Components");
    motion.velocity = entry.template get<std::string>("Kind") == "velocity";
    motion.function = entry.template get<std::string>("Function");
    check_expression(motion.function, deck, where + "/Function");
    settings.motions.push_back(motion);
  });
  for_each_sublist(step, "Initial velocity", [&](const std::string& name, const auto& entry) {
    InitialVelocity initial;
    initial.name = name;
    initial.node_set = entry.template get<std::string>("Node set");
    initial.translation = array3(entry, "Translation");
    initial.angular_velocity = array3(entry, "Angular velocity");
    initial.axis_point = array3(entry, "Axis point");
    settings.initial_velocities.push_back(initial);
  });
}

std::array<bool, 3> fixed_letters(const std::string& letters, const std::string& deck,
                                  const std::string& path) {
  std::array<bool, 3> fixed{};
  if (letters.empty())
    return fixed;
  for (int component : parse_translations(letters, deck, path))
    fixed[component] = true;
  return fixed;
}

void read_discrete(const Teuchos::ParameterList& discrete, const std::string& deck,
                   const std::string& path, ExplicitSettings& settings) {
  for_each_sublist(discrete, "Nodal masses", [&](const std::string& name, const auto& entry) {
    settings.nodal_masses.push_back(
        {name, entry.template get<std::string>("Node set"), entry.template get<double>("Mass")});
  });
  for_each_sublist(discrete, "Rigid bodies", [&](const std::string& name, const auto& entry) {
    const std::string where = path + "/Rigid bodies/" + name;
    RigidBodySpec body;
    body.name = name;
    body.node_set = entry.template get<std::string>("Node set");
    if (!entry.template get<Teuchos::Array<double>>("Reference point").empty())
      body.reference = array3(entry, "Reference point");
    body.mass = entry.template get<double>("Mass");
    body.inertia = array3(entry, "Inertia");
    body.velocity = array3(entry, "Velocity");
    body.angular_velocity = array3(entry, "Angular velocity");
    body.weighs = entry.template get<bool>("Weight");
    const bool no_gravity = settings.gravity == std::array<double, 3>{0, 0, 0};
    if (!body.weighs && (!body.node_set.empty() || no_gravity))
      throw_input_error(deck, where + "/Weight",
                        no_gravity ? "is false in a step without Gravity (nothing to leave out)"
                                   : "is false for a body that carries nodes (their weight is "
                                     "the nodes' own)",
                        "true, or leave it out");
    const auto translations = fixed_letters(entry.template get<std::string>("Fixed translations"),
                                            deck, where + "/Fixed translations");
    const auto rotations = fixed_letters(entry.template get<std::string>("Fixed rotations"), deck,
                                         where + "/Fixed rotations");
    for (int d = 0; d < 3; ++d) {
      body.fixed[d] = translations[d];
      body.fixed[3 + d] = rotations[d];
      const std::string axis(1, "xyz"[d]);
      body.motion[d] = entry.template get<std::string>("Motion " + axis);
      if (!body.motion[d].empty() && body.fixed[d])
        throw_input_error(deck, where + "/Motion " + axis,
                          "is given for a translation that Fixed translations holds at zero",
                          "either Motion " + axis + " or '" + axis + "' in Fixed translations");
      if (!body.motion[d].empty() && body.velocity[d] != 0)
        throw_input_error(deck, where + "/Velocity",
                          "gives a velocity along " + axis + ", which Motion " + axis +
                              " prescribes (its rate at t = 0 is the start velocity)",
                          "0 along " + axis + ", or no Motion " + axis);
    }
    if (body.node_set.empty() && !body.reference)
      throw_input_error(deck, where, "has neither a Node set nor a Reference point",
                        "a Node set to carry, or a Reference point for a point mass");
    if (body.node_set.empty() && body.mass <= 0)
      throw_input_error(deck, where + "/Mass", "is 0 for a body without nodes", "a positive mass");
    settings.bodies.push_back(body);
  });
  for_each_sublist(discrete, "Springs", [&](const std::string& name, const auto& entry) {
    SpringSpec spring;
    spring.name = name;
    spring.end_a = entry.template get<std::string>("End A");
    spring.end_b = entry.template get<std::string>("End B");
    spring.stiffness = array3(entry, "Stiffness");
    spring.damping = array3(entry, "Damping");
    if (spring.end_a == "ground")
      throw_input_error(deck, path + "/Springs/" + name + "/End A", "is 'ground'",
                        "a rigid body or node set ('ground' may only be End B)");
    settings.springs.push_back(spring);
  });
  for_each_sublist(discrete, "Moments", [&](const std::string& name, const auto& entry) {
    BodyMoment moment;
    moment.name = name;
    moment.body = entry.template get<std::string>("Body");
    moment.moment = array3(entry, "Moment");
    moment.function = entry.template get<std::string>("Function");
    check_expression(moment.function, deck, path + "/Moments/" + name + "/Function");
    settings.moments.push_back(moment);
  });
}

void read_output(const Teuchos::ParameterList& output, const std::string& deck,
                 const std::string& path, ExplicitSettings& settings) {
  settings.energy_interval = output.get<int>("Energy interval");
  settings.history_interval = output.get<int>("History interval");
  settings.exodus_interval = output.get<double>("Exodus interval");
  std::set<std::string> names;
  for_each_sublist(output, "Histories", [&](const std::string& name, const auto& entry) {
    HistorySpec history;
    history.name = name;
    history.node_set = entry.template get<std::string>("Node set");
    history.body = entry.template get<std::string>("Body");
    if (history.node_set.empty() == history.body.empty())
      throw_input_error(deck, path + "/Output/Histories/" + name,
                        history.body.empty() ? "names neither a Node set nor a Body"
                                             : "names both a Node set and a Body",
                        "exactly one of Node set and Body");
    history.quantity = entry.template get<std::string>("Quantity");
    if (history.body.empty() && history.quantity.find("angular") != std::string::npos)
      throw_input_error(deck, path + "/Output/Histories/" + name + "/Quantity",
                        "'" + history.quantity + "' is a rigid body's quantity",
                        "a Body, or displacement, velocity or acceleration of a Node set");
    history.component = std::string("xyz").find(entry.template get<std::string>("Component"));
    history.arrival_level = entry.template get<double>("Arrival level");
    history.period_reference = entry.template get<double>("Period reference");
    names.insert(name);
    settings.histories.push_back(history);
  });
  for_each_sublist(output, "Element histories", [&](const std::string& name, const auto& entry) {
    settings.element_histories.push_back(
        {name, static_cast<GlobalIndex>(entry.template get<double>("Element")) - 1});
  });
  for_each_sublist(output, "Wave speeds", [&](const std::string& name, const auto& entry) {
    const std::string where = path + "/Output/Wave speeds/" + name;
    WaveSpeedSpec wave{name, entry.template get<std::string>("From"),
                       entry.template get<std::string>("To"),
                       entry.template get<std::string>("Event") == "peak"};
    for (const auto& [end, label] : {std::pair{wave.from, "/From"}, std::pair{wave.to, "/To"}}) {
      if (!names.count(end))
        throw_input_error(deck, where + label, "names no history ('" + end + "')",
                          "the name of an entry under Output/Histories");
    }
    for (const auto& history : settings.histories) {
      if ((history.name == wave.from || history.name == wave.to) && history.node_set.empty())
        throw_input_error(deck, where, "uses history '" + history.name + "' of a body",
                          "histories of node sets (their distance gives the speed)");
    }
    if (!wave.peak) {
      for (const auto& history : settings.histories) {
        if ((history.name == wave.from || history.name == wave.to) && history.arrival_level <= 0)
          throw_input_error(deck, where + "/Event",
                            "is 'arrival' but history '" + history.name + "' has no Arrival level",
                            "an Arrival level > 0 on both histories, or Event 'peak'");
      }
    }
    settings.wave_speeds.push_back(wave);
  });
}

}  // namespace

ExplicitSettings read_explicit_settings(const Teuchos::ParameterList& step, const std::string& deck,
                                        const std::string& path) {
  ExplicitSettings settings;
  settings.end_time = step.get<double>("End time");
  settings.maximum_steps = step.get<double>("Maximum steps");
  settings.time_step = step.get<double>("Time step");
  settings.safety_factor = step.get<double>("Safety factor");
  // Time step is a number, so only_when cannot tie these to it: a fixed step makes the safety
  // factor meaningless, an automatic one the permission to exceed the limit.
  const bool fixed_step = settings.time_step > 0;
  const char* ignored = fixed_step ? "Safety factor" : "Allow unstable step";
  if (!step.getEntry(ignored).isDefault())
    throw_input_error(deck, path + "/" + ignored,
                      std::string("is used only with ") +
                          (fixed_step ? "an automatic step (Time step 0)" : "a fixed Time step") +
                          ", so the value would be ignored",
                      std::string("remove it, or ") +
                          (fixed_step ? "set Time step to 0" : "give a fixed Time step"));
  settings.allow_unstable_step = step.get<bool>("Allow unstable step");
  settings.energy_error_limit = step.get<double>("Energy error limit");
  settings.energy_growth_limit = step.get<double>("Energy growth limit");
  settings.rayleigh_mass = step.get<double>("Rayleigh mass damping");
  settings.mass_scaling_step = step.get<double>("Mass scaling step");
  settings.start_from = step.get<std::string>("Start from");
  const auto frame = step.get<Teuchos::Array<double>>("Preload frame velocity");
  if (!frame.empty()) {
    if (frame.size() != 3)
      throw_input_error(deck, path + "/Preload frame velocity",
                        "has " + std::to_string(frame.size()) + " entries",
                        "three components (m/s), or none");
    if (settings.start_from.empty())
      throw_input_error(deck, path + "/Preload frame velocity",
                        "is given without Start from, so there is no preload to convect",
                        "a Start from statics step, or no Preload frame velocity");
    settings.preload_frame = std::array<double, 3>{frame[0], frame[1], frame[2]};
  }
  const auto& solid = step.sublist("Solid");
  settings.kernel.full_integration = solid.get<std::string>("Integration") == "full";
  const std::string hourglass = solid.get<std::string>("Hourglass control");
  settings.kernel.hourglass = hourglass == "stiffness" ? HourglassForm::stiffness
                              : hourglass == "viscous" ? HourglassForm::viscous
                                                       : HourglassForm::none;
  settings.kernel.hourglass_coefficient = solid.get<double>("Hourglass coefficient");
  settings.kernel.bulk_linear = solid.get<double>("Bulk viscosity linear");
  settings.kernel.bulk_quadratic = solid.get<double>("Bulk viscosity quadratic");
  settings.kernel.batched = solid.get<std::string>("Kernel") == "batched";
  read_loads(step, deck, path, settings);
  read_discrete(step.sublist("Discrete parts"), deck, path + "/Discrete parts", settings);
  read_output(step.sublist("Output"), deck, path, settings);
  settings.contact_pairs = read_contact_pairs(step, deck, path, ContactUse::explicit_dynamics);
  for (const ContactPairSpec& pair : settings.contact_pairs)
    if (!pair.patch_times.empty() && pair.patch_times.back() > settings.end_time)
      throw_input_error(deck, path + "/Contact pairs/" + pair.name + "/Patch times",
                        "go beyond the End time (" + std::to_string(settings.end_time) + " s)",
                        "times up to the End time");
  const auto& checkpoint = step.sublist("Checkpoint");
  settings.checkpoint_interval = checkpoint.get<int>("Interval");
  settings.restart = checkpoint.get<bool>("Restart");
  settings.stop_after_steps = checkpoint.get<int>("Stop after steps");
  if (settings.stop_after_steps > 0 && settings.checkpoint_interval == 0)
    throw_input_error(deck, path + "/Checkpoint/Stop after steps",
                      "stops the run early but no checkpoint is written",
                      "a Checkpoint Interval > 0 so that the run can be resumed");
  return settings;
}

void check_explicit_settings(const ExplicitSettings& settings, const Mesh& mesh,
                             const std::string& deck, const std::string& path) {
  check_contact_pairs(settings.contact_pairs, mesh, deck, path);
  for (const auto& load : settings.loads) {
    if (!load.node_set.empty())
      mesh.node_set(load.node_set, deck, path + "/Nodal forces/" + load.name + "/Node set");
    else
      mesh.side_set(load.side_set, deck, path + "/Surface loads/" + load.name + "/Side set");
  }
  for (const auto& motion : settings.motions)
    mesh.node_set(motion.node_set, deck, path + "/Prescribed motion/" + motion.name + "/Node set");
  for (const auto& initial : settings.initial_velocities) {
    if (!initial.node_set.empty())
      mesh.node_set(initial.node_set, deck,
                    path + "/Initial velocity/" + initial.name + "/Node set");
  }
  const std::string discrete = path + "/Discrete parts";
  std::set<std::string> bodies;
  for (const auto& mass : settings.nodal_masses)
    mesh.node_set(mass.node_set, deck, discrete + "/Nodal masses/" + mass.name + "/Node set");
  for (const auto& body : settings.bodies) {
    if (!body.node_set.empty())
      mesh.node_set(body.node_set, deck, discrete + "/Rigid bodies/" + body.name + "/Node set");
    bodies.insert(body.name);
  }
  for (const auto& spring : settings.springs) {
    for (const auto& [end, label] :
         {std::pair{spring.end_a, "/End A"}, std::pair{spring.end_b, "/End B"}}) {
      if (end == "ground" || bodies.count(end) || mesh.has_node_set(end))
        continue;
      throw_input_error(deck, discrete + "/Springs/" + spring.name + label,
                        "names '" + end + "', which is no rigid body or node set",
                        "the name of a rigid body, a node set or 'ground'");
    }
    if (!bodies.count(spring.end_a) && spring.end_b != "ground" && !bodies.count(spring.end_b))
      check_disjoint_node_sets(mesh, spring.end_a, spring.end_b, deck,
                               discrete + "/Springs/" + spring.name + "/End B");
  }
  for (const auto& moment : settings.moments) {
    if (!bodies.count(moment.body))
      throw_input_error(deck, discrete + "/Moments/" + moment.name + "/Body",
                        "names no rigid body ('" + moment.body + "')",
                        "the name of an entry under Discrete parts/Rigid bodies");
  }
  for (const auto& history : settings.histories) {
    const std::string where = path + "/Output/Histories/" + history.name;
    if (!history.node_set.empty())
      mesh.node_set(history.node_set, deck, where + "/Node set");
    else if (!bodies.count(history.body))
      throw_input_error(deck, where + "/Body", "names no rigid body ('" + history.body + "')",
                        "the name of an entry under Discrete parts/Rigid bodies");
  }
  for (const auto& element : settings.element_histories) {
    if (element.element >= mesh.n_elements())
      throw_input_error(deck, path + "/Output/Element histories/" + element.name + "/Element",
                        "is " + std::to_string(element.element + 1),
                        "an element id from 1 to " + std::to_string(mesh.n_elements()));
    if (mesh.blocks[mesh.block_of(element.element)].type != ElementType::hex8)
      throw_input_error(deck, path + "/Output/Element histories/" + element.name + "/Element",
                        "is not a hex8 element", "the id of a hex8 element");
  }
}

}  // namespace railfe
